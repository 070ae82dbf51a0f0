// Scene files: models and shapes, their transforms and materials, and a model's material overrides.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <string_view>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/quaternion.hpp>

#include "core/Error.h"
#include "scene/GltfImporter.h"
#include "scene/Procedural.h"
#include "scene/SceneFileInternal.h"

namespace specula::scene::scenefile_detail {

namespace {

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

} // namespace

std::vector<std::string_view> withTransform(std::vector<std::string_view> keys)
{
    keys.insert(keys.end(), kTransformKeys.begin(), kTransformKeys.end());
    return keys;
}

namespace {

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
                                                     "emissiveStrength", "doubleSided", "alphaMode", "alphaCutoff", "blendMode",
                                                     "shading", "brdfD", "brdfG", "brdfF", "brdfDiffuse", "ior",
                                                     "shininess", "sectorLight", "transmission", "thickness", "dispersion",
                                                     "attenuationDistance", "attenuationColor", "clearcoat",
                                                     "clearcoatRoughness", "sheenColor", "sheenRoughness",
                                                     "anisotropyStrength", "anisotropyRotation", "iridescence", "iridescenceIor",
                                                     "iridescenceThicknessMinimum", "iridescenceThicknessMaximum",
                                                     "diffuseTransmission", "diffuseTransmissionColor"};

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
    // Blend mode (docs/transparency.md): what a blended surface's alpha scales.
    object.onlyFor("blendMode", material.alphaMode == AlphaMode::Blend, "alphaMode \"blend\"");
    if (const auto blendMode = object.choice("blendMode", {"fade", "transparent"}))
        material.blendMode = *blendMode == "transparent" ? BlendMode::Transparent : BlendMode::Fade;
    // Transmission and volume (KHR_materials_transmission, KHR_materials_volume).
    material.transmissionFactor = object.unitInterval("transmission").value_or(material.transmissionFactor);
    material.thickness = object.nonNegative("thickness").value_or(material.thickness);
    material.dispersion = object.nonNegative("dispersion").value_or(material.dispersion); // KHR_materials_dispersion
    material.attenuationDistance = object.nonNegative("attenuationDistance").value_or(material.attenuationDistance);
    if (const auto color = object.color("attenuationColor")) {
        if (glm::any(glm::greaterThan(*color, glm::vec3(1.0f)))) object.fail("attenuationColor", "must be between 0 and 1");
        material.attenuationColor = *color;
    }
    // KHR_materials_clearcoat's factors (a glTF model's clearcoat textures stay).
    material.clearcoatFactor = object.unitInterval("clearcoat").value_or(material.clearcoatFactor);
    material.clearcoatRoughnessFactor = object.unitInterval("clearcoatRoughness").value_or(material.clearcoatRoughnessFactor);
    // KHR_materials_sheen's factors (a glTF model's sheen textures stay).
    if (const auto color = object.color("sheenColor")) {
        if (glm::any(glm::greaterThan(*color, glm::vec3(1.0f)))) object.fail("sheenColor", "must be between 0 and 1");
        material.sheenColorFactor = *color;
    }
    material.sheenRoughnessFactor = object.unitInterval("sheenRoughness").value_or(material.sheenRoughnessFactor);
    // KHR_materials_anisotropy's factors (a glTF model's anisotropy texture stays).
    material.anisotropyStrength = object.unitInterval("anisotropyStrength").value_or(material.anisotropyStrength);
    material.anisotropyRotation = object.number("anisotropyRotation").value_or(material.anisotropyRotation);
    // KHR_materials_iridescence's factor, film IOR and thickness range (a glTF model's textures stay).
    material.iridescenceFactor = object.unitInterval("iridescence").value_or(material.iridescenceFactor);
    if (const auto ior = object.number("iridescenceIor")) {
        if (!(*ior >= 1.0f)) object.fail("iridescenceIor", "must be at least 1");
        material.iridescenceIor = *ior;
    }
    material.iridescenceThicknessMinimum = object.nonNegative("iridescenceThicknessMinimum").value_or(material.iridescenceThicknessMinimum);
    material.iridescenceThicknessMaximum = object.nonNegative("iridescenceThicknessMaximum").value_or(material.iridescenceThicknessMaximum);
    // KHR_materials_diffuse_transmission's factor and colour (a glTF model's textures stay).
    material.diffuseTransmissionFactor = object.unitInterval("diffuseTransmission").value_or(material.diffuseTransmissionFactor);
    if (const auto color = object.color("diffuseTransmissionColor")) {
        if (glm::any(glm::greaterThan(*color, glm::vec3(1.0f)))) object.fail("diffuseTransmissionColor", "must be between 0 and 1");
        material.diffuseTransmissionColorFactor = *color;
    }
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
                                         [&name = name](const Material& m) { return m.name == name; }); // clang 14: no structured binding captures
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

// castShadows / receiveShadows of a model or shape, on every node it added.
void applyShadowFlags(const Object& object, Scene& scene, size_t firstNode)
{
    const bool cast = object.boolean("castShadows").value_or(true);
    const bool receive = object.boolean("receiveShadows").value_or(true);
    for (size_t i = firstNode; i < scene.nodes.size(); ++i) {
        scene.nodes[i].castShadows = cast;
        scene.nodes[i].receiveShadows = receive;
    }
}

} // namespace

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
    const size_t firstNode = scene.nodes.size();
    addShape(scene, std::move(primitive), material, parseTransform(object), name);
    applyShadowFlags(object, scene, firstNode);
}

void parseModel(const Object& object, Scene& scene, const Files& files)
{
    object.required("path");
    const std::string file = *object.string("path");
    if (file.empty()) object.fail("path", "must not be empty");
    const fs::path path = files.resolve(object, "path", file);
    const glm::mat4 transform = parseTransform(object);
    Scene model;
    try {
        model = loadGltf(path, files.options);
    } catch (const Error& e) {
        // loadGltf names the model file; this adds which entry of the scene file asked for it.
        object.fail(object.where() + ": " + e.what());
    }
    if (const auto name = object.string("name")) model.name = *name;
    applyModelMaterials(object, model);
    const size_t firstNode = scene.nodes.size();
    scene.append(std::move(model), transform);
    applyShadowFlags(object, scene, firstNode);
}

} // namespace specula::scene::scenefile_detail
