// Sanitizer builds only (CMakeLists.txt, SPECULA_SANITIZE): keeps Mesa's EGL and DRI driver
// libraries mapped until the process exits (RTLD_NODELETE), so that LeakSanitizer can name the
// frames of what the driver leaves allocated at exit. Once eglTerminate has unloaded them, their
// frames are "<unknown module>" and no suppression (scripts/sanitizers/lsan.supp) can match
// them. Linked into every target; has no effect on what the program does.
#include <dlfcn.h>

#include <initializer_list>

namespace {

struct KeepDriverLoaded {
    KeepDriverLoaded()
    {
        for (const char* library : {"libEGL_mesa.so.0", "libGLX_mesa.so.0", "libglapi.so.0",
                                    "/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so"})
            dlopen(library, RTLD_LAZY | RTLD_GLOBAL | RTLD_NODELETE);
    }
} keepDriverLoaded;

} // namespace
