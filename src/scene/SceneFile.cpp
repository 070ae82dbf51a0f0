#include "scene/SceneFile.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <climits>
#include <cstdint>
#include <fstream>
#include <random>
#include <set>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "core/ImageIO.h"
#include "scene/GltfImporter.h"
#include "scene/Procedural.h"

namespace specula::scene {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

std::string lowercase(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

size_t editDistance(std::string_view a, std::string_view b)
{
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

// Keys and values quoted in messages come from the file and may hold control characters; an
// error must stay one line.
std::string oneLine(std::string text)
{
    std::replace_if(text.begin(), text.end(), [](unsigned char c) { return c < 0x20; }, ' ');
    return text;
}

/// "a, b or c".
std::string joinChoices(const std::vector<std::string_view>& words)
{
    std::string out;
    for (size_t i = 0; i < words.size(); ++i) {
        if (i > 0) out += i + 1 == words.size() ? " or " : ", ";
        out += words[i];
    }
    return out;
}

/// One JSON object of the file: knows where it is ("lights[2]") so that every error names the
/// file and the exact value, and rejects keys the schema does not list, which catches typos
/// that would otherwise be silently ignored.
class Object {
public:
    Object(const fs::path& file, const Json& json, std::string where, std::vector<std::string_view> keys)
        : mFile(file), mJson(json), mWhere(std::move(where))
    {
        if (!json.is_object()) fail(mWhere.empty() ? "the file must contain a JSON object" : mWhere + " must be an object");
        for (const auto& [key, value] : json.items()) {
            if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
            std::string message = fmt::format("unknown key '{}'", key);
            if (!mWhere.empty()) message += " in " + mWhere;
            // A near miss is almost always a typo of a known key.
            const auto closest = std::min_element(keys.begin(), keys.end(), [&](auto a, auto b) {
                return editDistance(key, a) < editDistance(key, b);
            });
            // At most 2 edits, fewer for short keys, where any suggestion would be a guess.
            const size_t allowed = std::clamp<size_t>(key.size() / 3, 1, 2);
            if (closest != keys.end() && editDistance(key, *closest) <= allowed)
                message += fmt::format(" (did you mean '{}'?)", *closest);
            fail(message);
        }
    }

    [[noreturn]] void fail(const std::string& message) const { throw Error("{}: {}", mFile.string(), oneLine(message)); }
    /// "lights[2].intensity", or "render" for a top-level key.
    std::string path(std::string_view key) const { return mWhere.empty() ? std::string(key) : mWhere + "." + std::string(key); }
    [[noreturn]] void fail(std::string_view key, const std::string& message) const { fail(path(key) + " " + message); }

    /// "lights[2]"; empty for the top level.
    const std::string& where() const { return mWhere; }
    bool has(std::string_view key) const { return mJson.contains(key); }
    const Json& at(std::string_view key) const { return mJson.at(std::string(key)); }

    std::optional<float> number(std::string_view key) const
    {
        if (!has(key)) return std::nullopt;
        if (!at(key).is_number()) fail(key, "must be a number");
        const float value = at(key).get<float>();
        if (!std::isfinite(value)) fail(key, "is out of range");
        return value;
    }
    float number(std::string_view key, float fallback) const { return number(key).value_or(fallback); }
    /// A number ≥ 0 (`strictly`: > 0).
    std::optional<float> nonNegative(std::string_view key, bool strictly = false) const
    {
        const auto value = number(key);
        if (value && strictly && !(*value > 0.0f)) fail(key, "must be positive");
        if (value && !(*value >= 0.0f)) fail(key, "must not be negative");
        return value;
    }
    std::optional<float> unitInterval(std::string_view key) const
    {
        const auto value = number(key);
        if (value && !(*value >= 0.0f && *value <= 1.0f)) fail(key, "must be between 0 and 1");
        return value;
    }
    std::optional<int> integer(std::string_view key, int min, int max) const
    {
        if (!has(key)) return std::nullopt;
        const Json& value = at(key);
        if (!value.is_number_integer()) fail(key, "must be an integer");
        // Unsigned beyond int64 cannot be in range; everything else compares as int64.
        const bool huge = value.is_number_unsigned() && value.get<uint64_t>() > uint64_t(INT64_MAX);
        if (huge || value.get<int64_t>() < min || value.get<int64_t>() > max)
            fail(key, fmt::format("must be between {} and {}", min, max));
        return value.get<int>();
    }
    std::optional<bool> boolean(std::string_view key) const
    {
        if (!has(key)) return std::nullopt;
        if (!at(key).is_boolean()) fail(key, "must be true or false");
        return at(key).get<bool>();
    }
    std::optional<std::string> string(std::string_view key) const
    {
        if (!has(key)) return std::nullopt;
        if (!at(key).is_string()) fail(key, "must be a string");
        return at(key).get<std::string>();
    }
    /// One of `choices`; the error lists them.
    std::optional<std::string> choice(std::string_view key, const std::vector<std::string_view>& choices) const
    {
        const auto value = string(key);
        if (value && std::find(choices.begin(), choices.end(), *value) == choices.end())
            fail(key, fmt::format("must be {} (got '{}')", joinChoices(choices), *value));
        return value;
    }
    /// An array of `sizes` numbers (one of them); empty when absent.
    std::vector<float> numbers(std::string_view key, std::initializer_list<size_t> sizes) const
    {
        if (!has(key)) return {};
        const Json& value = at(key);
        const bool sized = value.is_array() && std::find(sizes.begin(), sizes.end(), value.size()) != sizes.end();
        if (!sized || !std::all_of(value.begin(), value.end(), [](const Json& v) { return v.is_number(); })) {
            std::string counts;
            for (size_t size : sizes) counts += (counts.empty() ? "" : " or ") + std::to_string(size);
            fail(key, fmt::format("must be an array of {} numbers", counts));
        }
        std::vector<float> out = value.get<std::vector<float>>();
        if (!std::all_of(out.begin(), out.end(), [](float v) { return std::isfinite(v); })) fail(key, "is out of range");
        return out;
    }
    std::optional<glm::vec3> vec3(std::string_view key) const
    {
        const auto v = numbers(key, {3});
        if (v.empty()) return std::nullopt;
        return glm::vec3(v[0], v[1], v[2]);
    }
    /// A non-negative RGB triple (colours and radiances).
    std::optional<glm::vec3> color(std::string_view key) const
    {
        const auto value = vec3(key);
        if (value && glm::any(glm::lessThan(*value, glm::vec3(0.0f)))) fail(key, "must not have negative components");
        return value;
    }
    /// A direction: non-zero, returned normalised.
    std::optional<glm::vec3> direction(std::string_view key) const
    {
        const auto value = vec3(key);
        if (value && !(glm::length(*value) > 1e-6f)) fail(key, "must not be the zero vector");
        return value ? std::optional(glm::normalize(*value)) : std::nullopt;
    }
    /// A nested object, with its own allowed keys.
    std::optional<Object> object(std::string_view key, std::vector<std::string_view> keys) const
    {
        if (!has(key)) return std::nullopt;
        return Object(mFile, at(key), path(key), std::move(keys));
    }
    /// The objects of an array, each with the same allowed keys.
    std::vector<Object> objects(std::string_view key, const std::vector<std::string_view>& keys) const
    {
        std::vector<Object> out;
        if (!has(key)) return out;
        if (!at(key).is_array()) fail(key, "must be an array");
        for (size_t i = 0; i < at(key).size(); ++i)
            out.emplace_back(mFile, at(key)[i], fmt::format("{}[{}]", path(key), i), keys);
        return out;
    }
    /// The members of an object whose keys are names (not a fixed set), each an object with `keys`.
    std::vector<std::pair<std::string, Object>> members(std::string_view key, const std::vector<std::string_view>& keys) const
    {
        std::vector<std::pair<std::string, Object>> out;
        if (!has(key)) return out;
        if (!at(key).is_object()) fail(key, "must be an object");
        for (const auto& [name, value] : at(key).items())
            out.emplace_back(name, Object(mFile, value, fmt::format("{}.{}", path(key), name), keys));
        return out;
    }
    /// Rejects `key` where it has no meaning (a cone angle on a point light).
    void onlyFor(std::string_view key, bool applies, std::string_view what) const
    {
        if (!applies && has(key)) fail(key, fmt::format("only applies to {}", what));
    }
    void notBoth(std::string_view a, std::string_view b) const
    {
        if (has(a) && has(b)) fail(fmt::format("{} has both '{}' and '{}'; give one", mWhere.empty() ? "the file" : mWhere, a, b));
    }
    void required(std::string_view key) const
    {
        if (!has(key)) fail(fmt::format("{} needs '{}'", mWhere, key));
    }

private:
    const fs::path& mFile;
    const Json& mJson;
    std::string mWhere;
};

/// Rotation taking local −Z to `forward` and local +Y as close to `up` as possible: the glTF
/// convention for cameras and lights. Looking along `up` itself, the screen's up becomes the
/// direction a view tilting over the pole would have: −Z looking down, +Z looking up (for +Y up),
/// which keeps +X as the right-hand side.
glm::quat lookRotation(glm::vec3 forward, glm::vec3 up)
{
    forward = glm::normalize(forward);
    up = glm::normalize(up);
    glm::vec3 right = glm::cross(forward, up);
    // sin of the angle between them below 1e-4 rad: the cross product is mostly rounding error.
    if (glm::length(right) < 1e-4f) {
        const glm::vec3 axis = std::abs(up.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
        const glm::vec3 perpendicular = glm::normalize(axis - glm::dot(axis, up) * up);
        right = glm::cross(forward, glm::dot(forward, up) > 0.0f ? perpendicular : -perpendicular);
    }
    right = glm::normalize(right);
    const glm::vec3 trueUp = glm::cross(right, forward);
    return glm::normalize(glm::quat_cast(glm::mat3(right, trueUp, -forward)));
}

glm::mat4 parseTransform(const Object& object)
{
    object.notBoth("rotation", "rotationDegrees");
    const glm::vec3 translation = object.vec3("translation").value_or(glm::vec3(0.0f));
    glm::quat rotation(1.0f, 0.0f, 0.0f, 0.0f);
    if (const auto q = object.numbers("rotation", {4}); !q.empty()) {
        rotation = glm::quat(q[3], q[0], q[1], q[2]); // the file gives [x, y, z, w], as glTF does
        if (!(glm::length(rotation) > 1e-6f)) object.fail("rotation", "must be a non-zero quaternion [x, y, z, w]");
        rotation = glm::normalize(rotation);
    }
    if (const auto degrees = object.vec3("rotationDegrees")) {
        // About the fixed X axis first, then Y, then Z (Blender's XYZ Euler order).
        const glm::vec3 r = glm::radians(*degrees);
        rotation = glm::angleAxis(r.z, glm::vec3(0, 0, 1)) * glm::angleAxis(r.y, glm::vec3(0, 1, 0)) *
                   glm::angleAxis(r.x, glm::vec3(1, 0, 0));
    }
    glm::vec3 scale(1.0f);
    if (object.has("scale")) {
        if (object.at("scale").is_number()) {
            scale = glm::vec3(*object.number("scale"));
        } else if (object.at("scale").is_array() && object.at("scale").size() == 3) {
            scale = *object.vec3("scale");
        } else {
            object.fail("scale", "must be a number or an array of 3 numbers");
        }
        // A zero scale collapses the object and makes its normals undefined.
        if (glm::any(glm::equal(scale, glm::vec3(0.0f)))) object.fail("scale", "must not be zero");
    }
    return glm::translate(glm::mat4(1.0f), translation) * glm::toMat4(rotation) * glm::scale(glm::mat4(1.0f), scale);
}

const std::vector<std::string_view> kTransformKeys = {"translation", "rotation", "rotationDegrees", "scale"};

std::vector<std::string_view> withTransform(std::vector<std::string_view> keys)
{
    keys.insert(keys.end(), kTransformKeys.begin(), kTransformKeys.end());
    return keys;
}

Material defaultShapeMaterial(const std::string& name)
{
    Material material;
    material.name = name;
    // A white dielectric: glTF's default (metallic 1) would be a rough metal, rarely what a test
    // or demo shape wants.
    material.metallicFactor = 0.0f;
    material.roughnessFactor = 0.5f;
    return material;
}

/// The keys of a material object; a model's material overrides take all but "name".
const std::vector<std::string_view> kMaterialKeys = {"name", "baseColor", "metallic", "roughness", "emissive",
                                                     "emissiveStrength", "doubleSided", "alphaMode", "alphaCutoff",
                                                     "shading", "brdfD", "brdfG", "brdfF", "brdfDiffuse", "ior",
                                                     "shininess", "sectorLight"};

/// Sets the material's fields that `object` gives; the others keep their values (a shape's
/// defaults, or a glTF model's material with its textures).
void applyMaterialKeys(const Object& object, Material& material)
{
    if (const auto base = object.numbers("baseColor", {3, 4}); !base.empty()) {
        if (std::any_of(base.begin(), base.end(), [](float v) { return !(v >= 0.0f && v <= 1.0f); }))
            object.fail("baseColor", "components must be between 0 and 1");
        material.baseColorFactor = glm::vec4(base[0], base[1], base[2], base.size() == 4 ? base[3] : 1.0f);
    }
    material.metallicFactor = object.unitInterval("metallic").value_or(material.metallicFactor);
    material.roughnessFactor = object.unitInterval("roughness").value_or(material.roughnessFactor);
    material.emissiveFactor = object.color("emissive").value_or(material.emissiveFactor);
    material.emissiveStrength = object.nonNegative("emissiveStrength").value_or(material.emissiveStrength);
    material.doubleSided = object.boolean("doubleSided").value_or(material.doubleSided);
    if (const auto alphaMode = object.choice("alphaMode", {"opaque", "mask", "blend"}))
        material.alphaMode = *alphaMode == "mask" ? AlphaMode::Mask : *alphaMode == "blend" ? AlphaMode::Blend : AlphaMode::Opaque;
    object.onlyFor("alphaCutoff", material.alphaMode == AlphaMode::Mask, "alphaMode \"mask\"");
    material.alphaCutoff = object.nonNegative("alphaCutoff").value_or(material.alphaCutoff);
    // Material system (docs/scene-format.md): shading model, BRDF terms, F0 from an IOR, Phong exponent.
    if (const auto v = object.choice("shading", {"pbr", "unlit", "flat", "gouraud", "phong", "blinn-phong", "doom"}))
        material.shading.model = parseShadingModel(*v);
    if (const auto v = object.choice("brdfD", {"ggx", "beckmann", "blinn-phong"})) material.shading.distribution = parseBrdfDistribution(*v);
    if (const auto v = object.choice("brdfG", {"smith-ggx", "smith-ggx-correlated", "schlick-ggx", "neumann", "kelemen",
                                               "cook-torrance", "implicit"}))
        material.shading.geometry = parseBrdfGeometryName(*v);
    if (const auto v = object.choice("brdfF", {"schlick", "schlick-sg", "none"})) material.shading.fresnel = parseBrdfFresnel(*v);
    if (const auto v = object.choice("brdfDiffuse", {"lambert", "oren-nayar", "burley"})) material.shading.diffuse = parseBrdfDiffuse(*v);
    if (const auto ior = object.number("ior")) {
        if (!(*ior >= 1.0f)) object.fail("ior", "must be at least 1");
        material.ior = *ior;
    }
    material.shininess = object.nonNegative("shininess").value_or(material.shininess);
    material.sectorLight = object.integer("sectorLight", 0, 255).value_or(material.sectorLight);
}

Material parseMaterial(const Object& object, const std::string& name)
{
    Material material = defaultShapeMaterial(object.string("name").value_or(name));
    applyMaterialKeys(object, material);
    return material;
}

/// A model's "materials": {"<material name>" | "#<index>" | "*": {material keys but "name"}}.
/// "*" applies to every material of the model first, then each named one; a name the model
/// does not have is an error that lists the names it has.
void applyModelMaterials(const Object& object, Scene& model)
{
    const std::vector<std::string_view> keys(kMaterialKeys.begin() + 1, kMaterialKeys.end());
    const auto overrides = object.members("materials", keys);
    for (const auto& [name, material] : overrides)
        if (name == "*")
            for (Material& target : model.materials) applyMaterialKeys(material, target);
    for (const auto& [name, material] : overrides) {
        if (name == "*") continue;
        int index = -1;
        if (name.size() > 1 && name[0] == '#' && std::all_of(name.begin() + 1, name.end(), [](unsigned char c) { return std::isdigit(c) != 0; })) {
            index = std::atoi(name.c_str() + 1);
            if (index >= int(model.materials.size()))
                object.fail("materials", fmt::format("has '{}', but the model has {} materials", name, model.materials.size()));
        } else {
            const auto it = std::find_if(model.materials.begin(), model.materials.end(),
                                         [&](const Material& m) { return m.name == name; });
            if (it == model.materials.end()) {
                std::string names;
                for (size_t i = 0; i < model.materials.size(); ++i)
                    names += fmt::format("{}'{}'", i ? ", " : "", model.materials[i].name.empty() ? fmt::format("#{}", i) : model.materials[i].name);
                object.fail("materials", fmt::format("has '{}', but the model's materials are {}", name,
                                                     names.empty() ? "none" : names));
            }
            index = int(it - model.materials.begin());
        }
        applyMaterialKeys(material, model.materials[size_t(index)]);
    }
}

void parseShape(const Object& object, Scene& scene, size_t index)
{
    object.required("type");
    const std::string type = *object.choice("type", {"sphere", "cube", "plane"});
    const bool sphere = type == "sphere", cube = type == "cube", plane = type == "plane";
    object.onlyFor("radius", sphere, "spheres");
    object.onlyFor("segments", sphere, "spheres");
    object.onlyFor("rings", sphere, "spheres");
    object.onlyFor("halfExtent", cube, "cubes");
    object.onlyFor("size", plane, "planes");
    object.onlyFor("uvRepeat", plane, "planes");

    Primitive primitive;
    if (sphere) {
        const int segments = object.integer("segments", 3, 4096).value_or(64);
        // Rings default to segments / 2: the same angular step around and from pole to pole.
        const int rings = object.integer("rings", 2, 4096).value_or(std::max(2, segments / 2));
        primitive = makeUvSphere(object.nonNegative("radius", true).value_or(1.0f), segments, rings);
    } else if (cube) {
        primitive = makeCube(object.nonNegative("halfExtent", true).value_or(1.0f));
    } else {
        primitive = makePlane(object.nonNegative("size", true).value_or(1.0f),
                              object.nonNegative("uvRepeat", true).value_or(1.0f));
    }
    const std::string name = object.string("name").value_or(fmt::format("{}{}", type, index));
    Material material = defaultShapeMaterial(name);
    if (const auto materialObject = object.object("material", kMaterialKeys))
        material = parseMaterial(*materialObject, name);
    addShape(scene, std::move(primitive), material, parseTransform(object), name);
}

void parseModel(const Object& object, Scene& scene, const fs::path& directory)
{
    object.required("path");
    const std::string file = *object.string("path");
    if (file.empty()) object.fail("path", "must not be empty");
    const fs::path path = fs::path(file).is_absolute() ? fs::path(file) : directory / file;
    const glm::mat4 transform = parseTransform(object);
    Scene model;
    try {
        model = loadGltf(path);
    } catch (const Error& e) {
        // loadGltf names the model file; this adds which entry of the scene file asked for it.
        object.fail(object.where() + ": " + e.what());
    }
    if (const auto name = object.string("name")) model.name = *name;
    applyModelMaterials(object, model);
    scene.append(std::move(model), transform);
}

void parseLight(const Object& object, Scene& scene, size_t index)
{
    object.required("type");
    const std::string type = *object.choice("type", {"point", "spot", "directional"});
    Light light;
    light.type = type == "point" ? Light::Type::Point : type == "spot" ? Light::Type::Spot : Light::Type::Directional;
    const bool point = light.type == Light::Type::Point, spot = light.type == Light::Type::Spot;
    light.name = object.string("name").value_or(fmt::format("light{}", index));

    object.onlyFor("direction", !point, "spot and directional lights");
    object.onlyFor("target", !point, "spot and directional lights");
    object.onlyFor("range", point || spot, "point and spot lights");
    object.onlyFor("innerConeAngle", spot, "spot lights");
    object.onlyFor("outerConeAngle", spot, "spot lights");
    // A directional light has no position in the lighting; it may have one for gizmos.
    if (point || spot) object.required("position");
    object.notBoth("direction", "target");
    if (!point && !object.has("direction") && !object.has("target"))
        object.fail(fmt::format("{} needs 'direction' or 'target'", object.where()));

    light.color = object.color("color").value_or(light.color);
    light.intensity = object.nonNegative("intensity").value_or(light.intensity);
    light.range = object.nonNegative("range", true).value_or(0.0f);
    if (spot) {
        const float inner = object.number("innerConeAngle", 0.0f);
        const float outer = object.number("outerConeAngle", 45.0f);
        // KHR_lights_punctual's limits; inner < outer also keeps the falloff's division finite.
        if (!(outer > 0.0f && outer <= 90.0f)) object.fail("outerConeAngle", "must be in (0, 90] degrees");
        if (!(inner >= 0.0f && inner < outer)) object.fail("innerConeAngle", "must be at least 0 and less than outerConeAngle");
        light.innerConeAngle = glm::radians(inner);
        light.outerConeAngle = glm::radians(outer);
    }

    Node node;
    node.name = light.name;
    node.translation = object.vec3("position").value_or(glm::vec3(0.0f));
    if (!point) {
        glm::vec3 direction;
        if (const auto target = object.vec3("target")) {
            if (!(glm::length(*target - node.translation) > 1e-6f)) object.fail("target", "must differ from position");
            direction = glm::normalize(*target - node.translation);
        } else {
            direction = *object.direction("direction");
        }
        node.rotation = lookRotation(direction, glm::vec3(0, 1, 0));
    }
    scene.lights.push_back(light);
    node.light = int(scene.lights.size() - 1);
    scene.addNode(std::move(node));
}

void parseCamera(const Object& object, Scene& scene)
{
    const std::string type = object.choice("type", {"perspective", "orthographic"}).value_or("perspective");
    Camera camera;
    camera.type = type == "orthographic" ? Camera::Type::Orthographic : Camera::Type::Perspective;
    const bool perspective = camera.type == Camera::Type::Perspective;
    camera.name = object.string("name").value_or("camera");
    object.required("position");
    object.notBoth("direction", "target");
    object.onlyFor("yfov", perspective, "perspective cameras");
    object.onlyFor("aspectRatio", perspective, "perspective cameras");
    object.onlyFor("xmag", !perspective, "orthographic cameras");
    object.onlyFor("ymag", !perspective, "orthographic cameras");

    if (perspective) {
        const float yfov = object.number("yfov", 45.0f);
        if (!(yfov > 0.0f && yfov < 180.0f)) object.fail("yfov", "must be between 0 and 180 degrees");
        camera.yfov = glm::radians(yfov);
        camera.aspectRatio = object.nonNegative("aspectRatio", true).value_or(0.0f);
        camera.znear = object.nonNegative("znear", true).value_or(camera.znear);
    } else {
        object.required("xmag");
        object.required("ymag");
        camera.xmag = *object.nonNegative("xmag", true);
        camera.ymag = *object.nonNegative("ymag", true);
        camera.znear = object.nonNegative("znear").value_or(camera.znear);
    }
    camera.zfar = object.number("zfar", std::max(camera.zfar, camera.znear * 2.0f));
    if (!(camera.zfar > camera.znear)) object.fail("zfar", "must be greater than znear");

    Node node;
    node.name = camera.name;
    node.translation = *object.vec3("position");
    glm::vec3 forward(0, 0, -1);
    if (const auto target = object.vec3("target")) {
        if (!(glm::length(*target - node.translation) > 1e-6f)) object.fail("target", "must differ from position");
        forward = glm::normalize(*target - node.translation);
    } else if (const auto direction = object.direction("direction")) {
        forward = *direction;
    }
    const glm::vec3 up = object.direction("up").value_or(glm::vec3(0, 1, 0));
    node.rotation = lookRotation(forward, up);
    scene.cameras.push_back(camera);
    node.camera = int(scene.cameras.size() - 1);
    const int index = scene.addNode(std::move(node));
    // Scene::cameraInstances() walks the roots in order; the file's camera must come first, ahead
    // of any camera inside a model.
    scene.roots.erase(std::find(scene.roots.begin(), scene.roots.end(), index));
    scene.roots.insert(scene.roots.begin(), index);
}

const std::vector<std::string_view> kBillboardKeys = {"position", "scale", "tint", "axis"};

/// A billboard group: its own sprite, kind, size and alpha mode, and billboards given one by one
/// ("position", "billboards") and/or scattered at random in a box ("scatter").
void parseBillboardGroup(const Object& object, Scene& scene, const fs::path& directory, size_t index)
{
    BillboardGroup group;
    group.name = object.string("name").value_or(fmt::format("billboards{}", index));
    const std::string kind = object.choice("kind", {"point-sprite", "axis-aligned", "arbitrary-axis"}).value_or("point-sprite");
    group.kind = kind == "axis-aligned"     ? BillboardKind::AxisAligned
               : kind == "arbitrary-axis"   ? BillboardKind::ArbitraryAxis
                                            : BillboardKind::PointSprite;
    const bool arbitrary = group.kind == BillboardKind::ArbitraryAxis;

    object.notBoth("sprite", "image");
    const std::string sprite = object.choice("sprite", {"disc", "tree", "bar"}).value_or("disc");
    group.sprite = sprite == "tree" ? BuiltinSprite::Tree : sprite == "bar" ? BuiltinSprite::Bar : BuiltinSprite::Disc;
    if (const auto file = object.string("image")) {
        if (file->empty()) object.fail("image", "must not be empty");
        const fs::path path = fs::path(*file).is_absolute() ? fs::path(*file) : directory / *file;
        ImageRGBA8 decoded;
        try {
            decoded = readPng(path);
        } catch (const Error& e) {
            object.fail(object.path("image") + ": " + e.what());
        }
        Image image;
        image.name = path.filename().string();
        image.width = decoded.width;
        image.height = decoded.height;
        image.pixels = std::move(decoded.pixels);
        scene.images.push_back(std::move(image));
        group.image = int(scene.images.size() - 1);
    }

    if (object.has("size")) {
        if (object.at("size").is_number()) {
            group.size = glm::vec2(*object.number("size"));
        } else {
            const auto size = object.numbers("size", {2});
            group.size = {size[0], size[1]};
        }
        if (!(group.size.x > 0.0f && group.size.y > 0.0f)) object.fail("size", "must be positive");
    }
    group.sizeInPixels = object.boolean("sizeInPixels").value_or(false);
    if (const auto anchor = object.numbers("anchor", {2}); !anchor.empty()) {
        group.anchor = {anchor[0], anchor[1]};
        if (!(glm::all(glm::greaterThanEqual(group.anchor, glm::vec2(0.0f))) && glm::all(glm::lessThanEqual(group.anchor, glm::vec2(1.0f)))))
            object.fail("anchor", "must be between 0 and 1 in both coordinates");
    }
    group.tint = object.color("tint").value_or(group.tint);
    const std::string alphaMode = object.choice("alphaMode", {"opaque", "mask", "blend"}).value_or("mask");
    group.alphaMode = alphaMode == "opaque" ? AlphaMode::Opaque : alphaMode == "blend" ? AlphaMode::Blend : AlphaMode::Mask;
    object.onlyFor("alphaCutoff", group.alphaMode == AlphaMode::Mask, "alphaMode \"mask\"");
    group.alphaCutoff = object.unitInterval("alphaCutoff").value_or(group.alphaCutoff);
    group.sectorLight = object.integer("sectorLight", 0, 255).value_or(group.sectorLight);
    // The group's axis is each billboard's default; a billboard may give its own.
    object.onlyFor("axis", arbitrary, "arbitrary-axis billboards");
    const glm::vec3 axis = object.direction("axis").value_or(glm::vec3(0.0f, 1.0f, 0.0f));

    if (!object.has("position") && !object.has("billboards") && !object.has("scatter"))
        object.fail(fmt::format("{} needs 'position', 'billboards' or 'scatter'", object.where()));
    if (const auto position = object.vec3("position")) group.billboards.push_back({*position, 1.0f, glm::vec3(1.0f), axis});
    for (const Object& entry : object.objects("billboards", kBillboardKeys)) {
        entry.required("position");
        entry.onlyFor("axis", arbitrary, "arbitrary-axis billboards");
        Billboard b;
        b.position = *entry.vec3("position");
        b.scale = entry.nonNegative("scale", true).value_or(1.0f);
        b.tint = entry.color("tint").value_or(glm::vec3(1.0f));
        b.axis = entry.direction("axis").value_or(axis);
        group.billboards.push_back(b);
    }
    if (const auto scatter = object.object("scatter", {"count", "min", "max", "scale", "seed"})) {
        scatter->required("count");
        scatter->required("min");
        scatter->required("max");
        const int count = *scatter->integer("count", 1, 1000000);
        const glm::vec3 lo = *scatter->vec3("min"), hi = *scatter->vec3("max");
        if (!glm::all(glm::lessThanEqual(lo, hi))) scatter->fail("max", "must not be below min in any coordinate");
        glm::vec2 scale(1.0f);
        if (scatter->has("scale")) {
            if (scatter->at("scale").is_number()) {
                scale = glm::vec2(*scatter->number("scale"));
            } else {
                const auto range = scatter->numbers("scale", {2});
                scale = {range[0], range[1]};
            }
            if (!(scale.x > 0.0f && scale.y >= scale.x)) scatter->fail("scale", "must be positive, [smallest, largest]");
        }
        // mt19937's output sequence is fixed by the C++ standard (unlike the distributions), so
        // a seed gives the same field on every platform; 24 bits make a float in [0, 1).
        std::mt19937 random(uint32_t(scatter->integer("seed", 0, INT32_MAX).value_or(0)));
        auto uniform = [&] { return float(random() >> 8) * (1.0f / 16777216.0f); };
        for (int i = 0; i < count; ++i) {
            Billboard b;
            b.position = lo + (hi - lo) * glm::vec3(uniform(), uniform(), uniform());
            b.scale = glm::mix(scale.x, scale.y, uniform());
            b.axis = axis;
            group.billboards.push_back(b);
        }
    }
    scene.billboards.push_back(std::move(group));
}

EnvironmentSettings parseEnvironment(const Object& object, const fs::path& directory)
{
    EnvironmentSettings environment;
    object.notBoth("color", "file");
    environment.color = object.color("color");
    if (const auto file = object.string("file")) {
        if (file->empty()) object.fail("file", "must not be empty");
        const fs::path path = fs::path(*file).is_absolute() ? fs::path(*file) : directory / *file;
        const std::string extension = lowercase(path.extension().string());
        if (extension != ".hdr" && extension != ".exr") object.fail("file", "must be a .hdr or .exr image");
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) object.fail(fmt::format("{}: {}: no such file", object.path("file"), path.string()));
        environment.file = path.string();
    }
    environment.intensity = object.nonNegative("intensity").value_or(environment.intensity);
    environment.rotationDegrees = object.number("rotation", environment.rotationDegrees);
    return environment;
}

RenderSettings parseRender(const Object& object)
{
    RenderSettings render;
    render.width = object.integer("width", 1, 16384);
    render.height = object.integer("height", 1, 16384);
    render.msaa = object.integer("msaa", 1, 8);
    if (render.msaa && (*render.msaa & (*render.msaa - 1)) != 0) object.fail("msaa", "must be 1, 2, 4 or 8");
    render.exposure = object.number("exposure");
    render.tonemap = object.choice("tonemap", {"none", "reinhard", "reinhard-ext", "aces", "neutral", "agx"});
    render.brdfG = object.choice("brdfG", {"smith-ggx", "smith-ggx-correlated", "schlick-ggx", "neumann", "kelemen", "cook-torrance", "implicit"});
    render.shading = object.choice("shading", {"pbr", "unlit", "flat", "gouraud", "phong", "blinn-phong", "doom"});
    render.defaultLights = object.boolean("defaultLights");
    render.ev100 = object.number("ev100");
    return render;
}

/// A physical camera's exposure settings: all three or none.
std::optional<RenderSettings::CameraExposure> parseCameraExposure(const Object& object)
{
    const char* keys[] = {"aperture", "shutter", "iso"};
    const int given = int(std::count_if(std::begin(keys), std::end(keys), [&](const char* key) { return object.has(key); }));
    if (given == 0) return std::nullopt;
    if (given != 3) object.fail(fmt::format("{} needs 'aperture', 'shutter' and 'iso' together", object.where()));
    return RenderSettings::CameraExposure{*object.nonNegative("aperture", true), *object.nonNegative("shutter", true),
                                          *object.nonNegative("iso", true)};
}

/// One pass of "post" by its table (settings/PassSettings.h): `true`/`false`, or an object of
/// the table's fields (enabled unless it says "enabled": false). Fields are checked in the
/// table's order, an order between two fields (minEv100 < maxEv100) once both are read.
template <typename T>
void parsePass(const Object& post, const SettingsTable<T>& table, SettingsOverride<T>& out)
{
    const std::string_view key = table.key;
    if (!post.has(key)) return;
    if (post.at(key).is_boolean()) {
        out.set(&T::enabled, *post.boolean(key));
        return;
    }
    if (!post.at(key).is_object()) post.fail(key, "must be true, false or an object");
    std::vector<std::string_view> keys;
    for (const SettingField<T>& field : table.fields)
        if (std::string_view(field.name) != "enabled") keys.emplace_back(field.name);
    keys.emplace_back("enabled");
    const Object settings = *post.object(key, std::move(keys));
    out.set(&T::enabled, settings.boolean("enabled").value_or(true));
    const T& defaults = settingDefaults<T>();
    for (const SettingField<T>& field : table.fields) {
        if (std::string_view(field.name) == "enabled") continue;
        const SettingRange& range = field.range;
        std::visit(
            [&](auto member) {
                using V = SettingValue<decltype(member)>;
                std::optional<V> value;
                if constexpr (std::is_same_v<V, bool>) {
                    value = settings.boolean(field.name);
                } else if constexpr (std::is_same_v<V, int>) {
                    // A bounded range in Object::integer's words; any other checked after.
                    const bool bounded = range.bounded();
                    value = settings.integer(field.name, bounded ? int(range.min) : INT_MIN, bounded ? int(range.max) : INT_MAX);
                    if (value && !range.contains(*value)) settings.fail(field.name, range.requirement());
                } else {
                    value = settings.number(field.name);
                    if (value && !range.contains(*value)) settings.fail(field.name, range.requirement());
                }
                if (value) out.set(member, *value);
            },
            field.member);
        for (const SettingOrder<T>& order : table.orders) {
            const SettingField<T>* lower = table.find(order.lower);
            const SettingField<T>* upper = table.find(order.upper);
            if (std::max(lower, upper) != &field) continue;
            // The file's values over the defaults: one end given alone is judged against the other's default.
            T given = defaults;
            out.applyTo(given);
            if (lower->value(given) >= upper->value(given))
                settings.fail(lower->name, fmt::format("must be less than {} (defaults {} and {})", upper->name,
                                                       formatSetting(lower->kind(), lower->value(defaults)),
                                                       formatSetting(upper->kind(), upper->value(defaults))));
        }
    }
}

/// "post": each pass by its table.
PostOverrides parsePost(const Object& object)
{
    PostOverrides post;
    forEachPass([&](auto& pass) { parsePass(object, settingsTable<typename std::decay_t<decltype(pass)>::Settings>(), pass); }, post);
    return post;
}

/// nlohmann reports a byte offset; people want "file:line:column".
std::string describeParseError(const fs::path& file, const std::string& text, const Json::parse_error& e)
{
    const size_t end = std::min(e.byte == 0 ? 0 : e.byte - 1, text.size());
    size_t line = 1, lineStart = 0;
    for (size_t i = 0; i < end; ++i)
        if (text[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    // what() reads "[json.exception.parse_error.101] parse error at line 3, column 5: <reason>".
    std::string reason = e.what();
    if (const size_t at = reason.find(": ", reason.find("parse error")); at != std::string::npos) reason.erase(0, at + 2);
    std::replace(reason.begin(), reason.end(), '\n', ' ');
    return fmt::format("{}:{}:{}: {}", file.string(), line, end - lineStart + 1, reason);
}

Json parseJson(const fs::path& file, const std::string& text)
{
    // nlohmann keeps the last of two equal keys; a duplicate is almost always a mistake.
    std::vector<std::set<std::string>> keys;
    const auto callback = [&](int, Json::parse_event_t event, Json& parsed) {
        if (event == Json::parse_event_t::object_start) keys.emplace_back();
        if (event == Json::parse_event_t::object_end) keys.pop_back();
        if (event == Json::parse_event_t::key && !keys.back().insert(parsed.get<std::string>()).second)
            throw Error("{}: duplicate key '{}'", file.string(), oneLine(parsed.get<std::string>()));
        return true;
    };
    try {
        // Comments are allowed: scene files are written by hand.
        return Json::parse(text, callback, true, true);
    } catch (const Json::parse_error& e) {
        throw Error(describeParseError(file, text, e));
    } catch (const Json::exception& e) {
        // Other nlohmann errors (a number too large for a double) carry no position.
        std::string reason = e.what();
        if (const size_t at = reason.find("] "); at != std::string::npos) reason.erase(0, at + 2);
        throw Error("{}: {}", file.string(), reason);
    }
}

void checkIsFile(const fs::path& path)
{
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error("{}: no such file", path.string());
    if (fs::is_directory(path, ec)) throw Error("{}: is a directory, not a scene file", path.string());
}

} // namespace

SceneDocument loadScene(const fs::path& path)
{
    checkIsFile(path);
    const std::string extension = lowercase(path.extension().string());
    if (extension == ".gltf" || extension == ".glb") {
        SceneDocument document;
        document.scene = loadGltf(path);
        document.source = path;
        return document;
    }
    if (extension == ".json") return loadSceneFile(path);
    throw Error("{}: unknown scene format (use .gltf, .glb or .json)", path.string());
}

SceneDocument loadSceneFile(const fs::path& path)
{
    checkIsFile(path);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("{}: cannot read: {}", path.string(), std::generic_category().message(errno));
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw Error("{}: cannot read: {}", path.string(), std::generic_category().message(errno));

    const Json json = parseJson(path, text);
    const Object root(path, json, "", {"models", "shapes", "lights", "billboards", "camera", "environment", "render", "post"});
    const fs::path directory = path.parent_path();

    SceneDocument document;
    document.source = path;
    Scene& scene = document.scene;
    scene.name = path.stem().string();

    for (const Object& model : root.objects("models", withTransform({"path", "name", "materials"}))) parseModel(model, scene, directory);
    const auto shapes = root.objects("shapes", withTransform({"type", "name", "radius", "segments", "rings", "halfExtent",
                                                              "size", "uvRepeat", "material"}));
    for (size_t i = 0; i < shapes.size(); ++i) parseShape(shapes[i], scene, i);
    const auto lights = root.objects("lights", {"type", "name", "position", "direction", "target", "color", "intensity",
                                                "range", "innerConeAngle", "outerConeAngle"});
    for (size_t i = 0; i < lights.size(); ++i) parseLight(lights[i], scene, i);
    const auto billboards = root.objects("billboards", {"name", "kind", "sprite", "image", "size", "sizeInPixels", "anchor",
                                                        "tint", "alphaMode", "alphaCutoff", "axis", "sectorLight",
                                                        "position", "billboards", "scatter"});
    for (size_t i = 0; i < billboards.size(); ++i) parseBillboardGroup(billboards[i], scene, directory, i);
    if (const auto camera = root.object("camera", {"type", "name", "position", "target", "direction", "up", "yfov",
                                                   "aspectRatio", "znear", "zfar", "xmag", "ymag", "aperture", "shutter",
                                                   "iso"})) {
        parseCamera(*camera, scene);
        document.render.cameraExposure = parseCameraExposure(*camera);
    }
    if (const auto environment = root.object("environment", {"color", "file", "intensity", "rotation"}))
        document.environment = parseEnvironment(*environment, directory);
    if (const auto render = root.object("render", {"width", "height", "msaa", "exposure", "tonemap", "brdfG", "shading",
                                                   "defaultLights", "ev100"})) {
        const auto cameraExposure = document.render.cameraExposure;
        document.render = parseRender(*render);
        document.render.cameraExposure = cameraExposure;
        if (document.render.ev100 && cameraExposure)
            render->fail("ev100", "and the camera's aperture, shutter and iso both set the exposure; give one");
    }
    std::vector<std::string_view> passes;
    forEachPass([&](auto& pass) { passes.emplace_back(settingsTable<typename std::decay_t<decltype(pass)>::Settings>().key); },
                document.post);
    if (const auto post = root.object("post", passes)) document.post = parsePost(*post);
    return document;
}

} // namespace specula::scene
