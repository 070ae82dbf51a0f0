#pragma once
// An OpenGL 4.5 core context, headless (EGL) or in a window (GLFW).
#include <memory>
#include <string>

#include <glm/vec2.hpp>

namespace specula::platform {

struct ContextDesc {
    int width = 1280;      ///< window size; ignored by headless contexts
    int height = 720;
    bool debug = true;     ///< request a KHR_debug context
    bool visible = true;   ///< windows only
    std::string title = "Specula";
};

/// One OpenGL 4.5 core context, current on the creating thread, loaded with libepoxy.
class Context {
public:
    virtual ~Context() = default;
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    /// Headless: EGL surfaceless (Mesa), then EGL device enumeration (NVIDIA), then a pbuffer.
    /// SPECULA_EGL_PLATFORM=surfaceless|device|pbuffer forces one. Throws specula::Error.
    static std::unique_ptr<Context> createHeadless(const ContextDesc& desc = {});
    /// A GLFW window. Throws specula::Error when no display or no GL 4.5.
    static std::unique_ptr<Context> createWindow(const ContextDesc& desc = {});

    virtual void makeCurrent() = 0;
    virtual void swapBuffers() {}
    virtual void pollEvents() {}
    /// Sleeps until an event arrives or `seconds` pass (a minimised window has nothing to draw).
    virtual void waitEvents(double seconds) { (void)seconds; }
    virtual bool shouldClose() const { return false; }
    /// Size of the default framebuffer; (0, 0) for headless contexts.
    virtual glm::ivec2 framebufferSize() const { return {0, 0}; }
    /// GLFWwindow* for windowed contexts, nullptr otherwise.
    virtual void* nativeWindow() const { return nullptr; }

    /// How the context was made, e.g. "EGL surfaceless".
    const std::string& backend() const { return mBackend; }

protected:
    Context() = default;
    std::string mBackend;
};

} // namespace specula::platform
