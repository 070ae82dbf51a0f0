#pragma once
// Hot reload's eyes: notices edits to the GLSL files under a directory by polling their
// modification times and sizes (a size change is seen even when the clock's tick is coarser
// than the time between two saves).
#include <cstdint>
#include <filesystem>
#include <map>
#include <utility>

namespace specula::viewer {

class ShaderWatcher {
public:
    /// Takes the first snapshot of every regular file under `root`.
    explicit ShaderWatcher(std::filesystem::path root);

    /// True when a file was added, removed or changed since the last snapshot; takes a new one.
    bool changed();
    const std::filesystem::path& root() const { return mRoot; }

private:
    using Snapshot = std::map<std::filesystem::path, std::pair<std::filesystem::file_time_type, uintmax_t>>;
    Snapshot snapshot() const;
    std::filesystem::path mRoot;
    Snapshot mLast;
};

} // namespace specula::viewer
