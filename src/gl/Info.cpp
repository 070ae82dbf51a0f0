#include "gl/Info.h"

#include <epoxy/gl.h>

namespace specula::gl {
namespace {

std::string str(GLenum name)
{
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s ? s : "";
}

} // namespace

DeviceInfo queryDeviceInfo()
{
    DeviceInfo info;
    info.vendor = str(GL_VENDOR);
    info.renderer = str(GL_RENDERER);
    info.version = str(GL_VERSION);
    info.glslVersion = str(GL_SHADING_LANGUAGE_VERSION);
    const std::pair<const char*, GLenum> limits[] = {
        {"GL_MAX_TEXTURE_SIZE", GL_MAX_TEXTURE_SIZE},
        {"GL_MAX_CUBE_MAP_TEXTURE_SIZE", GL_MAX_CUBE_MAP_TEXTURE_SIZE},
        {"GL_MAX_ARRAY_TEXTURE_LAYERS", GL_MAX_ARRAY_TEXTURE_LAYERS},
        {"GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS", GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS},
        {"GL_MAX_TEXTURE_IMAGE_UNITS", GL_MAX_TEXTURE_IMAGE_UNITS},
        {"GL_MAX_UNIFORM_BLOCK_SIZE", GL_MAX_UNIFORM_BLOCK_SIZE},
        {"GL_MAX_UNIFORM_BUFFER_BINDINGS", GL_MAX_UNIFORM_BUFFER_BINDINGS},
        {"GL_MAX_SHADER_STORAGE_BLOCK_SIZE", GL_MAX_SHADER_STORAGE_BLOCK_SIZE},
        {"GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS", GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS},
        {"GL_MAX_COLOR_ATTACHMENTS", GL_MAX_COLOR_ATTACHMENTS},
        {"GL_MAX_DRAW_BUFFERS", GL_MAX_DRAW_BUFFERS},
        {"GL_MAX_SAMPLES", GL_MAX_SAMPLES},
        {"GL_MAX_COLOR_TEXTURE_SAMPLES", GL_MAX_COLOR_TEXTURE_SAMPLES},
        {"GL_MAX_DEPTH_TEXTURE_SAMPLES", GL_MAX_DEPTH_TEXTURE_SAMPLES},
        {"GL_MAX_VERTEX_ATTRIBS", GL_MAX_VERTEX_ATTRIBS},
        {"GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS", GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS},
        {"GL_MAX_COMPUTE_SHARED_MEMORY_SIZE", GL_MAX_COMPUTE_SHARED_MEMORY_SIZE},
        {"GL_MAX_VIEWPORT_DIMS", GL_MAX_VIEWPORT_DIMS},
    };
    for (const auto& [name, e] : limits) {
        GLint64 value[2] = {0, 0};
        glGetInteger64v(e, value);
        info.limits.emplace_back(name, value[0]);
    }
    GLint bits = 0;
    glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
    info.limits.emplace_back("GL_QUERY_COUNTER_BITS (GL_TIME_ELAPSED)", bits);
    for (const char* ext : {"GL_KHR_debug", "GL_ARB_timer_query", "GL_ARB_direct_state_access", "GL_ARB_compute_shader",
                            "GL_EXT_texture_filter_anisotropic", "GL_ARB_texture_filter_anisotropic"}) {
        info.extensions.emplace_back(ext, epoxy_has_gl_extension(ext));
    }
    return info;
}

int maxTextureUnits()
{
    GLint value = 0;
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &value);
    return value;
}

int maxCombinedTextureUnits()
{
    GLint value = 0;
    glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &value);
    return value;
}

int maxColorSamples()
{
    GLint samples = 0;
    glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &samples);
    return samples;
}

int maxDepthSamples()
{
    GLint samples = 0;
    glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &samples);
    return samples;
}

} // namespace specula::gl
