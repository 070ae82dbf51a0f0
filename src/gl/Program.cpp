#include "gl/Program.h"

#include <dlfcn.h>
#include <epoxy/gl.h>
#include <link.h>

#include <cstdlib>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/Error.h"
#include "gl/Debug.h"
#include "gl/ShaderSource.h"

namespace specula::gl {
namespace {

std::string shaderLog(GLuint shader)
{
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    return log;
}

GLuint compile(GLenum stage, const std::filesystem::path& root, const std::string& path,
               const std::vector<std::string>& defines)
{
    const ShaderSource source = loadShaderSource(root, path, defines);
    const GLuint shader = glCreateShader(stage);
    const char* text = source.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        const std::string log = mapShaderLog(shaderLog(shader), source.files);
        glDeleteShader(shader);
        // First error line only: that is the one-line message; the rest goes to debug log.
        const std::string first = log.substr(0, log.find('\n'));
        throw ShaderError("shader compile error: {}", first.empty() ? "shaders/" + path : first);
    }
    return shader;
}

} // namespace

void detail::deleteProgram(uint32_t id)
{
    glDeleteProgram(id);
}

namespace {

/// The directory of the file that holds this code: the shared library, or the executable a
/// static library is linked into.
std::filesystem::path moduleDirectory()
{
    Dl_info info{};
    link_map* map = nullptr;
    if (dladdr1(reinterpret_cast<void*>(&moduleDirectory), &info, reinterpret_cast<void**>(&map), RTLD_DL_LINKMAP) &&
        map && map->l_name && map->l_name[0] != '\0')
        return std::filesystem::path(map->l_name).parent_path();
    // The main program's link map has no name.
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path() : exe.parent_path();
}

/// share/specula/shaders beside the module or one level up: bin/../share in an installed
/// tree, build/share in the build tree (a link to the sources, for editing and hot reload).
/// Relative only, so an installed tree can move.
std::filesystem::path installedShaderDirectory()
{
    const std::filesystem::path module = moduleDirectory();
    if (module.empty()) return {};
    for (const char* candidate : {"../share/specula/shaders", "share/specula/shaders"}) {
        std::error_code ec;
        const std::filesystem::path dir = std::filesystem::weakly_canonical(module / candidate, ec);
        if (!ec && std::filesystem::is_directory(dir, ec)) return dir;
    }
    return {};
}

} // namespace

std::filesystem::path shaderRoot()
{
    if (const char* dir = std::getenv("SPECULA_SHADER_DIR"); dir && *dir) return dir;
    static const std::filesystem::path installed = installedShaderDirectory();
    return installed; // empty: the embedded copy
}

Program::Program(const ProgramDesc& desc) : mDesc(desc)
{
    std::vector<GLuint> shaders;
    const std::filesystem::path root = desc.root.empty() ? shaderRoot() : desc.root;
    auto cleanup = [&] {
        for (GLuint shader : shaders) glDeleteShader(shader);
    };
    try {
        if (!desc.compute.empty()) {
            shaders.push_back(compile(GL_COMPUTE_SHADER, root, desc.compute, desc.defines));
        } else {
            shaders.push_back(compile(GL_VERTEX_SHADER, root, desc.vertex, desc.defines));
            shaders.push_back(compile(GL_FRAGMENT_SHADER, root, desc.fragment, desc.defines));
        }
    } catch (const ShaderError&) {
        cleanup();
        throw;
    } catch (const Error& e) {
        // The loader's errors (a missing or cyclic include) are the files' fault too.
        cleanup();
        throw ShaderError(e.what());
    } catch (...) {
        cleanup();
        throw;
    }
    const GLuint program = glCreateProgram();
    mHandle = Handle<detail::deleteProgram>(program);
    for (GLuint shader : shaders) glAttachShader(program, shader);
    glLinkProgram(program);
    for (GLuint shader : shaders) glDetachShader(program, shader);
    cleanup();
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
        std::string log(size_t(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program, length, nullptr, log.data());
        log.resize(std::strlen(log.c_str()));
        const std::string first = log.substr(0, log.find('\n'));
        throw ShaderError("shader link error in '{}': {}", desc.label.empty() ? desc.vertex + desc.compute : desc.label, first);
    }
    label(GL_PROGRAM, program, desc.label);
}

int Program::uniformLocation(const char* name) const
{
    return glGetUniformLocation(id(), name);
}

void Program::set(int location, int value) const { glProgramUniform1i(id(), location, value); }
void Program::set(int location, uint32_t value) const { glProgramUniform1ui(id(), location, value); }
void Program::set(int location, float value) const { glProgramUniform1f(id(), location, value); }
void Program::set(int location, const glm::ivec2& value) const { glProgramUniform2iv(id(), location, 1, glm::value_ptr(value)); }
void Program::set(int location, const glm::ivec3& value) const { glProgramUniform3iv(id(), location, 1, glm::value_ptr(value)); }
void Program::set(int location, const glm::vec2& value) const { glProgramUniform2fv(id(), location, 1, glm::value_ptr(value)); }
void Program::set(int location, const glm::vec3& value) const { glProgramUniform3fv(id(), location, 1, glm::value_ptr(value)); }
void Program::set(int location, const glm::vec4& value) const { glProgramUniform4fv(id(), location, 1, glm::value_ptr(value)); }
void Program::set(int location, const glm::mat3& value) const
{
    glProgramUniformMatrix3fv(id(), location, 1, GL_FALSE, glm::value_ptr(value));
}
void Program::set(int location, const glm::mat4& value) const
{
    glProgramUniformMatrix4fv(id(), location, 1, GL_FALSE, glm::value_ptr(value));
}

} // namespace specula::gl
