#pragma once
// Replays UI actions from a text file, one per line, so the viewer can be tested headless.
// The line format is documented in docs/viewer.md.
#include <filesystem>
#include <string>
#include <vector>

namespace specula::viewer {

class Viewer;

class ViewerScript {
public:
    /// Reads the file; throws specula::Error when it cannot.
    explicit ViewerScript(const std::filesystem::path& path);

    /// Runs actions until one asks for frames; returns how many (0 = the script is done).
    /// Throws specula::Error naming file and line for a bad line or a failed expectation.
    int runUntilFrames(Viewer& viewer);
    bool done() const { return mNext >= mLines.size(); }

private:
    int run(Viewer& viewer, const std::string& line); ///< frames asked for, or 0
    std::filesystem::path mPath;
    std::vector<std::string> mLines;
    size_t mNext = 0;
};

} // namespace specula::viewer
