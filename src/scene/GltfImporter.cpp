#include "scene/GltfImporter.h"

#include <algorithm>
#include <cassert>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <string_view>

#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>
#include <stb/stb_image.h>
#include <tiny_gltf.h>

#include "core/Error.h"
#include "core/Log.h"
#include "scene/Tangents.h"

namespace specula::scene {

namespace {

namespace fs = std::filesystem;

/// Extensions we can honour when a file lists them as required.
constexpr std::string_view kSupportedRequiredExtensions[] = {
    "KHR_lights_punctual",
    "KHR_materials_emissive_strength",
    "KHR_materials_ior",      // F0 of the dielectric part (Material::ior)
    "KHR_materials_specular", // factors; its textures are ignored
    "KHR_mesh_quantization", // integer attributes: the accessor reader handles every component type
    "KHR_texture_transform",
    // Textures carry a DDS source in the extension; we use their plain `source` when there is
    // one and drop the texture with a warning otherwise. Large real scenes (GasStation) require
    // it without using any texture at all.
    "MSFT_texture_dds",
};

// An accessor without a bufferView (all zeros, maybe sparse) has no data bounding its count;
// this keeps a hostile count from turning into a multi-gigabyte allocation. Accessors with a
// bufferView are bounded by the file's size.
constexpr size_t kMaxUnbackedAccessorCount = size_t(1) << 24;

constexpr uint32_t kGlbMagic = 0x46546C67;     // "glTF", little endian
constexpr uint32_t kGlbJsonChunk = 0x4E4F534A; // "JSON"

/// tinygltf separates its messages with newlines; our errors are one line. It also quotes
/// whole data URIs, which can be megabytes of base64: those are cut short.
std::string oneLine(std::string_view text)
{
    std::string out;
    bool pendingSeparator = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (text.substr(i).starts_with(";base64,")) {
            out += ";base64,...";
            i += 8;
            while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '+' ||
                                       text[i] == '/' || text[i] == '='))
                ++i;
            --i;
            continue;
        }
        if (c == '\n' || c == '\r') {
            pendingSeparator = !out.empty();
            continue;
        }
        if (pendingSeparator) {
            out += "; ";
            pendingSeparator = false;
        }
        out += c;
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == '.')) out.pop_back();
    return out;
}

uint32_t readU32(const std::vector<unsigned char>& bytes, size_t offset)
{
    uint32_t value = 0;
    std::memcpy(&value, bytes.data() + offset, 4); // glTF is little endian, as are our targets
    return value;
}

// ---------------------------------------------------------------------------------------------
// Images

/// Decodes an encoded image (PNG, JPEG, ...) to RGBA8 into `image`; returns why it failed, or "".
/// Rows come out top first as Image wants, as long as nobody turns on stb's vertical flip (a
/// process-wide setting; nothing in Specula does).
std::string decodeRgba8(const unsigned char* bytes, size_t size, tinygltf::Image& image)
{
    if (size == 0) return "the image data is empty";
    if (size > size_t(std::numeric_limits<int>::max())) return "the image data is too large";
    const int length = int(size);
    int width = 0, height = 0, channels = 0;
    std::vector<unsigned char> pixels;
    // stb_image also reads 16-bit PNGs through stbi_load, but truncates them (v >> 8); read
    // them at 16 bits and round instead, so 8-bit values stored as 16-bit ones survive exactly.
    if (stbi_is_16_bit_from_memory(bytes, length)) {
        if (stbi_us* data = stbi_load_16_from_memory(bytes, length, &width, &height, &channels, 4)) {
            pixels.resize(size_t(width) * size_t(height) * 4);
            for (size_t i = 0; i < pixels.size(); ++i)
                pixels[i] = uint8_t((uint32_t(data[i]) * 255u + 32767u) / 65535u);
            stbi_image_free(data);
        }
    }
    if (pixels.empty()) {
        stbi_uc* data = stbi_load_from_memory(bytes, length, &width, &height, &channels, 4);
        if (!data) {
            const char* reason = stbi_failure_reason();
            return fmt::format("cannot decode it ({})", reason ? reason : "unknown format");
        }
        pixels.assign(data, data + size_t(width) * size_t(height) * 4);
        stbi_image_free(data);
    }
    image.width = width;
    image.height = height;
    image.component = 4;
    image.bits = 8;
    image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image.image = std::move(pixels);
    return {};
}

/// Why each image that failed to decode failed, by image index.
using ImageFailures = std::map<int, std::string>;

/// tinygltf's image callback. tinygltf fails the whole load when its own loader cannot decode
/// an image; ours records the problem and carries on, leaving the image empty.
bool loadImageData(tinygltf::Image* image, const int imageIndex, std::string* /*err*/, std::string* /*warn*/,
                   int /*reqWidth*/, int /*reqHeight*/, const unsigned char* bytes, int size, void* user)
{
    // Images in a bufferView are decoded later, from the bufferView once it is known to lie
    // inside its buffer: tinygltf hands us a pointer whose range it has not checked.
    if (image->bufferView >= 0) return true;
    const std::string reason = decodeRgba8(bytes, size_t(std::max(size, 0)), *image);
    if (!reason.empty()) (*static_cast<ImageFailures*>(user))[imageIndex] = reason;
    return true;
}

// ---------------------------------------------------------------------------------------------
// tinygltf::Value helpers (Value::Get asserts on the wrong type, so look before reading)

