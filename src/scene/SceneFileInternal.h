#pragma once
// Private to the JSON scene-file loader, which is split by concern: SceneFile.cpp (reading and
// parsing the file, the top-level keys, loadScene and loadSceneFile), SceneFileModels.cpp
// (models, shapes, transforms, materials and a model's material overrides) and
// SceneFileSections.cpp (lights, the camera, billboards, environment, render and post).
// Not for use elsewhere.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "scene/Scene.h"
#include "scene/SceneFile.h"

namespace specula::scene::scenefile_detail {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// Text helpers (SceneFile.cpp)
std::string lowercase(std::string text);
size_t editDistance(std::string_view a, std::string_view b);
std::string oneLine(std::string text);
std::string joinChoices(const std::vector<std::string_view>& words);

/// One JSON object of the file: knows where it is ("lights[2]") so that every error names the
/// file and the exact value, and rejects keys the schema does not list, which catches typos
/// that would otherwise be silently ignored.
class Object {
public:
    Object(const fs::path& file, const Json& json, std::string where, std::vector<std::string_view> keys)
        : mFile(file), mJson(json), mWhere(std::move(where))
    {
        if (!json.is_object()) fail(mWhere.empty() ? "the file must contain a JSON object" : mWhere + " must be an object");
        for (const auto& item : json.items()) {
            // Not a structured binding: clang 14 (the sanitizer build) cannot capture one in a lambda.
            const std::string& key = item.key();
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

/// The files a scene file names: relative to its directory and inside its tree unless
/// LoadOptions::allowExternalFiles (SceneFile.cpp).
struct Files {
    fs::path directory;
    const LoadOptions& options;
    /// The path `file` (the value of `key` in `object`) names, or a one-line refusal.
    fs::path resolve(const Object& object, std::string_view key, const std::string& file) const;
};

// Models and shapes (SceneFileModels.cpp)
std::vector<std::string_view> withTransform(std::vector<std::string_view> keys);
void parseShape(const Object& object, Scene& scene, size_t index);
void parseModel(const Object& object, Scene& scene, const Files& files);

// Lights, the camera, billboards and the settings sections (SceneFileSections.cpp)
void parseLight(const Object& object, Scene& scene, size_t index);
void parseCamera(const Object& object, Scene& scene);
void parseBillboardGroup(const Object& object, Scene& scene, const Files& files, size_t index);
EnvironmentSettings parseEnvironment(const Object& object, const Files& files);
RenderSettings parseRender(const Object& object);
std::optional<RenderSettings::CameraExposure> parseCameraExposure(const Object& object);
PostOverrides parsePost(const Object& object);

} // namespace specula::scene::scenefile_detail
