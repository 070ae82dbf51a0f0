// Scene files: lights, the camera, billboards, and the environment, render and post sections.
#include <algorithm>
#include <climits>
#include <cstdint>
#include <iterator>
#include <random>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include <glm/gtx/quaternion.hpp>

#include "core/Error.h"
#include "core/ImageIO.h"
#include "scene/SceneFileInternal.h"

namespace specula::scene::scenefile_detail {

namespace {

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

} // namespace

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
    object.onlyFor("radius", point || spot, "point and spot lights");
    object.onlyFor("angularDiameter", !point && !spot, "directional lights");
    light.castShadows = object.boolean("castShadows").value_or(true);
    light.radius = object.nonNegative("radius").value_or(light.radius);
    if (object.has("angularDiameter")) {
        const float degrees = object.number("angularDiameter", 0.53f);
        if (!(degrees >= 0.0f && degrees <= 45.0f)) object.fail("angularDiameter", "must be between 0 and 45 degrees");
        light.angularDiameter = glm::radians(degrees);
    }
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
void parseBillboardGroup(const Object& object, Scene& scene, const Files& files, size_t index)
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
        const fs::path path = files.resolve(object, "image", *file);
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

EnvironmentSettings parseEnvironment(const Object& object, const Files& files)
{
    EnvironmentSettings environment;
    object.notBoth("color", "file");
    environment.color = object.color("color");
    if (const auto file = object.string("file")) {
        if (file->empty()) object.fail("file", "must not be empty");
        const fs::path path = files.resolve(object, "file", *file);
        const std::string extension = lowercase(path.extension().string());
        if (extension != ".hdr" && extension != ".exr") object.fail("file", "must be a .hdr or .exr image");
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) object.fail(fmt::format("{}: {}: no such file", object.path("file"), path.string()));
        environment.file = path.string();
    }
    environment.intensity = object.nonNegative("intensity").value_or(environment.intensity);
    environment.rotationDegrees = object.number("rotation", environment.rotationDegrees);
    environment.ibl = object.choice("ibl", {"split-sum", "importance"});
    environment.sun = object.choice("sun", {"extract", "keep"});
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
    render.transparency = object.choice("transparency", {"sorted", "oit"});
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

namespace {

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

} // namespace

/// "post": each pass by its table.
PostOverrides parsePost(const Object& object)
{
    PostOverrides post;
    forEachPass([&](auto& pass) { parsePass(object, settingsTable<typename std::decay_t<decltype(pass)>::Settings>(), pass); }, post);
    return post;
}

} // namespace specula::scene::scenefile_detail
