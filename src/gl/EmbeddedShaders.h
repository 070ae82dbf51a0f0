#pragma once
// The shaders the library was built with, embedded at build time (cmake/EmbedShaders.cmake),
// so that a program linking it needs no files beside it: what shaderRoot() falls back to.
#include <span>
#include <string_view>

namespace specula::gl {

struct EmbeddedShader {
    std::string_view path; ///< relative to shaders/, '/'-separated
    std::string_view text;
};

/// Every file of shaders/, sorted by path.
std::span<const EmbeddedShader> embeddedShaders();

/// The embedded file at `path` (relative to shaders/, normalised), or nullptr.
const EmbeddedShader* findEmbeddedShader(std::string_view path);

} // namespace specula::gl
