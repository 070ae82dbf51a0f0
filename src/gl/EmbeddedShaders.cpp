#include "gl/EmbeddedShaders.h"

#include <algorithm>

namespace specula::gl {

const EmbeddedShader* findEmbeddedShader(std::string_view path)
{
    const std::span<const EmbeddedShader> shaders = embeddedShaders();
    const auto it = std::lower_bound(shaders.begin(), shaders.end(), path,
                                     [](const EmbeddedShader& shader, std::string_view p) { return shader.path < p; });
    return it != shaders.end() && it->path == path ? &*it : nullptr;
}

} // namespace specula::gl
