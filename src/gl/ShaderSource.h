#pragma once
// GLSL source assembly: #include resolution (each file once, cycles reported), defines,
// and #line directives so that compiler messages can name the original file and line.
// No GL here, so it is unit-testable.
#include <filesystem>
#include <string>
#include <vector>

namespace specula::gl {

struct ShaderSource {
    std::string text;
    /// Source-string numbers used in #line directives: files[n] is the path (relative to
    /// the shader root) that "#line L n" refers to.
    std::vector<std::string> files;
};

/// Loads `path` (relative to `root`), resolving `#include "x"` relative to the including
/// file first, then to `root`; an empty `root` reads the copy embedded in the library
/// (gl/EmbeddedShaders.h). `defines` are "NAME" or "NAME VALUE", inserted after #version.
/// Throws specula::Error ("file:line: cannot include ...", "include cycle: a -> b -> a").
ShaderSource loadShaderSource(const std::filesystem::path& root, const std::string& path,
                              const std::vector<std::string>& defines = {});

/// Rewrites a driver's info log so that "N:L(C)" (Mesa) and "N(L)" (NVIDIA) references read
/// "shaders/<file>:L". Lines it does not recognise are kept.
std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files);

} // namespace specula::gl
