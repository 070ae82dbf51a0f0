// Headless OpenGL through EGL. Mesa offers a surfaceless platform (no window system at all);
// NVIDIA's driver exposes GPUs through EGL device enumeration; anything else gets a pbuffer.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/Error.h"
#include "core/Log.h"
#include "platform/Context.h"
#include "platform/KeepDriverLoaded.h"

namespace specula::platform {
namespace {

bool hasExtension(const char* list, const char* name)
{
    if (!list) return false;
    const size_t length = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)); p += length) {
        if ((p == list || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0')) return true;
    }
    return false;
}

class EglContext final : public Context {
public:
    ~EglContext() override
    {
        if (mDisplay != EGL_NO_DISPLAY) {
            eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            if (mContext != EGL_NO_CONTEXT) eglDestroyContext(mDisplay, mContext);
            if (mSurface != EGL_NO_SURFACE) eglDestroySurface(mDisplay, mSurface);
            eglTerminate(mDisplay);
        }
    }

    // Tries one way of getting a display; returns false (and cleans up) if it fails.
    bool tryCreate(const std::string& platform, const ContextDesc& desc, std::string& why)
    {
        const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        auto getPlatformDisplay =
            reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        bool needSurface = false;
        if (platform == "surfaceless") {
            if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless") || !getPlatformDisplay) {
                why = "no EGL_MESA_platform_surfaceless";
                return false;
            }
            mDisplay = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        } else if (platform == "device") {
            auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
            if (!hasExtension(clientExtensions, "EGL_EXT_device_enumeration") || !queryDevices || !getPlatformDisplay) {
                why = "no EGL_EXT_device_enumeration";
                return false;
            }
            EGLDeviceEXT devices[16];
            EGLint count = 0;
            if (!queryDevices(16, devices, &count) || count == 0) {
                why = "no EGL devices";
                return false;
            }
            // Prefer the first device that initialises; software devices come last on Mesa.
            for (EGLint i = 0; i < count && mDisplay == EGL_NO_DISPLAY; ++i) {
                EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) {
                    mDisplay = display;
                } else if (display != EGL_NO_DISPLAY) {
                    eglTerminate(display);
                }
            }
        } else {
            mDisplay = eglGetDisplay(EGL_DEFAULT_DISPLAY);
            needSurface = true;
        }
        if (mDisplay == EGL_NO_DISPLAY) {
            why = "no display";
            return false;
        }
        EGLint major = 0, minor = 0;
        if (!eglInitialize(mDisplay, &major, &minor)) {
            why = "eglInitialize failed";
            mDisplay = EGL_NO_DISPLAY;
            return false;
        }
        const char* displayExtensions = eglQueryString(mDisplay, EGL_EXTENSIONS);
        if (!needSurface && !hasExtension(displayExtensions, "EGL_KHR_surfaceless_context")) needSurface = true;

        if (!eglBindAPI(EGL_OPENGL_API)) {
            why = "eglBindAPI(EGL_OPENGL_API) failed";
            return false;
        }
        const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                        EGL_SURFACE_TYPE, needSurface ? EGL_PBUFFER_BIT : 0,
                                        EGL_NONE};
        EGLConfig config = nullptr;
        EGLint configCount = 0;
        if (!eglChooseConfig(mDisplay, configAttribs, &config, 1, &configCount) || configCount == 0) {
            why = "no OpenGL EGL config";
            return false;
        }
        const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                         EGL_CONTEXT_MINOR_VERSION, 5,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_CONTEXT_OPENGL_DEBUG, desc.debug ? EGL_TRUE : EGL_FALSE,
                                         EGL_NONE};
        mContext = eglCreateContext(mDisplay, config, EGL_NO_CONTEXT, contextAttribs);
        if (mContext == EGL_NO_CONTEXT) {
            why = fmt::format("eglCreateContext for OpenGL 4.5 core failed (0x{:x})", eglGetError());
            return false;
        }
        if (needSurface) {
            const EGLint pbufferAttribs[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
            mSurface = eglCreatePbufferSurface(mDisplay, config, pbufferAttribs);
            if (mSurface == EGL_NO_SURFACE) {
                why = "eglCreatePbufferSurface failed";
                return false;
            }
        }
        if (!eglMakeCurrent(mDisplay, mSurface, mSurface, mContext)) {
            why = "eglMakeCurrent failed";
            return false;
        }
        mBackend = platform == "surfaceless" ? "EGL surfaceless"
                 : platform == "device"      ? "EGL device"
                                             : "EGL pbuffer";
        return true;
    }

    void makeCurrent() override { eglMakeCurrent(mDisplay, mSurface, mSurface, mContext); }

    void reset()
    {
        if (mDisplay != EGL_NO_DISPLAY) {
            eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            if (mContext != EGL_NO_CONTEXT) eglDestroyContext(mDisplay, mContext);
            if (mSurface != EGL_NO_SURFACE) eglDestroySurface(mDisplay, mSurface);
            eglTerminate(mDisplay);
        }
        mDisplay = EGL_NO_DISPLAY;
        mContext = EGL_NO_CONTEXT;
        mSurface = EGL_NO_SURFACE;
    }

private:
    EGLDisplay mDisplay = EGL_NO_DISPLAY;
    EGLContext mContext = EGL_NO_CONTEXT;
    EGLSurface mSurface = EGL_NO_SURFACE;
};

} // namespace

std::unique_ptr<Context> Context::createHeadless(const ContextDesc& desc)
{
    std::vector<std::string> order = {"surfaceless", "device", "pbuffer"};
    if (const char* forced = std::getenv("SPECULA_EGL_PLATFORM"); forced && *forced) order = {forced};

    keepDriverLoaded();
    std::string failures;
    for (const std::string& platform : order) {
        auto context = std::unique_ptr<EglContext>(new EglContext());
        std::string why;
        if (context->tryCreate(platform, desc, why)) {
            log::debug("OpenGL context: {}", context->backend());
            return context;
        }
        context->reset();
        failures += fmt::format("{}{}: {}", failures.empty() ? "" : "; ", platform, why);
    }
    throw Error("cannot create a headless OpenGL 4.5 context ({})", failures);
}

} // namespace specula::platform
