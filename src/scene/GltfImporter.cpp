#include "scene/GltfImporter.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>

#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>

#include "scene/GltfInternal.h"

namespace specula::scene {

namespace {

namespace fs = std::filesystem;

/// Extensions we honour, so a file may list them as required and is not warned about them.
constexpr std::string_view kSupportedExtensions[] = {
    "EXT_mesh_gpu_instancing", // each instance a child node of its node (GltfImporter.cpp, meshInstances)
    "EXT_meshopt_compression",    // bufferViews decoded with meshoptimizer (GltfCompression.cpp)
    "EXT_texture_webp",           // WebP images decoded with libwebp (GltfMaterials.cpp)
    "KHR_animation_pointer",      // materials, texture transforms, lights, cameras, node visibility (GltfAnimation.cpp)
    "KHR_draco_mesh_compression", // primitives decoded with Draco (GltfCompression.cpp)
    "KHR_lights_punctual",
    "KHR_materials_anisotropy", // the anisotropic specular lobe (Material::anisotropy*)
    "KHR_materials_clearcoat", // the clearcoat layer (Material::clearcoat*)
    "KHR_materials_diffuse_transmission", // a Lambertian BTDF (Material::diffuseTransmission*)
    "KHR_materials_dispersion", // per-channel refraction through a volume (Material::dispersion)
    "KHR_materials_emissive_strength",
    "KHR_materials_sheen", // the sheen lobe (Material::sheen*)
    "KHR_materials_ior",      // F0 of the dielectric part (Material::ior)
    "KHR_materials_pbrSpecularGlossiness", // archived; converted (GltfMaterials.cpp, convertSpecularGlossiness)
    "KHR_materials_iridescence", // the thin film (Material::iridescence*)
    "KHR_materials_specular", // the dielectric F0 and F90: factors and textures (Material::specular*)
    "KHR_materials_transmission", // factor and texture (Material::transmission*; docs/transparency.md)
    "KHR_materials_unlit",    // the unlit shading model (Material::shading)
    "KHR_materials_variants", // material variants (Scene::variants, Primitive::variants; --variant)
    "KHR_node_visibility",    // hidden subtrees' meshes and lights are not drawn (Node::visible)
    "KHR_materials_volume",       // thickness (factor and texture) and attenuation (Material::thickness, attenuation*)
    "KHR_mesh_quantization", // integer attributes: the accessor reader handles every component type
    "KHR_texture_transform",
    // Metadata (XMP as JSON-LD packets on the asset and its objects): nothing in it changes
    // the image, so there is nothing to read and nothing to warn about.
    "KHR_xmp_json_ld",
    // Textures carry a DDS source in the extension; we use their plain `source` when there is
    // one and drop the texture with a warning otherwise. Large real scenes (GasStation) require
    // it without using any texture at all.
    "MSFT_texture_dds",
};

bool supported(std::string_view name)
{
    return std::find(std::begin(kSupportedExtensions), std::end(kSupportedExtensions), name) !=
           std::end(kSupportedExtensions);
}

/// Why a required extension is refused: the extension, and for the ones people ship that we
/// cannot read, why not.
std::string refusal(std::string_view name)
{
    if (name == "KHR_texture_basisu")
        return "requires the unsupported extension KHR_texture_basisu (KTX2 / Basis Universal textures: Debian 12 "
               "packages no KTX library to decode them)";
    return fmt::format("requires the unsupported extension {}", name);
}

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

} // namespace

namespace gltf_detail {

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
// The conversion from tinygltf's model to our scene: the checks, cameras, lights, nodes

void Importer::checkVersion() const
{
    // glTF 1.0 files are laid out differently and would load as nonsense.
    const std::string& version = mModel.asset.minVersion.empty() ? mModel.asset.version : mModel.asset.minVersion;
    if (!version.starts_with("2.")) fail("glTF version {} is not supported (only 2.x is)", version);
}

void Importer::checkRequiredExtensions() const
{
    for (const std::string& name : mModel.extensionsRequired)
        if (!supported(name)) fail("{}", refusal(name));
}

void Importer::warnIgnoredExtensions()
{
    std::vector<std::string_view> warned;
    for (const std::string& name : mModel.extensionsUsed) {
        if (supported(name) || std::find(warned.begin(), warned.end(), name) != warned.end()) continue;
        warned.push_back(name);
        if (name == "KHR_texture_basisu") {
            warn("uses KHR_texture_basisu (KTX2 / Basis Universal textures), which Specula cannot decode (Debian 12 "
                 "packages no KTX library); textures without a PNG or JPEG fallback are drawn without it");
        } else {
            warn("uses the extension {}, which Specula does not support; it is ignored", name);
        }
    }
}

/// Every bufferView must lie inside its buffer; after this, views can be read unchecked.
void Importer::checkBufferViews() const
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

// -- cameras, lights -------------------------------------------------------------------------

void Importer::convertCameras()
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

void Importer::convertLights()
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

void Importer::convertNodes()
{
    // EXT_mesh_gpu_instancing: each instance becomes a child node of its node that holds the
    // mesh (the node's own transform then the instance's, as the extension says), added after
    // the file's nodes so that their indices (animations, skins, scenes) stay.
    struct Instances {
        int node;
        std::vector<Node> children;
    };
    std::vector<Instances> instanced;
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
        if (source.skin >= 0) {
            at(mModel.skins, source.skin, "skin", where);
            node.skin = source.skin;
        }
        for (double w : source.weights) node.weights.push_back(float(w));
        for (int child : source.children) {
            at(mModel.nodes, child, "node", where);
            node.children.push_back(child);
        }
        if (const tinygltf::Value* instancing = extension(source.extensions, "EXT_mesh_gpu_instancing"))
            instanced.push_back({int(i), meshInstances(*instancing, node, where)});
        mScene.nodes.push_back(std::move(node));
    }
    for (Instances& instances : instanced) {
        Node& node = mScene.nodes[size_t(instances.node)];
        if (instances.children.empty()) continue;
        node.mesh = -1; // drawn by its instances only
        node.skin = -1;
        node.weights.clear();
        for (Node& child : instances.children) {
            child.weightsFrom = instances.node; // an animation of the node's weights reaches its instances
            mScene.nodes[size_t(instances.node)].children.push_back(int(mScene.nodes.size()));
            mScene.nodes.push_back(std::move(child));
        }
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

    // KHR_node_visibility: a node whose `visible` is false hides its meshes and lights and
    // those of every node below it, whatever theirs say; cameras stay (Scene::meshInstances).
    // A KHR_animation_pointer channel may change it (scene/Pose.h nodeVisibility).
    for (size_t i = 0; i < mModel.nodes.size(); ++i) {
        const tinygltf::Value* visibility = extension(mModel.nodes[i].extensions, "KHR_node_visibility");
        const tinygltf::Value* visible = visibility ? member(*visibility, "visible") : nullptr;
        if (visible && visible->IsBool()) mScene.nodes[i].visible = visible->Get<bool>();
    }
}

std::vector<Node> Importer::meshInstances(const tinygltf::Value& instancing, const Node& node, std::string_view where)
{
    const auto name = fmt::format("{} EXT_mesh_gpu_instancing", where);
    if (node.mesh < 0) {
        warn("{} has EXT_mesh_gpu_instancing but no mesh; the extension is ignored there", where);
        return {};
    }
    const tinygltf::Value* attributes = member(instancing, "attributes");
    if (!attributes || !attributes->IsObject()) fail("{} has no \"attributes\" object", name);
    // Each attribute is optional; those given must agree on the count (the extension's rule).
    std::optional<size_t> count;
    const auto attribute = [&](const char* key, int components) -> std::optional<AccessorData<float>> {
        const auto index = integer(*attributes, key);
        if (!index) return std::nullopt;
        const auto what = fmt::format("{} {}", name, key);
        // Held to --max-instances before anything is read: each instance becomes a node and a draw.
        const uint64_t declared = at(mModel.accessors, *index, "accessor", what).count;
        const uint64_t limit = mImages.limits.maxInstances;
        if (declared > limit - std::min(limit, mInstanceCount))
            fail("{} brings the model to {} instances, over the limit of {} (--max-instances)", what, mInstanceCount + declared, limit);
        AccessorData<float> data = read<float>(*index, what);
        if (data.components != components) fail("{} has {} components per element instead of {}", what, data.components, components);
        if (count && *count != data.count) fail("{} has {} elements where the other attributes have {}", what, data.count, *count);
        count = data.count;
        return data;
    };
    const auto translation = attribute("TRANSLATION", 3), rotation = attribute("ROTATION", 4), scale = attribute("SCALE", 3);
    if (!count) fail("{} names none of TRANSLATION, ROTATION and SCALE", name);
    mInstanceCount += *count;
    std::vector<Node> instances(*count);
    for (size_t k = 0; k < instances.size(); ++k) {
        Node& instance = instances[k];
        instance.name = fmt::format("{} instance {}", node.name.empty() ? std::string(where) : node.name, k);
        instance.mesh = node.mesh;
        instance.skin = node.skin;
        instance.weights = node.weights;
        if (translation) instance.translation = glm::vec3(translation->at(k, 0), translation->at(k, 1), translation->at(k, 2));
        if (scale) instance.scale = glm::vec3(scale->at(k, 0), scale->at(k, 1), scale->at(k, 2));
        if (rotation) {
            const glm::vec4 q(rotation->at(k, 0), rotation->at(k, 1), rotation->at(k, 2), rotation->at(k, 3)); // x y z w
            const float length = glm::length(q);
            if (!(length > 1e-6f) || !std::isfinite(length)) fail("{} ROTATION {} is not a rotation ({}, {}, {}, {})", name, k, q.x, q.y, q.z, q.w);
            instance.rotation = glm::quat(q.w / length, q.x / length, q.y / length, q.z / length);
        }
        const auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
        if (!finite(instance.translation) || !finite(instance.scale)) fail("{} instance {} has a number that is not finite", name, k);
    }
    return instances;
}

void Importer::chooseRoots()
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

} // namespace gltf_detail

namespace {

using gltf_detail::ImageDecoding;
using gltf_detail::Importer;
using gltf_detail::loadImageData;

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

/// When tinygltf rejects a file, an unsupported required extension is usually the real reason:
/// its data does not parse the way tinygltf expects. Name it if there is one.
std::string unsupportedRequiredExtension(std::string_view json)
{
    const auto document = nlohmann::json::parse(json.begin(), json.end(), nullptr, /*allow_exceptions*/ false);
    if (!document.is_object()) return {};
    const auto it = document.find("extensionsRequired");
    if (it == document.end() || !it->is_array()) return {};
    for (const auto& name : *it) {
        if (!name.is_string()) continue;
        const auto& text = name.get_ref<const std::string&>();
        if (!supported(text)) return text;
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

/// tinygltf's own spelling of percent-decoding (dlib::urldecode, '+' as a space too), so that the
/// checks see the path tinygltf will open.
std::string decodeUri(std::string_view uri)
{
    const auto hex = [](char c) -> unsigned {
        if (c >= '0' && c <= '9') return unsigned(c - '0');
        if (c >= 'a' && c <= 'f') return unsigned(c - 'a' + 10);
        if (c >= 'A' && c <= 'F') return unsigned(c - 'A' + 10);
        return 0;
    };
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            out += ' ';
        } else if (uri[i] == '%' && uri.size() > i + 2) {
            out += char((hex(uri[i + 1]) << 4) | hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

/// The first refusal of a declared reference or size, before tinygltf reads or allocates
/// anything for it: URIs outside the model's folder, buffers and accessors over the limits.
/// Anything malformed is left to tinygltf, which reports it.
void checkDeclarations(const std::string& file, std::string_view json, const fs::path& directory,
                       const LoadOptions& options)
{
    const auto document = nlohmann::json::parse(json.begin(), json.end(), nullptr, /*allow_exceptions*/ false);
    if (!document.is_object()) return;
    const auto array = [&](const char* key) -> const nlohmann::json* {
        const auto it = document.find(key);
        return it != document.end() && it->is_array() ? &*it : nullptr;
    };
    const auto checkUri = [&](const nlohmann::json& item, const char* kind, size_t index) {
        const auto uri = item.find("uri");
        if (uri == item.end() || !uri->is_string()) return;
        const auto& text = uri->get_ref<const std::string&>();
        if (text.starts_with("data:")) return; // embedded, no file
        const std::string decoded = decodeUri(text);
        if (const auto reason = refuseReference(directory, decoded, options.allowExternalFiles)) {
            throw Error("{}: {}[{}].uri '{}' {}: refused{}", file, kind, index, text, *reason,
                        options.allowExternalFiles ? "" : " (--allow-external-files allows files outside it)");
        }
    };
    const auto declared = [](const nlohmann::json& item, const char* key) -> std::optional<double> {
        const auto it = item.find(key);
        if (it == item.end() || !it->is_number()) return std::nullopt;
        return it->get<double>();
    };
    const LoadLimits& limits = options.limits;
    if (const auto* buffers = array("buffers")) {
        for (size_t i = 0; i < buffers->size(); ++i) {
            const auto& buffer = (*buffers)[i];
            if (!buffer.is_object()) continue;
            const auto bytes = declared(buffer, "byteLength");
            if (bytes && *bytes > double(limits.maxBufferBytes))
                throw Error("{}: buffers[{}] declares {} bytes, over the limit of {} (--max-buffer-bytes)", file, i,
                            *bytes, limits.maxBufferBytes);
            checkUri(buffer, "buffers", i);
        }
    }
    if (const auto* accessors = array("accessors")) {
        for (size_t i = 0; i < accessors->size(); ++i) {
            const auto& accessor = (*accessors)[i];
            if (!accessor.is_object()) continue;
            const auto count = declared(accessor, "count");
            if (count && *count > double(limits.maxAccessorCount))
                throw Error("{}: accessors[{}] declares {} elements, over the limit of {} (--max-accessor-count)", file,
                            i, *count, limits.maxAccessorCount);
        }
    }
    if (const auto* images = array("images")) {
        for (size_t i = 0; i < images->size(); ++i)
            if ((*images)[i].is_object()) checkUri((*images)[i], "images", i);
    }
}

/// What tinygltf (Debian's, built without its Draco option) cannot parse in compressed files
/// and WebP images, rewritten in the JSON before it sees it: the document after the changes and, for a .glb, the
/// file rebuilt around it; nothing when nothing needs changing.
struct PreparedFile {
    std::vector<unsigned char> bytes;
    /// Draco primitives' indices accessors, by mesh and primitive: tinygltf refuses an indices
    /// accessor without a bufferView, which is what Draco's are, so they are taken out of the
    /// primitives and handed to the importer instead.
    std::map<std::pair<size_t, size_t>, int> dracoIndices;
};

std::optional<PreparedFile> prepareForTinygltf(const std::vector<unsigned char>& bytes, bool binary)
{
    const std::string_view json = jsonText(bytes, binary);
    auto document = nlohmann::json::parse(json.begin(), json.end(), nullptr, /*allow_exceptions*/ false);
    if (!document.is_object()) return std::nullopt; // tinygltf reports it
    PreparedFile prepared;
    bool changed = false;
    const auto accessors = document.find("accessors");
    const auto meshes = document.find("meshes");
    if (meshes != document.end() && meshes->is_array()) {
        for (size_t m = 0; m < meshes->size(); ++m) {
            auto& mesh = (*meshes)[m];
            if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
            auto& primitives = mesh["primitives"];
            for (size_t p = 0; p < primitives.size(); ++p) {
                auto& primitive = primitives[p];
                if (!primitive.is_object() || !primitive.contains("indices") || !primitive["indices"].is_number_integer())
                    continue;
                const auto extensions = primitive.find("extensions");
                if (extensions == primitive.end() || !extensions->is_object() ||
                    !extensions->contains("KHR_draco_mesh_compression"))
                    continue;
                const auto index = primitive["indices"].get<int64_t>();
                if (index < 0 || accessors == document.end() || !accessors->is_array() || size_t(index) >= accessors->size())
                    continue; // out of range: the importer reports it
                if ((*accessors)[size_t(index)].contains("bufferView")) continue;
                prepared.dracoIndices[{m, p}] = int(index);
                primitive.erase("indices");
                changed = true;
            }
        }
    }
    // EXT_meshopt_compression's fallback buffer may hold no data (no uri); tinygltf then reads it
    // as the .glb's BIN chunk, or refuses a .gltf. Only compressed bufferViews may use it, and
    // those are decoded into buffers of their own: a one-byte stand-in is enough.
    const auto buffers = document.find("buffers");
    if (buffers != document.end() && buffers->is_array()) {
        for (size_t i = binary ? 1 : 0; i < buffers->size(); ++i) {
            auto& buffer = (*buffers)[i];
            if (!buffer.is_object() || buffer.contains("uri")) continue;
            const auto extensions = buffer.find("extensions");
            if (extensions == buffer.end() || !extensions->is_object()) continue;
            const auto meshopt = extensions->find("EXT_meshopt_compression");
            if (meshopt == extensions->end() || !meshopt->is_object()) continue;
            const auto fallback = meshopt->find("fallback");
            if (fallback == meshopt->end() || !fallback->is_boolean() || !fallback->get<bool>()) continue;
            buffer["uri"] = "data:application/octet-stream;base64,AA==";
            buffer["byteLength"] = 1;
            changed = true;
        }
    }
    // tinygltf takes data URIs of a fixed list of types only, which lacks WebP
    // (EXT_texture_webp); as a byte stream it hands them to our decoder just the same.
    const auto images = document.find("images");
    if (images != document.end() && images->is_array()) {
        constexpr std::string_view kWebpUri = "data:image/webp;base64,";
        for (auto& image : *images) {
            if (!image.is_object() || !image.contains("uri") || !image["uri"].is_string()) continue;
            auto& uri = image["uri"].get_ref<std::string&>();
            if (!uri.starts_with(kWebpUri)) continue;
            uri.replace(0, kWebpUri.size(), "data:application/octet-stream;base64,");
            changed = true;
        }
    }
    // KHR_animation_pointer's channels have no target node, which Debian's tinygltf requires:
    // -1 stands in for it (the importer reads the pointer from the target's extension).
    const auto animations = document.find("animations");
    if (animations != document.end() && animations->is_array()) {
        for (auto& animation : *animations) {
            if (!animation.is_object() || !animation.contains("channels") || !animation["channels"].is_array()) continue;
            for (auto& channel : animation["channels"]) {
                if (!channel.is_object() || !channel.contains("target") || !channel["target"].is_object()) continue;
                auto& target = channel["target"];
                if (target.contains("node")) continue;
                target["node"] = -1;
                changed = true;
            }
        }
    }
    if (!changed) return std::nullopt;

    std::string text = document.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    if (!binary) {
        prepared.bytes.assign(text.begin(), text.end());
        return prepared;
    }
    // glTF 2.0 spec (GLB file format): chunks are 4-byte aligned, JSON padded with spaces.
    while (text.size() % 4 != 0) text += ' ';
    const size_t rest = bytes.size() - 20 - json.size(); // the BIN chunk (and any after it)
    const auto put32 = [&](uint32_t value) {
        for (int k = 0; k < 4; ++k) prepared.bytes.push_back(uint8_t(value >> (8 * k)));
    };
    put32(kGlbMagic);
    put32(2);
    put32(uint32_t(12 + 8 + text.size() + rest));
    put32(uint32_t(text.size()));
    put32(kGlbJsonChunk);
    prepared.bytes.insert(prepared.bytes.end(), text.begin(), text.end());
    prepared.bytes.insert(prepared.bytes.end(), bytes.end() - std::ptrdiff_t(rest), bytes.end());
    return prepared;
}

/// tinygltf opens files through these. checkDeclarations has refused the URIs outside the
/// model's folder; these hold the line whatever tinygltf does with a URI (it also looks in the
/// current directory) and keep a file over the buffer limit from being read at all.
struct FileAccess {
    fs::path root; ///< canonical
    const LoadOptions& options;
    std::string refusal; ///< the first file refused, as the end of a message naming the model

    bool allowed(const std::string& path) const
    {
        if (options.allowExternalFiles) return true;
        std::error_code ec;
        const fs::path resolved = fs::weakly_canonical(path, ec);
        if (ec) return false;
        auto r = root.begin();
        for (auto p = resolved.begin(); r != root.end(); ++r, ++p)
            if (!r->empty() && (p == resolved.end() || *p != *r)) return false;
        return true;
    }
    static bool exists(const std::string& path, void* user)
    {
        std::error_code ec;
        return static_cast<FileAccess*>(user)->allowed(path) && fs::is_regular_file(path, ec);
    }
    static std::string expand(const std::string& path, void*) { return path; } // no ~ or $VARS
    static bool read(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user)
    {
        auto& self = *static_cast<FileAccess*>(user);
        if (!self.allowed(path)) {
            if (err) *err = "outside the model's folder";
            return false;
        }
        std::error_code ec;
        const uintmax_t size = fs::file_size(path, ec);
        if (ec) {
            if (err) *err = ec.message();
            return false;
        }
        if (size > self.options.limits.maxBufferBytes) {
            self.refusal = fmt::format("{} is {} bytes, over the limit of {} (--max-buffer-bytes)", path, size,
                                       self.options.limits.maxBufferBytes);
            if (err) *err = self.refusal;
            return false;
        }
        std::ifstream in(path, std::ios::binary);
        if (!in) {
            if (err) *err = "cannot open the file";
            return false;
        }
        out->resize(size_t(size));
        if (size > 0 && !in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size))) {
            if (err) *err = "cannot read the file";
            return false;
        }
        return true;
    }
    static bool write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*)
    {
        if (err) *err = "the importer writes no files";
        return false;
    }
};

Scene loadFromBytes(const std::string& file, const fs::path& path, const std::vector<unsigned char>& bytes,
                    const LoadOptions& options)
{
    if (bytes.empty()) throw Error("{}: the file is empty", file);
    // tinygltf takes 32-bit lengths; GLB cannot exceed 4 GiB either.
    if (bytes.size() >= std::numeric_limits<uint32_t>::max()) throw Error("{}: the file is too large", file);
    const bool binary = bytes.size() >= 4 && readU32(bytes, 0) == kGlbMagic;
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".glb" && !binary) throw Error("{}: not a binary glTF file (no 'glTF' magic)", file);
    if (binary) {
        // tinygltf reports all of these as "Invalid glTF binary"; say which.
        if (bytes.size() < 20) throw Error("{}: truncated .glb: {} bytes is less than a header", file, bytes.size());
        if (readU32(bytes, 4) != 2) throw Error("{}: unsupported .glb version {}", file, readU32(bytes, 4));
        if (readU32(bytes, 8) > bytes.size())
            throw Error("{}: truncated .glb: the header says {} bytes but the file has {}", file, readU32(bytes, 8),
                        bytes.size());
        if (readU32(bytes, 16) != kGlbJsonChunk) throw Error("{}: the first chunk of the .glb is not JSON", file);
        if (uint64_t(readU32(bytes, 12)) + 20 > bytes.size())
            throw Error("{}: truncated .glb: the JSON chunk needs {} bytes but the file has {}", file,
                        uint64_t(readU32(bytes, 12)) + 20, bytes.size());
    }
    const fs::path directory = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    checkDeclarations(file, jsonText(bytes, binary), directory, options);

    tinygltf::TinyGLTF loader;
    ImageDecoding images;
    images.limits = options.limits;
    loader.SetImageLoader(&loadImageData, &images);
    std::error_code ec;
    FileAccess access{fs::weakly_canonical(directory, ec), options, {}};
    loader.SetFsCallbacks({&FileAccess::exists, &FileAccess::expand, &FileAccess::read, &FileAccess::write, &access});
    tinygltf::Model model;
    std::string err, warn;
    const std::string baseDir = directory.string();
    bool loaded = false;
    std::optional<PreparedFile> prepared = prepareForTinygltf(bytes, binary);
    const std::vector<unsigned char>& parsed = prepared ? prepared->bytes : bytes;
    if (parsed.size() >= std::numeric_limits<uint32_t>::max()) throw Error("{}: the file is too large", file);
    try {
        loaded = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, parsed.data(), unsigned(parsed.size()), baseDir)
                        : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(parsed.data()),
                                                     unsigned(parsed.size()), baseDir);
    } catch (const std::exception& e) {
        // tinygltf reports most problems through `err`, but not all (vector::at, bad_alloc).
        err = e.what();
    }
    if (!images.refusal.empty()) throw Error("{}: {}", file, images.refusal);
    if (!access.refusal.empty()) throw Error("{}: {}", file, access.refusal);
    if (!loaded) {
        const std::string extensionName = unsupportedRequiredExtension(jsonText(bytes, binary));
        if (!extensionName.empty()) throw Error("{}: {}", file, refusal(extensionName));
        throw Error("{}: {}", file, describeLoadError(err));
    }
    // Missing images are reported again, with their consequence, by the importer.
    if (!warn.empty()) log::debug("{}: tinygltf: {}", file, oneLine(warn));

    return Importer(file, path.stem().string(), model, images, prepared ? std::move(prepared->dracoIndices) : decltype(PreparedFile::dracoIndices){}).run();
}

} // namespace

Scene loadGltf(const fs::path& path, const LoadOptions& options)
{
    const std::string file = path.string();
    try {
        return loadFromBytes(file, path, readFile(path, file), options);
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        // bad_alloc and the like: still the user's file at fault, still one line.
        throw Error("{}: {}", file, e.what());
    }
}

Scene loadGltfFromMemory(const std::vector<unsigned char>& bytes, const fs::path& path, const LoadOptions& options)
{
    const std::string file = path.string();
    try {
        return loadFromBytes(file, path, bytes, options);
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error("{}: {}", file, e.what());
    }
}

} // namespace specula::scene
