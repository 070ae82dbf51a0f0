// glTF import: images, samplers, textures and materials, with their extensions.
#include <algorithm>
#include <cmath>
#include <limits>

#include <cstring>

#include <webp/decode.h>

#include "core/ImageIO.h"
#include "scene/GltfInternal.h"

namespace specula::scene::gltf_detail {

namespace {

// ---------------------------------------------------------------------------------------------
// Images

/// Decodes an encoded image (PNG, JPEG, WebP) to RGBA8 into `image`; returns why it failed, or
/// "". A warning from the decoder (corrupt data it got past) goes to decoding.warnings.
/// An image over a limit sets `decoding.refusal` (the load fails) before anything is decoded:
/// the decoders allocate the whole image from the header's size before they read the pixels,
/// so a few hundred forged bytes would otherwise cost gigabytes.
std::string decodeRgba8(const unsigned char* bytes, size_t size, tinygltf::Image& image, int index,
                        ImageDecoding& decoding)
{
    if (size == 0) return "the image data is empty";
    if (size > size_t(std::numeric_limits<int>::max())) return "the image data is too large";
    // EXT_texture_webp's images (RIFF container, WEBP form), decoded with libwebp.
    const bool webp = size >= 12 && std::memcmp(bytes, "RIFF", 4) == 0 && std::memcmp(bytes + 8, "WEBP", 4) == 0;
    // glTF's images are PNG and JPEG (WebP with EXT_texture_webp).
    if (!webp && !isPngOrJpeg(bytes, size)) return "cannot decode it (not a PNG, JPEG or WebP image)";
    int width = 0, height = 0;
    bool sized = false;
    if (webp) {
        sized = WebPGetInfo(bytes, size, &width, &height) != 0;
    } else if (const std::optional<EncodedImageSize> header = encodedImageSize(bytes, size)) {
        width = header->width;
        height = header->height;
        sized = true;
    }
    if (sized) {
        const LoadLimits& limits = decoding.limits;
        const uint64_t bytesNeeded = uint64_t(width) * uint64_t(height) * 4;
        if (width > limits.maxImageSize || height > limits.maxImageSize) {
            decoding.refusal = fmt::format("image {} is {}x{} pixels, over the limit of {} per side (--max-image-size)",
                                           index, width, height, limits.maxImageSize);
            return decoding.refusal;
        }
        if (bytesNeeded > limits.maxTextureBytes - std::min(limits.maxTextureBytes, decoding.textureBytes)) {
            decoding.refusal =
                fmt::format("image {} ({}x{}) brings the model's textures to {} bytes, over the limit of {} "
                            "(--max-texture-memory)", index, width, height, decoding.textureBytes + bytesNeeded,
                            limits.maxTextureBytes);
            return decoding.refusal;
        }
        decoding.textureBytes += bytesNeeded;
    }
    std::vector<unsigned char> pixels;
    if (webp) {
        uint8_t* data = WebPDecodeRGBA(bytes, size, &width, &height);
        if (!data) return "cannot decode it (malformed WebP data)";
        pixels.assign(data, data + size_t(width) * size_t(height) * 4);
        WebPFree(data);
    } else {
        DecodedImage decoded = decodePngOrJpeg(bytes, size);
        if (!decoded.error.empty()) return fmt::format("cannot decode it ({})", decoded.error);
        if (!decoded.warning.empty()) decoding.warnings[index] = decoded.warning;
        width = decoded.image.width;
        height = decoded.image.height;
        pixels = std::move(decoded.image.pixels);
    }
    image.width = width;
    image.height = height;
    image.component = 4;
    image.bits = 8;
    image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image.image = std::move(pixels);
    return {};
}

} // namespace

/// tinygltf's image callback. tinygltf fails the whole load when its own loader cannot decode
/// an image; ours records the problem and carries on, leaving the image empty.
bool loadImageData(tinygltf::Image* image, const int imageIndex, std::string* err, std::string* /*warn*/,
                   int /*reqWidth*/, int /*reqHeight*/, const unsigned char* bytes, int size, void* user)
{
    // Images in a bufferView are decoded later, from the bufferView once it is known to lie
    // inside its buffer: tinygltf hands us a pointer whose range it has not checked.
    if (image->bufferView >= 0) return true;
    auto& decoding = *static_cast<ImageDecoding*>(user);
    const std::string reason = decodeRgba8(bytes, size_t(std::max(size, 0)), *image, imageIndex, decoding);
    if (!decoding.refusal.empty()) {
        if (err) *err = decoding.refusal; // loadGltf reports decoding.refusal itself
        return false;
    }
    if (!reason.empty()) decoding.failures[imageIndex] = reason;
    return true;
}

// -- images, samplers, materials -----------------------------------------------------------

void Importer::convertImages()
{
    std::vector<bool> used(mModel.images.size(), false);
    for (const tinygltf::Texture& texture : mModel.textures) {
        const int image = textureSource(texture);
        if (image >= 0 && size_t(image) < used.size()) used[size_t(image)] = true;
    }
    for (size_t i = 0; i < mModel.images.size(); ++i) {
        tinygltf::Image& source = mModel.images[i];
        const auto where = fmt::format("image {}", i);
        std::string failure;
        if (source.bufferView >= 0) {
            // checkBufferViews has made sure the view lies inside its buffer.
            const tinygltf::BufferView& view = at(mModel.bufferViews, source.bufferView, "bufferView", where);
            const unsigned char* bytes = mModel.buffers[size_t(view.buffer)].data.data() + view.byteOffset;
            failure = decodeRgba8(bytes, view.byteLength, source, int(i), mImages);
            if (!mImages.refusal.empty()) fail("{}", mImages.refusal);
        } else if (source.image.empty()) {
            // tinygltf leaves an image empty, with a warning of its own, when it cannot read
            // the file; decoding failures were recorded by loadImageData.
            const auto it = mImages.failures.find(int(i));
            failure = it != mImages.failures.end() ? it->second : "the file is missing or unreadable";
        }

        Image image;
        const bool dataUri = source.uri.starts_with("data:");
        image.name = !source.name.empty() || dataUri ? source.name : source.uri;
        const std::string label = source.uri.empty() || dataUri ? where : fmt::format("{} '{}'", where, source.uri);
        if (failure.empty() && source.width > 0 && source.height > 0 &&
            source.image.size() == size_t(source.width) * size_t(source.height) * 4) {
            image.width = source.width;
            image.height = source.height;
            image.pixels = std::move(source.image);
            if (const auto it = mImages.warnings.find(int(i)); it != mImages.warnings.end())
                warn("{}: {} (decoded anyway)", label, it->second);
        } else {
            if (failure.empty()) failure = "it has no pixels";
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

int Importer::textureSource(const tinygltf::Texture& texture)
{
    // EXT_texture_webp: the WebP image, in place of `source` (a PNG or JPEG fallback, if any).
    if (const tinygltf::Value* webp = extension(texture.extensions, "EXT_texture_webp"))
        if (const auto image = integer(*webp, "source"); image && *image >= 0) return *image;
    return texture.source;
}

Wrap Importer::wrap(int mode)
{
    switch (mode) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return Wrap::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return Wrap::MirroredRepeat;
    default: return Wrap::Repeat; // glTF's default, also for invalid values
    }
}

void Importer::convertSamplers()
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

TextureRef Importer::textureRef(int textureIndex, int texCoord, const tinygltf::ExtensionMap& extensions,
                                std::string_view where)
{
    TextureRef ref;
    if (textureIndex < 0) return ref; // tinygltf's "absent"
    const tinygltf::Texture& texture = at(mModel.textures, textureIndex, "texture", where);
    const auto name = fmt::format("texture {}", textureIndex);
    const int image = textureSource(texture);
    if (image < 0) {
        // KHR_texture_basisu's textures were warned about once, by the extension's name.
        if (extension(texture.extensions, "KHR_texture_basisu"))
            log::debug("{}: {} has only a KTX2 image; {} is drawn without it", mFile, name, where);
        else
            warn("{} has no image in a format we read; {} is drawn without it", name, where);
        return ref;
    }
    at(mModel.images, image, "image", name);
    ref.image = image;
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

TextureRef Importer::extensionTexture(const tinygltf::Value& extension, const char* name, std::string_view where)
{
    // A textureInfo inside a material extension: tinygltf leaves it as JSON.
    const tinygltf::Value* info = member(extension, name);
    if (!info || !info->IsObject()) return {};
    const auto index = integer(*info, "index");
    if (!index) return {};
    tinygltf::ExtensionMap extensions;
    if (const tinygltf::Value* ext = member(*info, "extensions"); ext && ext->IsObject())
        for (const std::string& key : ext->Keys()) extensions[key] = ext->Get(key);
    return textureRef(*index, integer(*info, "texCoord").value_or(0), extensions, fmt::format("{} {}", where, name));
}

void Importer::convertMaterials()
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
            material.specularTexture = extensionTexture(*specular, "specularTexture", where);
            material.specularColorTexture = extensionTexture(*specular, "specularColorTexture", where);
        }
        // KHR_materials_ior: 1.5 (the default) is F0 = 0.04 exactly; 0 means "no
        // interface" in the extension (transmission-only), which has no F0 here: left unset.
        if (const tinygltf::Value* ior = extension(source.extensions, "KHR_materials_ior")) {
            const double value = number(*ior, "ior").value_or(1.5);
            if (value >= 1.0 && value != 1.5) material.ior = float(value);
        }
        // KHR_materials_transmission and KHR_materials_volume. Volume without transmission
        // changes nothing (the extension's rule).
        if (const tinygltf::Value* transmission = extension(source.extensions, "KHR_materials_transmission")) {
            material.transmissionFactor = float(std::clamp(number(*transmission, "transmissionFactor").value_or(0.0), 0.0, 1.0));
            material.transmissionTexture = extensionTexture(*transmission, "transmissionTexture", where);
        }
        if (const tinygltf::Value* volume = extension(source.extensions, "KHR_materials_volume")) {
            material.thickness = float(std::max(number(*volume, "thicknessFactor").value_or(0.0), 0.0));
            // The extension's default distance is +infinity, which glTF's JSON cannot write: 0 holds it here.
            const double distance = number(*volume, "attenuationDistance").value_or(0.0);
            material.attenuationDistance = std::isfinite(distance) && distance > 0.0 ? float(distance) : 0.0f;
            if (const tinygltf::Value* color = member(*volume, "attenuationColor");
                color && color->IsArray() && color->ArrayLen() == 3)
                for (int c = 0; c < 3; ++c)
                    if (color->Get(c).IsNumber()) material.attenuationColor[c] = float(std::clamp(color->Get(c).GetNumberAsDouble(), 0.0, 1.0));
            material.thicknessTexture = extensionTexture(*volume, "thicknessTexture", where);
        }
        // KHR_materials_dispersion: 20 / V_d; it spreads the refraction through a volume.
        if (const tinygltf::Value* dispersion = extension(source.extensions, "KHR_materials_dispersion")) {
            const double value = number(*dispersion, "dispersion").value_or(0.0);
            material.dispersion = std::isfinite(value) ? float(std::max(value, 0.0)) : 0.0f;
        }
        // KHR_materials_diffuse_transmission: a Lambertian BTDF for that fraction of the diffuse lobe.
        if (const tinygltf::Value* diffuse = extension(source.extensions, "KHR_materials_diffuse_transmission")) {
            const double value = number(*diffuse, "diffuseTransmissionFactor").value_or(0.0);
            material.diffuseTransmissionFactor = std::isfinite(value) ? float(std::clamp(value, 0.0, 1.0)) : 0.0f;
            if (const tinygltf::Value* color = member(*diffuse, "diffuseTransmissionColorFactor");
                color && color->IsArray() && color->ArrayLen() == 3)
                for (int c = 0; c < 3; ++c)
                    if (color->Get(c).IsNumber())
                        material.diffuseTransmissionColorFactor[c] = float(std::clamp(color->Get(c).GetNumberAsDouble(), 0.0, 1.0));
            material.diffuseTransmissionTexture = extensionTexture(*diffuse, "diffuseTransmissionTexture", where);
            material.diffuseTransmissionColorTexture = extensionTexture(*diffuse, "diffuseTransmissionColorTexture", where);
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
        // KHR_materials_clearcoat: factors, their textures and the layer's normal map.
        if (const tinygltf::Value* clearcoat = extension(source.extensions, "KHR_materials_clearcoat")) {
            material.clearcoatFactor = float(std::clamp(number(*clearcoat, "clearcoatFactor").value_or(0.0), 0.0, 1.0));
            material.clearcoatRoughnessFactor =
                float(std::clamp(number(*clearcoat, "clearcoatRoughnessFactor").value_or(0.0), 0.0, 1.0));
            material.clearcoatTexture = extensionTexture(*clearcoat, "clearcoatTexture", where);
            material.clearcoatRoughnessTexture = extensionTexture(*clearcoat, "clearcoatRoughnessTexture", where);
            material.clearcoatNormalTexture = extensionTexture(*clearcoat, "clearcoatNormalTexture", where);
            if (const tinygltf::Value* normal = member(*clearcoat, "clearcoatNormalTexture"))
                material.clearcoatNormalScale = float(number(*normal, "scale").value_or(1.0));
        }
        // KHR_materials_sheen: colour and roughness factors and their textures (sRGB RGB, A).
        if (const tinygltf::Value* sheen = extension(source.extensions, "KHR_materials_sheen")) {
            if (const tinygltf::Value* color = member(*sheen, "sheenColorFactor"); color && color->IsArray() && color->ArrayLen() == 3)
                for (int c = 0; c < 3; ++c) {
                    const tinygltf::Value& e = color->Get(c);
                    if (e.IsNumber()) material.sheenColorFactor[c] = float(std::clamp(e.GetNumberAsDouble(), 0.0, 1.0));
                }
            material.sheenRoughnessFactor = float(std::clamp(number(*sheen, "sheenRoughnessFactor").value_or(0.0), 0.0, 1.0));
            material.sheenColorTexture = extensionTexture(*sheen, "sheenColorTexture", where);
            material.sheenRoughnessTexture = extensionTexture(*sheen, "sheenRoughnessTexture", where);
        }
        // KHR_materials_anisotropy: strength (0 to 1), rotation (radians, any), the texture.
        if (const tinygltf::Value* anisotropy = extension(source.extensions, "KHR_materials_anisotropy")) {
            material.anisotropyStrength = float(std::clamp(number(*anisotropy, "anisotropyStrength").value_or(0.0), 0.0, 1.0));
            const double rotation = number(*anisotropy, "anisotropyRotation").value_or(0.0);
            material.anisotropyRotation = std::isfinite(rotation) ? float(std::remainder(rotation, 2.0 * 3.14159265358979323846)) : 0.0f;
            material.anisotropyTexture = extensionTexture(*anisotropy, "anisotropyTexture", where);
        }
        // KHR_materials_iridescence: strength (R) and thickness (G) textures, the film's IOR and
        // thickness range in nm (the minimum may exceed the maximum: the texture mixes them).
        if (const tinygltf::Value* iridescence = extension(source.extensions, "KHR_materials_iridescence")) {
            material.iridescenceFactor = float(std::clamp(number(*iridescence, "iridescenceFactor").value_or(0.0), 0.0, 1.0));
            material.iridescenceIor = float(std::max(number(*iridescence, "iridescenceIor").value_or(1.3), 1.0));
            material.iridescenceThicknessMinimum = float(std::max(number(*iridescence, "iridescenceThicknessMinimum").value_or(100.0), 0.0));
            material.iridescenceThicknessMaximum = float(std::max(number(*iridescence, "iridescenceThicknessMaximum").value_or(400.0), 0.0));
            material.iridescenceTexture = extensionTexture(*iridescence, "iridescenceTexture", where);
            material.iridescenceThicknessTexture = extensionTexture(*iridescence, "iridescenceThicknessTexture", where);
        }
        if (const tinygltf::Value* sg = extension(source.extensions, "KHR_materials_pbrSpecularGlossiness"))
            convertSpecularGlossiness(*sg, material, where);
        // KHR_materials_unlit: colour = the base colour term (factor × texture × vertex colour),
        // whatever the lights and the environment. The other PBR properties are only the fallback
        // of viewers without the extension (kept for --shading pbr), but emission is no part of
        // the unlit colour, so it goes.
        if (extension(source.extensions, "KHR_materials_unlit")) {
            material.shading.model = ShadingModel::Unlit;
            material.emissiveFactor = glm::vec3(0.0f);
            material.emissiveTexture = {};
        }
        mScene.materials.push_back(std::move(material));
    }
}

void Importer::convertSpecularGlossiness(const tinygltf::Value& sg, Material& material, const std::string& where)
{
    // The archived KHR_materials_pbrSpecularGlossiness, converted as KHR_materials_specular's
    // text describes: a dielectric whose F0 is the specular colour itself (ior 0: F0(ior) = 1,
    // times specularColor), base colour = diffuse, roughness = 1 - glossiness. It replaces the
    // metal-rough values, which are only the fallback of viewers without the extension.
    material.baseColorFactor = glm::vec4(1.0f);
    if (const tinygltf::Value* diffuse = member(sg, "diffuseFactor"); diffuse && diffuse->IsArray() && diffuse->ArrayLen() == 4)
        for (int c = 0; c < 4; ++c)
            if (diffuse->Get(c).IsNumber()) material.baseColorFactor[c] = float(std::clamp(diffuse->Get(c).GetNumberAsDouble(), 0.0, 1.0));
    material.baseColorTexture = extensionTexture(sg, "diffuseTexture", where);
    material.specularColorFactor = glm::vec3(1.0f);
    if (const tinygltf::Value* specular = member(sg, "specularFactor"); specular && specular->IsArray() && specular->ArrayLen() == 3)
        for (int c = 0; c < 3; ++c)
            if (specular->Get(c).IsNumber()) material.specularColorFactor[c] = float(std::clamp(specular->Get(c).GetNumberAsDouble(), 0.0, 1.0));
    material.specularFactor = 1.0f;
    material.ior = 0.0f;
    material.metallicFactor = 0.0f;
    const float glossiness = float(std::clamp(number(sg, "glossinessFactor").value_or(1.0), 0.0, 1.0));
    material.roughnessFactor = 1.0f - glossiness;
    material.metallicRoughnessTexture = {};
    // specularGlossinessTexture: RGB the specular colour (sRGB), A the glossiness (linear).
    const TextureRef texture = extensionTexture(sg, "specularGlossinessTexture", where);
    material.specularColorTexture = texture;
    if (texture.valid()) {
        // Roughness 1 - glossinessFactor x A is no factor times a texel: a linear image of it in G
        // (the metallic-roughness texture's channel), one per source image and factor.
        const auto key = std::make_pair(texture.image, glossiness);
        auto found = mRoughnessImages.find(key);
        if (found == mRoughnessImages.end()) {
            const Image& source = mScene.images.at(size_t(texture.image));
            int derived = -1;
            if (!source.pixels.empty()) {
                // Held to the model's texture memory like any decoded image.
                const LoadLimits& limits = mImages.limits;
                const uint64_t bytes = source.pixels.size();
                if (bytes > limits.maxTextureBytes - std::min(limits.maxTextureBytes, mImages.textureBytes))
                    fail("{}: the roughness made from specularGlossinessTexture's image {} brings the model's textures to {} "
                         "bytes, over the limit of {} (--max-texture-memory)",
                         where, texture.image, mImages.textureBytes + bytes, limits.maxTextureBytes);
                mImages.textureBytes += bytes;
                Image roughness;
                roughness.name = source.name + " (roughness from glossiness)";
                roughness.width = source.width;
                roughness.height = source.height;
                roughness.pixels.resize(source.pixels.size());
                for (size_t i = 0; i + 3 < source.pixels.size(); i += 4) {
                    const float g = glossiness * float(source.pixels[i + 3]) / 255.0f;
                    roughness.pixels[i] = 255;
                    roughness.pixels[i + 1] = uint8_t(std::lround(255.0f * (1.0f - g)));
                    roughness.pixels[i + 2] = 0;
                    roughness.pixels[i + 3] = 255;
                }
                mScene.images.push_back(std::move(roughness));
                derived = int(mScene.images.size() - 1);
            }
            found = mRoughnessImages.emplace(key, derived).first;
        }
        if (found->second >= 0) {
            material.metallicRoughnessTexture = texture;
            material.metallicRoughnessTexture.image = found->second;
            material.roughnessFactor = 1.0f;
        }
    }
}

void Importer::convertVariants()
{
    const tinygltf::Value* root = extension(mModel.extensions, "KHR_materials_variants");
    if (!root) return;
    const tinygltf::Value* variants = member(*root, "variants");
    if (!variants || !variants->IsArray()) fail("KHR_materials_variants has no \"variants\" array");
    for (size_t i = 0; i < variants->ArrayLen(); ++i) {
        const tinygltf::Value* name = member(variants->Get(int(i)), "name");
        if (!name || !name->IsString()) fail("KHR_materials_variants variant {} has no name", i);
        mScene.variants.push_back(name->Get<std::string>());
    }
}

void Importer::readVariantMappings(const tinygltf::Primitive& source, Primitive& primitive, const std::string& where) const
{
    const tinygltf::Value* extensionObject = extension(source.extensions, "KHR_materials_variants");
    if (!extensionObject) return;
    const auto context = where + " KHR_materials_variants";
    const tinygltf::Value* mappings = member(*extensionObject, "mappings");
    if (!mappings || !mappings->IsArray()) fail("{} has no \"mappings\" array", context);
    for (size_t m = 0; m < mappings->ArrayLen(); ++m) {
        const tinygltf::Value& mapping = mappings->Get(int(m));
        const auto mappingWhere = fmt::format("{} mapping {}", context, m);
        const std::optional<int> material = integer(mapping, "material");
        if (!material) fail("{} has no material", mappingWhere);
        at(mModel.materials, *material, "material", mappingWhere);
        const tinygltf::Value* variants = member(mapping, "variants");
        if (!variants || !variants->IsArray() || variants->ArrayLen() == 0)
            fail("{} has no \"variants\" array", mappingWhere);
        for (size_t v = 0; v < variants->ArrayLen(); ++v) {
            const tinygltf::Value& index = variants->Get(int(v));
            const double value = index.IsNumber() ? index.GetNumberAsDouble() : -1.0;
            if (!(value >= 0.0 && value < double(mScene.variants.size())) || value != double(int(value)))
                fail("{} refers to variant {}, which is out of range (the file has {})", mappingWhere,
                     index.IsNumber() ? fmt::format("{}", value) : std::string("(not a number)"), mScene.variants.size());
            const int variant = int(value);
            // Each variant once per primitive: a second mapping of it would be ambiguous.
            for (const VariantMapping& earlier : primitive.variants)
                if (earlier.variant == variant) fail("{} maps variant {} a second time", mappingWhere, variant);
            primitive.variants.push_back({variant, *material});
        }
    }
}

} // namespace specula::scene::gltf_detail
