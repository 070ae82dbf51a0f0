#include "scene/SceneFile.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <fstream>
#include <iterator>
#include <set>
#include <string_view>
#include <system_error>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "scene/GltfImporter.h"
#include "scene/SceneFileInternal.h"

namespace specula::scene {

namespace scenefile_detail {

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

namespace {

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

fs::path Files::resolve(const Object& object, std::string_view key, const std::string& file) const
{
    if (const auto reason = refuseReference(directory, file, options.allowExternalFiles))
        object.fail(key, fmt::format("'{}' {}: refused{}", file, *reason,
                                     options.allowExternalFiles ? "" : " (--allow-external-files allows files outside it)"));
    return fs::path(file).is_absolute() ? fs::path(file) : directory / file;
}

} // namespace scenefile_detail

// The sections' parsers and the helpers they share (SceneFileInternal.h).
using namespace scenefile_detail;

SceneDocument loadScene(const fs::path& path, const LoadOptions& options)
{
    checkIsFile(path);
    const std::string extension = lowercase(path.extension().string());
    if (extension == ".gltf" || extension == ".glb") {
        SceneDocument document;
        document.scene = loadGltf(path, options);
        document.source = path;
        return document;
    }
    if (extension == ".json") return loadSceneFile(path, options);
    throw Error("{}: unknown scene format (use .gltf, .glb or .json)", path.string());
}

SceneDocument loadSceneFile(const fs::path& path, const LoadOptions& options)
{
    checkIsFile(path);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("{}: cannot read: {}", path.string(), std::generic_category().message(errno));
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw Error("{}: cannot read: {}", path.string(), std::generic_category().message(errno));
    return loadSceneText(text, path, options);
}

SceneDocument loadSceneText(const std::string& text, const fs::path& path, const LoadOptions& options)
{
    const Json json = parseJson(path, text);
    const Object root(path, json, "", {"models", "shapes", "lights", "billboards", "camera", "environment", "render", "post"});
    const Files files{path.parent_path(), options};

    SceneDocument document;
    document.source = path;
    Scene& scene = document.scene;
    scene.name = path.stem().string();

    for (const Object& model : root.objects("models", withTransform({"path", "name", "materials", "castShadows", "receiveShadows"}))) parseModel(model, scene, files);
    const auto shapes = root.objects("shapes", withTransform({"type", "name", "radius", "segments", "rings", "halfExtent",
                                                              "size", "uvRepeat", "material", "castShadows", "receiveShadows"}));
    for (size_t i = 0; i < shapes.size(); ++i) parseShape(shapes[i], scene, i);
    const auto lights = root.objects("lights", {"type", "name", "position", "direction", "target", "color", "intensity",
                                                "range", "innerConeAngle", "outerConeAngle", "castShadows", "radius",
                                                "angularDiameter"});
    for (size_t i = 0; i < lights.size(); ++i) parseLight(lights[i], scene, i);
    const auto billboards = root.objects("billboards", {"name", "kind", "sprite", "image", "size", "sizeInPixels", "anchor",
                                                        "tint", "alphaMode", "alphaCutoff", "axis", "sectorLight",
                                                        "position", "billboards", "scatter"});
    for (size_t i = 0; i < billboards.size(); ++i) parseBillboardGroup(billboards[i], scene, files, i);
    if (const auto camera = root.object("camera", {"type", "name", "position", "target", "direction", "up", "yfov",
                                                   "aspectRatio", "znear", "zfar", "xmag", "ymag", "aperture", "shutter",
                                                   "iso"})) {
        parseCamera(*camera, scene);
        document.render.cameraExposure = parseCameraExposure(*camera);
    }
    if (const auto environment = root.object("environment", {"color", "file", "intensity", "rotation", "ibl", "sun"}))
        document.environment = parseEnvironment(*environment, files);
    if (const auto render = root.object("render", {"width", "height", "msaa", "exposure", "tonemap", "brdfG", "shading",
                                                   "defaultLights", "ev100", "transparency"})) {
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
