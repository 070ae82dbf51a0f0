#pragma once
// Files for the unit tests: a scratch directory removed with everything in it, whole-file
// reads and writes, the message of the specula::Error a call throws, and scene files from
// JSON text.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/Error.h"
#include "scene/LoadOptions.h"

namespace specula::scene {
struct SceneDocument;
}

namespace specula::test {

/// A fresh directory, specula-<prefix>-<random number>, under the system temp directory;
/// removed with everything in it (owner permissions restored first, for tests that lock it).
class TempDir {
public:
    explicit TempDir(std::string_view prefix = "unit");
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return mPath; }
    std::filesystem::path operator/(std::string_view name) const { return mPath / name; }
    /// Writes `bytes` to `name` in the directory (whose parent must exist) and returns its path.
    std::filesystem::path write(std::string_view name, std::string_view bytes) const;
    /// Names of the entries, sorted, hidden ones (the writers' temporary files) included.
    std::vector<std::string> entries() const;

private:
    std::filesystem::path mPath;
};

void writeFile(const std::filesystem::path& path, std::string_view bytes);
std::string readFile(const std::filesystem::path& path);

/// The message of the specula::Error `f` throws; a test failure if it throws nothing or
/// something else, or if the message is more than one line (errors are printed as one).
template <typename F>
std::string errorOf(F&& f)
{
    try {
        f();
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
        return message;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not a specula::Error: " << e.what();
        return {};
    }
    ADD_FAILURE() << "no error thrown";
    return {};
}

/// Scene files in a scratch directory that name the shared assets: outside their folder, so
/// loaded with --allow-external-files (the confinement itself: tests/cli/test_cli_limits.cpp).
inline const scene::LoadOptions kAllowExternal{.allowExternalFiles = true};

/// The document of a scene file holding `json` (written to a scratch directory, removed after).
scene::SceneDocument loadSceneText(std::string_view json);
/// The error loading a scene file holding `json` (errorOf), its path replaced by "scene.json".
std::string sceneError(std::string_view json);

} // namespace specula::test
