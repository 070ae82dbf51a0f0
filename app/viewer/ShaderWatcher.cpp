#include "ShaderWatcher.h"

namespace specula::viewer {

ShaderWatcher::ShaderWatcher(std::filesystem::path root) : mRoot(std::move(root)), mLast(snapshot()) {}

ShaderWatcher::Snapshot ShaderWatcher::snapshot() const
{
    // Errors (a file deleted while listing, a directory that is gone) end the listing: what was
    // listed differs from the last snapshot, and the next poll tries again.
    Snapshot files;
    std::error_code error;
    for (auto it = std::filesystem::recursive_directory_iterator(mRoot, error);
         !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error)) {
        if (!it->is_regular_file(error)) continue;
        files[it->path()] = {it->last_write_time(error), it->file_size(error)};
    }
    return files;
}

bool ShaderWatcher::changed()
{
    Snapshot now = snapshot();
    if (now == mLast) return false;
    mLast = std::move(now);
    return true;
}

} // namespace specula::viewer