const tinygltf::Value* member(const tinygltf::Value& object, const char* key)
{
    if (!object.IsObject() || !object.Has(key)) return nullptr;
    return &object.Get(key);
}

const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const char* name)
{
    const auto it = extensions.find(name);
    return it != extensions.end() && it->second.IsObject() ? &it->second : nullptr;
}

std::optional<double> number(const tinygltf::Value& object, const char* key)
{
    const tinygltf::Value* value = member(object, key);
    if (!value || !value->IsNumber()) return std::nullopt;
    return value->GetNumberAsDouble();
}

/// A number as an int, clamped into int's range (converting an out-of-range double is undefined).
std::optional<int> integer(const tinygltf::Value& object, const char* key)
{
    const auto value = number(object, key);
    if (!value || std::isnan(*value)) return std::nullopt;
    return int(std::clamp(*value, double(std::numeric_limits<int>::min()), double(std::numeric_limits<int>::max())));
}

std::optional<glm::vec2> vec2(const tinygltf::Value& object, const char* key)
{
    const tinygltf::Value* value = member(object, key);
    if (!value || !value->IsArray() || value->ArrayLen() != 2) return std::nullopt;
    if (!value->Get(0).IsNumber() || !value->Get(1).IsNumber()) return std::nullopt;
    return glm::vec2(float(value->Get(0).GetNumberAsDouble()), float(value->Get(1).GetNumberAsDouble()));
}

// ---------------------------------------------------------------------------------------------
// Accessors

int componentCount(int type)
{
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0; // matrices: no vertex attribute we read uses them
    }
}

/// Byte size of a glTF accessor component type, or 0 for types glTF does not allow.
size_t componentSize(int componentType)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

template <typename T>
T load(const unsigned char* p)
{
    T value;
    std::memcpy(&value, p, sizeof(T)); // accessors need not be aligned for T in memory
    return value;
}

/// One component as a double; normalized integers map to [0, 1] or [-1, 1] with the glTF 2.0
/// spec's decoding equations (signed ones clamped so that -128 and -32768 give -1).
double readComponent(const unsigned char* p, int componentType, bool normalized)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const double v = load<int8_t>(p);
        return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
        const double v = load<uint8_t>(p);
        return normalized ? v / 255.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        const double v = load<int16_t>(p);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        const double v = load<uint16_t>(p);
        return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        const double v = load<uint32_t>(p);
        return normalized ? v / 4294967295.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
    default: return 0.0;
    }
}

/// Accessor contents as `components` values per element.
template <typename T>
struct AccessorData {
    size_t count = 0;
    int components = 0;
    std::vector<T> values;
    T at(size_t element, int component) const { return values[element * size_t(components) + size_t(component)]; }
};

/// A primitive's index list as a triangle list, whatever its (triangle) mode.
std::vector<uint32_t> triangulate(const std::vector<uint32_t>& in, int mode)
{
    std::vector<uint32_t> out;
    const size_t n = in.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        out.assign(in.begin(), in.begin() + std::ptrdiff_t(n - n % 3));
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        // The glTF 2.0 spec (Meshes, topology types): triangle i is (i, i + 1 + i % 2,
        // i + 2 - i % 2), which keeps every triangle counter-clockwise.
        for (size_t i = 0; i + 2 < n; ++i) {
            const uint32_t a = in[i], b = in[i + 1 + i % 2], c = in[i + 2 - i % 2];
            // Repeated indices are how strips are stitched together; they draw nothing.
            if (a != b && b != c && a != c) out.insert(out.end(), {a, b, c});
        }
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        // The glTF 2.0 spec (Meshes, topology types): triangle i is (i + 1, i + 2, 0).
        for (size_t i = 0; i + 2 < n; ++i) out.insert(out.end(), {in[i + 1], in[i + 2], in[0]});
    }
    return out;
}

const char* modeName(int mode)
{
    switch (mode) {
    case TINYGLTF_MODE_POINTS: return "points";
    case TINYGLTF_MODE_LINE: return "lines";
    case TINYGLTF_MODE_LINE_LOOP: return "line loops";
    case TINYGLTF_MODE_LINE_STRIP: return "line strips";
    default: return "an unknown mode";
    }
}

// ---------------------------------------------------------------------------------------------
// The conversion from tinygltf's model to our scene

class Importer {
public:
    Importer(std::string file, std::string name, tinygltf::Model& model, ImageFailures imageFailures)
        : mFile(std::move(file)), mModel(model), mImageFailures(std::move(imageFailures))
    {
        mScene.name = std::move(name);
    }

