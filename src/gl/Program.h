#pragma once
// Shader programs built from files under the shader root, with #include and defines.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/fwd.hpp>

#include "core/Error.h"
#include "gl/Handle.h"

namespace specula::gl {

namespace detail {
void deleteProgram(uint32_t id);
}

/// A program that could not be built from its files: a missing or cyclic include, a compile or
/// a link error. The message names the file and line (shaders/forward/pbr.frag:120: ...).
class ShaderError : public Error {
public:
    using Error::Error;
};

/// Where the GLSL sources are read from: $SPECULA_SHADER_DIR; else share/specula/shaders
/// beside or one level above the file holding the library (bin/../share when installed; the
/// build tree's share/, a link to shaders/); else empty, meaning the copy embedded in the
/// library at build time (loadShaderSource reads it), which always matches the C++ it was
/// built with.
std::filesystem::path shaderRoot();

struct ProgramDesc {
    std::string vertex;   ///< paths relative to the shader root
    std::string fragment;
    std::string compute;
    std::vector<std::string> defines;
    std::string label;
    std::filesystem::path root; ///< empty = shaderRoot()
};

class Program {
public:
    Program() = default;
    /// Compiles and links; throws ShaderError whose message names file and line.
    explicit Program(const ProgramDesc& desc);

    uint32_t id() const { return mHandle.get(); }
    explicit operator bool() const { return bool(mHandle); }
    const ProgramDesc& desc() const { return mDesc; }

    /// Looks a uniform up (do it once, at set-up); -1 when absent or optimised away.
    int uniformLocation(const char* name) const;

    void set(int location, int value) const;
    void set(int location, uint32_t value) const;
    void set(int location, float value) const;
    void set(int location, const glm::ivec2& value) const;
    void set(int location, const glm::ivec3& value) const;
    void set(int location, const glm::vec2& value) const;
    void set(int location, const glm::vec3& value) const;
    void set(int location, const glm::vec4& value) const;
    void set(int location, const glm::mat3& value) const;
    void set(int location, const glm::mat4& value) const;

private:
    Handle<detail::deleteProgram> mHandle;
    ProgramDesc mDesc;
};

} // namespace specula::gl
