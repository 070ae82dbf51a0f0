#include "TestFiles.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <random>

#include "scene/SceneFile.h"

namespace fs = std::filesystem;

namespace specula::test {

TempDir::TempDir(std::string_view prefix)
{
    std::random_device random;
    mPath = fs::temp_directory_path() / ("specula-" + std::string(prefix) + "-" + std::to_string(random()));
    fs::create_directories(mPath);
}

TempDir::~TempDir()
{
    std::error_code ec;
    fs::permissions(mPath, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(mPath, ec);
}

fs::path TempDir::write(std::string_view name, std::string_view bytes) const
{
    const fs::path path = mPath / name;
    writeFile(path, bytes);
    return path;
}

std::vector<std::string> TempDir::entries() const
{
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(mPath)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

void writeFile(const fs::path& path, std::string_view bytes)
{
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

std::string readFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

scene::SceneDocument loadSceneText(std::string_view json)
{
    const TempDir dir("scene-text");
    return scene::loadSceneFile(dir.write("scene.json", json), kAllowExternal);
}

std::string sceneError(std::string_view json)
{
    const TempDir dir("scene-text");
    const fs::path path = dir.write("scene.json", json);
    std::string message = errorOf([&] { scene::loadSceneFile(path, kAllowExternal); });
    if (message.starts_with(path.string())) message.replace(0, path.string().size(), "scene.json");
    return message;
}

} // namespace specula::test