    Scene run()
    {
        checkVersion();
        checkRequiredExtensions();
        checkBufferViews();
        convertImages();
        convertSamplers();
        convertMaterials();
        convertMeshes();
        convertCameras();
        convertLights();
        convertNodes();
        chooseRoots();
        return std::move(mScene);
    }

private:
    template <typename... Args>
    [[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) const
    {
        throw Error("{}: {}", mFile, fmt::format(format, std::forward<Args>(args)...));
    }

    template <typename... Args>
    void warn(fmt::format_string<Args...> format, Args&&... args)
    {
        std::string message = fmt::format("{}: {}", mFile, fmt::format(format, std::forward<Args>(args)...));
        log::warn("{}", message);
        mScene.warnings.push_back(std::move(message));
    }

    /// `items[index]`, or an error naming `where` the index came from.
    template <typename T>
    const T& at(const std::vector<T>& items, int index, std::string_view kind, std::string_view where) const
    {
        if (index < 0 || size_t(index) >= items.size())
            fail("{} refers to {} {}, which is out of range (the file has {})", where, kind, index, items.size());
        return items[size_t(index)];
    }

    void checkVersion() const
    {
        // glTF 1.0 files are laid out differently and would load as nonsense.
        const std::string& version = mModel.asset.minVersion.empty() ? mModel.asset.version : mModel.asset.minVersion;
        if (!version.starts_with("2.")) fail("glTF version {} is not supported (only 2.x is)", version);
    }

    void checkRequiredExtensions() const
    {
        for (const std::string& name : mModel.extensionsRequired) {
            if (std::find(std::begin(kSupportedRequiredExtensions), std::end(kSupportedRequiredExtensions), name) ==
                std::end(kSupportedRequiredExtensions))
                fail("requires the unsupported extension {}", name);
        }
    }

    /// Every bufferView must lie inside its buffer; after this, views can be read unchecked.
    void checkBufferViews() const
    {
        for (size_t i = 0; i < mModel.bufferViews.size(); ++i) {
            const tinygltf::BufferView& view = mModel.bufferViews[i];
            const auto where = fmt::format("bufferView {}", i);
            const size_t size = at(mModel.buffers, view.buffer, "buffer", where).data.size();
            if (view.byteOffset > size || view.byteLength > size - view.byteOffset)
                fail("bufferView {} (offset {}, length {}) reaches past the end of buffer {} ({} bytes)", i,
                     view.byteOffset, view.byteLength, view.buffer, size);
        }
    }

    /// Start of `count` elements of `elementSize` bytes, `stride` apart, at `byteOffset` in a
    /// bufferView; an error unless they all lie inside it.
    const unsigned char* elements(int viewIndex, size_t byteOffset, size_t count, size_t elementSize, size_t stride,
                                  std::string_view where) const
    {
        assert(stride >= elementSize && elementSize > 0);
        const tinygltf::BufferView& view = at(mModel.bufferViews, viewIndex, "bufferView", where);
        if (count > 0) {
            const size_t length = view.byteLength;
            // Written to avoid overflow: offset + (count - 1) * stride + elementSize <= length.
            if (byteOffset > length || elementSize > length - byteOffset ||
                count - 1 > (length - byteOffset - elementSize) / stride)
                fail(
                    "{} reads past the end of bufferView {} ({} elements of {} bytes every {} from offset {}; the view "
                    "has {} bytes)",
                    where, viewIndex, count, elementSize, stride, byteOffset, length);
        }
        return mModel.buffers[size_t(view.buffer)].data.data() + view.byteOffset + byteOffset;
    }

    /// Reads accessor `index`, converting each component with readComponent, sparse values applied.
    template <typename T>
    AccessorData<T> read(int index, std::string_view where) const
    {
        const tinygltf::Accessor& accessor = at(mModel.accessors, index, "accessor", where);
        const auto name = fmt::format("accessor {}", index);
        AccessorData<T> out;
        out.components = componentCount(accessor.type);
        const size_t size = componentSize(accessor.componentType);
        if (out.components == 0) fail("{} is a matrix; {} needs a scalar or a vector", name, where);
        if (size == 0) fail("{} has the invalid componentType {}", name, accessor.componentType);
        out.count = accessor.count;
        const size_t elementSize = size * size_t(out.components);

        // Without a bufferView the accessor is all zeros (glTF 2.0 spec, Sparse Accessors).
        const unsigned char* data = nullptr;
        size_t stride = elementSize;
        if (accessor.bufferView >= 0) {
            const tinygltf::BufferView& view = at(mModel.bufferViews, accessor.bufferView, "bufferView", name);
            if (view.byteStride != 0) stride = view.byteStride;
            if (stride < elementSize)
                fail("{} has elements of {} bytes but bufferView {} has a byteStride of {}", name, elementSize,
                     accessor.bufferView, stride);
            data = elements(accessor.bufferView, accessor.byteOffset, out.count, elementSize, stride, name);
        } else if (out.count > kMaxUnbackedAccessorCount) {
            fail("{} has no bufferView and an implausible count ({})", name, out.count);
        }

        out.values.assign(out.count * size_t(out.components), T(0));
        auto readElement = [&](const unsigned char* p, size_t element) {
            for (int c = 0; c < out.components; ++c)
                out.values[element * size_t(out.components) + size_t(c)] =
                    T(readComponent(p + size_t(c) * size, accessor.componentType, accessor.normalized));
        };
        if (data)
            for (size_t i = 0; i < out.count; ++i) readElement(data + i * stride, i);

        if (accessor.sparse.isSparse) {
            const auto& sparse = accessor.sparse;
            const auto sparseName = fmt::format("the sparse part of {}", name);
            const int indexType = sparse.indices.componentType;
            if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
                fail("{} has indices of the invalid componentType {}", sparseName, indexType);
            if (sparse.count < 0 || size_t(sparse.count) > out.count || sparse.indices.byteOffset < 0 ||
                sparse.values.byteOffset < 0)
                fail("{} has an invalid count or byteOffset", sparseName);
            const size_t count = size_t(sparse.count);
            const size_t indexSize = componentSize(indexType);
            const unsigned char* indices = elements(sparse.indices.bufferView, size_t(sparse.indices.byteOffset), count,
                                                    indexSize, indexSize, sparseName);
            const unsigned char* values = elements(sparse.values.bufferView, size_t(sparse.values.byteOffset), count,
                                                   elementSize, elementSize, sparseName);
            for (size_t k = 0; k < count; ++k) {
                const auto target = size_t(readComponent(indices + k * indexSize, indexType, false));
                if (target >= out.count)
                    fail("{} replaces element {}, but the accessor has {}", sparseName, target, out.count);
                readElement(values + k * elementSize, target);
            }
        }
        return out;
    }

    // -- images, samplers, materials -----------------------------------------------------------

    void convertImages()
    {
        std::vector<bool> used(mModel.images.size(), false);
        for (const tinygltf::Texture& texture : mModel.textures)
            if (texture.source >= 0 && size_t(texture.source) < used.size()) used[size_t(texture.source)] = true;
        for (size_t i = 0; i < mModel.images.size(); ++i) {
            tinygltf::Image& source = mModel.images[i];
            const auto where = fmt::format("image {}", i);
            std::string failure;
            if (source.bufferView >= 0) {
                // checkBufferViews has made sure the view lies inside its buffer.
                const tinygltf::BufferView& view = at(mModel.bufferViews, source.bufferView, "bufferView", where);
                const unsigned char* bytes = mModel.buffers[size_t(view.buffer)].data.data() + view.byteOffset;
                failure = decodeRgba8(bytes, view.byteLength, source);
            } else if (source.image.empty()) {
                // tinygltf leaves an image empty, with a warning of its own, when it cannot read
                // the file; decoding failures were recorded by loadImageData.
                const auto it = mImageFailures.find(int(i));
                failure = it != mImageFailures.end() ? it->second : "the file is missing or unreadable";
            }

            Image image;
            const bool dataUri = source.uri.starts_with("data:");
            image.name = !source.name.empty() || dataUri ? source.name : source.uri;
            if (failure.empty() && source.width > 0 && source.height > 0 &&
                source.image.size() == size_t(source.width) * size_t(source.height) * 4) {
                image.width = source.width;
                image.height = source.height;
                image.pixels = std::move(source.image);
            } else {
                if (failure.empty()) failure = "it has no pixels";
                const std::string label =
                    source.uri.empty() || dataUri ? where : fmt::format("{} '{}'", where, source.uri);
                // Images no texture samples directly (the DDS ones of MSFT_texture_dds) cost nothing when missing.
                if (used[i]) {
                    warn("{}: {}; a neutral texture is used instead", label, failure);
                } else {
                    log::debug("{}: {}: {} (unused)", mFile, label, failure);
                }
            }
            mScene.images.push_back(std::move(image));
        }
    }

    static Wrap wrap(int mode)
    {
        switch (mode) {
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return Wrap::ClampToEdge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return Wrap::MirroredRepeat;
        default: return Wrap::Repeat; // glTF's default, also for invalid values
        }
    }

    void convertSamplers()
    {
        for (const tinygltf::Sampler& source : mModel.samplers) {
            Sampler sampler;
            sampler.magFilter = source.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ? Filter::Nearest : Filter::Linear;
            auto minify = [&sampler](Filter filter, bool mipmaps, bool mipLinear) {
                sampler.minFilter = filter;
                sampler.mipmaps = mipmaps;
                sampler.mipLinear = mipLinear;
            };
            switch (source.minFilter) {
            case TINYGLTF_TEXTURE_FILTER_NEAREST: minify(Filter::Nearest, false, false); break;
            case TINYGLTF_TEXTURE_FILTER_LINEAR: minify(Filter::Linear, false, false); break;
            case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST: minify(Filter::Nearest, true, false); break;
            case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST: minify(Filter::Linear, true, false); break;
            case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR: minify(Filter::Nearest, true, true); break;
            // LINEAR_MIPMAP_LINEAR, and an absent (-1) or invalid minFilter: trilinear, the default.
            default: minify(Filter::Linear, true, true); break;
            }
            sampler.wrapS = wrap(source.wrapS);
            sampler.wrapT = wrap(source.wrapT);
            mScene.samplers.push_back(sampler);
        }
    }

    TextureRef textureRef(int textureIndex, int texCoord, const tinygltf::ExtensionMap& extensions,
                          std::string_view where)
    {
        TextureRef ref;
        if (textureIndex < 0) return ref; // tinygltf's "absent"
        const tinygltf::Texture& texture = at(mModel.textures, textureIndex, "texture", where);
        const auto name = fmt::format("texture {}", textureIndex);
        if (texture.source < 0) {
            warn("{} has no image in a format we read; {} is drawn without it", name, where);
            return ref;
        }
        at(mModel.images, texture.source, "image", name);
        ref.image = texture.source;
        if (texture.sampler >= 0) {
            at(mModel.samplers, texture.sampler, "sampler", name);
            ref.sampler = texture.sampler;
        }
        ref.texCoord = texCoord;
        if (const tinygltf::Value* transform = extension(extensions, "KHR_texture_transform")) {
            ref.transform.offset = vec2(*transform, "offset").value_or(glm::vec2(0.0f));
            ref.transform.rotation = float(number(*transform, "rotation").value_or(0.0));
            ref.transform.scale = vec2(*transform, "scale").value_or(glm::vec2(1.0f));
            if (const auto override = integer(*transform, "texCoord")) ref.texCoord = *override;
        }
        if (ref.texCoord != 0 && ref.texCoord != 1) {
            warn("{} uses TEXCOORD_{}; only TEXCOORD_0 and TEXCOORD_1 are read, so TEXCOORD_0 is used", where,
                 ref.texCoord);
            ref.texCoord = 0;
        }
        return ref;
    }

    template <int N>
    glm::vec<N, float> factor(const std::vector<double>& values, glm::vec<N, float> fallback, std::string_view where,
                              std::string_view what) const
    {
        if (values.empty()) return fallback;
        if (values.size() != size_t(N)) fail("{}: {} has {} numbers instead of {}", where, what, values.size(), N);
        glm::vec<N, float> out;
        for (int i = 0; i < N; ++i) out[i] = float(values[size_t(i)]);
        return out;
    }

    void convertMaterials()
    {
        for (size_t i = 0; i < mModel.materials.size(); ++i) {
            const tinygltf::Material& source = mModel.materials[i];
            const auto where = fmt::format("material {}", i);
            const auto& pbr = source.pbrMetallicRoughness;
            Material material;
            material.name = source.name;
            material.baseColorFactor = factor<4>(pbr.baseColorFactor, glm::vec4(1.0f), where, "baseColorFactor");
            material.metallicFactor = float(pbr.metallicFactor);
            material.roughnessFactor = float(pbr.roughnessFactor);
            material.emissiveFactor = factor<3>(source.emissiveFactor, glm::vec3(0.0f), where, "emissiveFactor");
            if (const tinygltf::Value* strength = extension(source.extensions, "KHR_materials_emissive_strength"))
                material.emissiveStrength = float(number(*strength, "emissiveStrength").value_or(1.0));
            if (const tinygltf::Value* specular = extension(source.extensions, "KHR_materials_specular")) {
                material.specularFactor = float(std::clamp(number(*specular, "specularFactor").value_or(1.0), 0.0, 1.0));
                if (const tinygltf::Value* color = member(*specular, "specularColorFactor");
                    color && color->IsArray() && color->ArrayLen() == 3)
                    for (int c = 0; c < 3; ++c)
                        if (color->Get(c).IsNumber()) material.specularColorFactor[c] = float(std::max(color->Get(c).GetNumberAsDouble(), 0.0));
            }
            // KHR_materials_ior: 1.5 (the default) is F0 = 0.04 exactly; 0 means "no
            // interface" in the extension (transmission-only), which has no F0 here: left unset.
            if (const tinygltf::Value* ior = extension(source.extensions, "KHR_materials_ior")) {
                const double value = number(*ior, "ior").value_or(1.5);
                if (value >= 1.0 && value != 1.5) material.ior = float(value);
            }
            material.normalScale = float(source.normalTexture.scale);
            material.occlusionStrength = float(source.occlusionTexture.strength);
            if (source.alphaMode == "MASK") {
                material.alphaMode = AlphaMode::Mask;
            } else if (source.alphaMode == "BLEND") {
                material.alphaMode = AlphaMode::Blend;
            } else if (source.alphaMode != "OPAQUE") {
                warn("{} has the unknown alphaMode '{}'; it is drawn opaque", where, source.alphaMode);
            }
            material.alphaCutoff = float(source.alphaCutoff);
            material.doubleSided = source.doubleSided;

            material.baseColorTexture = textureRef(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                                   pbr.baseColorTexture.extensions, where + " baseColorTexture");
            material.metallicRoughnessTexture =
                textureRef(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                           pbr.metallicRoughnessTexture.extensions, where + " metallicRoughnessTexture");
            material.normalTexture = textureRef(source.normalTexture.index, source.normalTexture.texCoord,
                                                source.normalTexture.extensions, where + " normalTexture");
            material.occlusionTexture = textureRef(source.occlusionTexture.index, source.occlusionTexture.texCoord,
                                                   source.occlusionTexture.extensions, where + " occlusionTexture");
            material.emissiveTexture = textureRef(source.emissiveTexture.index, source.emissiveTexture.texCoord,
                                                  source.emissiveTexture.extensions, where + " emissiveTexture");
            mScene.materials.push_back(std::move(material));
        }
    }

    // -- meshes ----------------------------------------------------------------------------------

    std::optional<Primitive> convertPrimitive(const tinygltf::Primitive& source, const std::string& where)
    {
        // tinygltf reads an absent mode as TRIANGLES.
        const int mode = source.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            warn("{} draws {}, which are not supported; it is skipped", where, modeName(mode));
            return std::nullopt;
        }
        auto attribute = [&](const char* name) {
            const auto it = source.attributes.find(name);
            return it == source.attributes.end() ? -1 : it->second;
        };
        const int positionAccessor = attribute("POSITION");
        if (positionAccessor < 0) {
            // The glTF 2.0 spec (Meshes): without positions a primitive is not rendered.
            warn("{} has no POSITION; it is skipped", where);
            return std::nullopt;
        }

        const auto positions = read<float>(positionAccessor, where + " POSITION");
        if (positions.components != 3) fail("{} POSITION must be VEC3", where);
        const size_t vertexCount = positions.count;
        if (vertexCount > std::numeric_limits<uint32_t>::max()) fail("{} has too many vertices", where);

        // Reads an optional attribute; its count must match POSITION's.
        auto optional = [&](const char* name, int minComponents, int maxComponents) {
            std::optional<AccessorData<float>> data;
            const int index = attribute(name);
            if (index < 0) return data;
            const auto attributeWhere = fmt::format("{} {}", where, name);
            data = read<float>(index, attributeWhere);
            if (data->components < minComponents || data->components > maxComponents)
                fail("{} has {} components per element, which glTF does not allow", attributeWhere, data->components);
            if (data->count != vertexCount)
                fail("{} has {} elements but POSITION has {}", attributeWhere, data->count, vertexCount);
            return data;
        };
        const auto normals = optional("NORMAL", 3, 3);
        const auto tangents = optional("TANGENT", 4, 4);
        const auto uv0 = optional("TEXCOORD_0", 2, 2);
        const auto uv1 = optional("TEXCOORD_1", 2, 2);
        const auto colors = optional("COLOR_0", 3, 4);

        Primitive primitive;
        primitive.vertices.resize(vertexCount);
        for (size_t i = 0; i < vertexCount; ++i) {
            Vertex& v = primitive.vertices[i];
            v.position = {positions.at(i, 0), positions.at(i, 1), positions.at(i, 2)};
            if (normals) v.normal = {normals->at(i, 0), normals->at(i, 1), normals->at(i, 2)};
            if (tangents) {
                // glTF requires w = ±1; take only its sign, so a stray 0 cannot flatten the bitangent.
                v.tangent = {tangents->at(i, 0), tangents->at(i, 1), tangents->at(i, 2),
                             tangents->at(i, 3) < 0.0f ? -1.0f : 1.0f};
            }
            if (uv0) v.uv0 = {uv0->at(i, 0), uv0->at(i, 1)};
            if (uv1) v.uv1 = {uv1->at(i, 0), uv1->at(i, 1)};
            if (colors) {
                v.color = {colors->at(i, 0), colors->at(i, 1), colors->at(i, 2),
                           colors->components == 4 ? colors->at(i, 3) : 1.0f};
            }
            primitive.bounds.extend(v.position);
        }
        primitive.hasTangents = tangents.has_value();
        primitive.hasColors = colors.has_value();

        if (source.indices >= 0) {
            const auto indexWhere = where + " indices";
            const auto& accessor = at(mModel.accessors, source.indices, "accessor", indexWhere);
            if (accessor.type != TINYGLTF_TYPE_SCALAR ||
                (accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                 accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                 accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
                fail("{}: accessor {} must hold unsigned byte, short or int scalars", indexWhere, source.indices);
            auto indices = read<uint32_t>(source.indices, indexWhere);
            for (uint32_t index : indices.values)
                if (index >= vertexCount)
                    fail("{} refer to vertex {}, but there are {} vertices", indexWhere, index, vertexCount);
            primitive.indices = triangulate(indices.values, mode);
        } else if (mode != TINYGLTF_MODE_TRIANGLES) {
            std::vector<uint32_t> sequence(vertexCount);
            for (size_t i = 0; i < vertexCount; ++i) sequence[i] = uint32_t(i);
            primitive.indices = triangulate(sequence, mode);
        }

        if (source.material >= 0) {
            at(mModel.materials, source.material, "material", where);
            primitive.material = source.material;
        }

        if (!normals) {
            // The glTF 2.0 spec (Meshes): without normals, flat normals, and tangents are ignored.
            generateFlatNormals(primitive);
            primitive.hasTangents = false;
        }
        if (!primitive.hasTangents && primitive.material >= 0) {
            const TextureRef& normalTexture = mScene.materials[size_t(primitive.material)].normalTexture;
            if (normalTexture.valid()) generateTangents(primitive, normalTexture.texCoord);
        }
        return primitive;
    }

    void convertMeshes()
    {
        for (size_t m = 0; m < mModel.meshes.size(); ++m) {
            const tinygltf::Mesh& source = mModel.meshes[m];
            Mesh mesh;
            mesh.name = source.name;
            for (size_t p = 0; p < source.primitives.size(); ++p) {
                auto primitive = convertPrimitive(source.primitives[p], fmt::format("mesh {} primitive {}", m, p));
                if (primitive) mesh.primitives.push_back(std::move(*primitive));
            }
            mScene.meshes.push_back(std::move(mesh));
        }
    }

    // -- cameras, lights -------------------------------------------------------------------------

    void convertCameras()
    {
        for (size_t i = 0; i < mModel.cameras.size(); ++i) {
            const tinygltf::Camera& source = mModel.cameras[i];
            Camera camera;
            camera.name = source.name;
            if (source.type == "orthographic") {
                const auto& o = source.orthographic;
                camera.type = Camera::Type::Orthographic;
                camera.xmag = float(o.xmag);
                camera.ymag = float(o.ymag);
                camera.znear = float(o.znear);
                camera.zfar = float(o.zfar);
                if (!(camera.xmag != 0.0f && camera.ymag != 0.0f && camera.zfar > camera.znear &&
                      camera.znear >= 0.0f)) {
                    warn("camera {} has invalid orthographic parameters; defaults are used", i);
                    camera = Camera{.name = source.name, .type = Camera::Type::Orthographic};
                }
            } else {
                const auto& p = source.perspective;
                camera.yfov = float(p.yfov);
                camera.aspectRatio = float(p.aspectRatio);
                camera.znear = float(p.znear);
                camera.zfar = float(p.zfar); // 0: infinite, as in glTF
                const bool valid = camera.yfov > 0.0f && camera.yfov < glm::pi<float>() && camera.znear > 0.0f &&
                                   camera.aspectRatio >= 0.0f && (camera.zfar == 0.0f || camera.zfar > camera.znear);
                if (!valid) {
                    warn("camera {} has invalid perspective parameters; defaults are used", i);
                    camera = Camera{.name = source.name};
                }
            }
            mScene.cameras.push_back(std::move(camera));
        }
    }

    void convertLights()
    {
        for (size_t i = 0; i < mModel.lights.size(); ++i) {
            const tinygltf::Light& source = mModel.lights[i];
            Light light;
            light.name = source.name;
            light.intensity = float(source.intensity);
            if (source.type == "directional") {
                light.type = Light::Type::Directional;
            } else if (source.type == "spot") {
                light.type = Light::Type::Spot;
                // tinygltf fills in the extension's defaults, 0 and π/4.
                light.innerConeAngle = float(source.spot.innerConeAngle);
                light.outerConeAngle = float(source.spot.outerConeAngle);
            } else if (source.type != "point") {
                // Kept, dark, so that the nodes' light indices still line up.
                warn("light {} has the unknown type '{}'; it is left dark", i, source.type);
                light.intensity = 0.0f;
            }
            light.color = factor<3>(source.color, glm::vec3(1.0f), fmt::format("light {}", i), "color");
            light.range = float(source.range); // tinygltf: 0 when absent, meaning infinite
            mScene.lights.push_back(std::move(light));
        }
    }

    // -- nodes -----------------------------------------------------------------------------------

    void convertNodes()
    {
        for (size_t i = 0; i < mModel.nodes.size(); ++i) {
            const tinygltf::Node& source = mModel.nodes[i];
            const auto where = fmt::format("node {}", i);
            Node node;
            node.name = source.name;
            if (!source.matrix.empty()) {
                if (source.matrix.size() != 16)
                    fail("{}: matrix has {} numbers instead of 16", where, source.matrix.size());
                glm::mat4 matrix;
                for (int c = 0; c < 4; ++c)
                    for (int r = 0; r < 4; ++r) matrix[c][r] = float(source.matrix[size_t(c * 4 + r)]); // column major
                node.matrix = matrix;
            } else {
                node.translation = factor<3>(source.translation, glm::vec3(0.0f), where, "translation");
                node.scale = factor<3>(source.scale, glm::vec3(1.0f), where, "scale");
                const glm::vec4 q = factor<4>(source.rotation, glm::vec4(0, 0, 0, 1), where, "rotation"); // x y z w
                // Exporters write unit quaternions to float precision; renormalise, and treat a
                // zero (invalid) one as no rotation rather than a collapse to a point.
                const float length = glm::length(q);
                if (length > 1e-6f && std::isfinite(length)) {
                    node.rotation.x = q.x / length;
                    node.rotation.y = q.y / length;
                    node.rotation.z = q.z / length;
                    node.rotation.w = q.w / length;
                }
            }
            if (source.mesh >= 0) {
                at(mModel.meshes, source.mesh, "mesh", where);
                node.mesh = source.mesh;
            }
            if (source.camera >= 0) {
                at(mModel.cameras, source.camera, "camera", where);
                node.camera = source.camera;
            }
            if (const tinygltf::Value* lights = extension(source.extensions, "KHR_lights_punctual")) {
                if (const auto light = integer(*lights, "light")) {
                    at(mModel.lights, *light, "light", where);
                    node.light = *light;
                }
            }
            for (int child : source.children) {
                at(mModel.nodes, child, "node", where);
                node.children.push_back(child);
            }
            mScene.nodes.push_back(std::move(node));
        }

        // The glTF 2.0 spec (Nodes and Hierarchy): nodes form disjoint strict trees. Check it, so nothing downstream
        // walks a cycle or draws a node twice.
        mParent.assign(mScene.nodes.size(), -1);
        for (size_t i = 0; i < mScene.nodes.size(); ++i) {
            for (int child : mScene.nodes[i].children) {
                if (mParent[size_t(child)] >= 0 || child == int(i))
                    fail("node {} has more than one parent, or is its own child (nodes must form trees)", child);
                mParent[size_t(child)] = int(i);
            }
        }
        // With one parent each, every node is reached from a parentless one unless it lies on
        // (or below) a cycle.
        std::vector<bool> reached(mScene.nodes.size(), false);
        std::vector<int> stack;
        for (size_t i = 0; i < mScene.nodes.size(); ++i)
            if (mParent[i] < 0) stack.push_back(int(i));
        while (!stack.empty()) {
            const int node = stack.back();
            stack.pop_back();
            reached[size_t(node)] = true;
            for (int child : mScene.nodes[size_t(node)].children) stack.push_back(child);
        }
        for (size_t i = 0; i < reached.size(); ++i)
            if (!reached[i]) fail("node {} is part of a cycle in the node hierarchy", i);
    }

    void chooseRoots()
    {
        if (mModel.scenes.empty()) {
            // No scene to pick from: show everything.
            for (size_t i = 0; i < mScene.nodes.size(); ++i)
                if (mParent[i] < 0) mScene.roots.push_back(int(i));
            return;
        }
        const int sceneIndex = mModel.defaultScene >= 0 ? mModel.defaultScene : 0;
        const tinygltf::Scene& scene = at(mModel.scenes, sceneIndex, "scene", "the default scene");
        const auto where = fmt::format("scene {}", sceneIndex);
        for (int node : scene.nodes) {
            at(mModel.nodes, node, "node", where);
            if (mParent[size_t(node)] >= 0) {
                warn("{} lists node {}, which is not a root; it is ignored there", where, node);
                continue;
            }
            if (std::find(mScene.roots.begin(), mScene.roots.end(), node) == mScene.roots.end())
                mScene.roots.push_back(node);
        }
    }

    std::string mFile; ///< the path as the user gave it, for messages
    tinygltf::Model& mModel;
    ImageFailures mImageFailures;
    Scene mScene;
    std::vector<int> mParent; ///< per node, -1 for roots
};

// ---------------------------------------------------------------------------------------------
// Reading the file

std::vector<unsigned char> readFile(const fs::path& path, const std::string& file)
{
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error("{}: file not found", file);
    if (fs::is_directory(path, ec)) throw Error("{}: is a directory, not a glTF file", file);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("{}: cannot open the file", file);
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw Error("{}: cannot read the file", file);
    if (bytes.empty()) throw Error("{}: the file is empty", file);
    // tinygltf takes 32-bit lengths; GLB cannot exceed 4 GiB either.
    if (bytes.size() >= std::numeric_limits<uint32_t>::max()) throw Error("{}: the file is too large", file);
    return bytes;
}

/// The JSON text of a .gltf file or of a .glb's JSON chunk, or empty when it cannot be found.
std::string_view jsonText(const std::vector<unsigned char>& bytes, bool binary)
{
    const auto* chars = reinterpret_cast<const char*>(bytes.data());
    if (!binary) return {chars, bytes.size()};
    if (bytes.size() < 20) return {};
    const size_t length = readU32(bytes, 12);
    if (length > bytes.size() - 20) return {};
    return {chars + 20, length};
}

/// When tinygltf rejects a file, an unsupported required extension (Draco, say) is usually the
/// real reason: its data does not parse the way tinygltf expects. Name it if there is one.
std::string unsupportedRequiredExtension(std::string_view json)
{
    const auto document = nlohmann::json::parse(json.begin(), json.end(), nullptr, /*allow_exceptions*/ false);
    if (!document.is_object()) return {};
    const auto it = document.find("extensionsRequired");
    if (it == document.end() || !it->is_array()) return {};
    for (const auto& name : *it) {
        if (!name.is_string()) continue;
        const auto& text = name.get_ref<const std::string&>();
        if (std::find(std::begin(kSupportedRequiredExtensions), std::end(kSupportedRequiredExtensions), text) ==
            std::end(kSupportedRequiredExtensions))
            return text;
    }
    return {};
}

/// tinygltf's error, reworded where it is cryptic.
std::string describeLoadError(const std::string& err)
{
    std::string message = oneLine(err);
    if (message.empty()) return "not a valid glTF file";
    // nlohmann's messages start "[json.exception.parse_error.101] parse error at line 1, ...".
    if (message.starts_with("[json.exception.")) {
        const size_t end = message.find("] ");
        return "invalid JSON: " + (end == std::string::npos ? message : message.substr(end + 2));
    }
    return message;
}

} // namespace

Scene loadGltf(const fs::path& path)
{
    const std::string file = path.string();
    try {
        const std::vector<unsigned char> bytes = readFile(path, file);
        const bool binary = bytes.size() >= 4 && readU32(bytes, 0) == kGlbMagic;
        std::string extension = path.extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(),
                       [](unsigned char c) { return char(std::tolower(c)); });
        if (extension == ".glb" && !binary) throw Error("{}: not a binary glTF file (no 'glTF' magic)", file);
        if (binary) {
            // tinygltf reports all of these as "Invalid glTF binary"; say which.
            if (bytes.size() < 20)
                throw Error("{}: truncated .glb: {} bytes is less than a header", file, bytes.size());
            if (readU32(bytes, 4) != 2) throw Error("{}: unsupported .glb version {}", file, readU32(bytes, 4));
            if (readU32(bytes, 8) > bytes.size())
                throw Error("{}: truncated .glb: the header says {} bytes but the file has {}", file, readU32(bytes, 8),
                            bytes.size());
            if (readU32(bytes, 16) != kGlbJsonChunk) throw Error("{}: the first chunk of the .glb is not JSON", file);
            if (uint64_t(readU32(bytes, 12)) + 20 > bytes.size())
                throw Error("{}: truncated .glb: the JSON chunk needs {} bytes but the file has {}", file,
                            uint64_t(readU32(bytes, 12)) + 20, bytes.size());
        }

        tinygltf::TinyGLTF loader;
        ImageFailures imageFailures;
        loader.SetImageLoader(&loadImageData, &imageFailures);
        tinygltf::Model model;
        std::string err, warn;
        const std::string baseDir = path.parent_path().string();
        bool loaded = false;
        try {
            loaded =
                binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), baseDir)
                       : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                                    unsigned(bytes.size()), baseDir);
        } catch (const std::exception& e) {
            // tinygltf reports most problems through `err`, but not all (vector::at, bad_alloc).
            err = e.what();
        }
        if (!loaded) {
            const std::string extensionName = unsupportedRequiredExtension(jsonText(bytes, binary));
            if (!extensionName.empty()) throw Error("{}: requires the unsupported extension {}", file, extensionName);
            throw Error("{}: {}", file, describeLoadError(err));
        }
        // Missing images are reported again, with their consequence, by the importer.
        if (!warn.empty()) log::debug("{}: tinygltf: {}", file, oneLine(warn));

        return Importer(file, path.stem().string(), model, std::move(imageFailures)).run();
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        // bad_alloc and the like: still the user's file at fault, still one line.
        throw Error("{}: {}", file, e.what());
    }
}

} // namespace specula::scene
