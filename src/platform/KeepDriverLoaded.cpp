// Sanitizer builds only (SPECULA_SANITIZE): keeps Mesa's EGL and DRI driver libraries mapped
// until the process exits (RTLD_NODELETE), so that LeakSanitizer can name the frames of what the
// driver leaves allocated at exit, and finds it reachable from the driver's globals. Once
// eglTerminate has unloaded them, their frames are "<unknown module>" and no suppression
// (scripts/sanitizers/lsan.supp) can match them. Called by every context the library makes, so
// it holds for any program linking it (the tests, the CLI, an embedding program such as
// examples/embed); has no effect on what the program does, and does nothing in other builds.
#include "platform/KeepDriverLoaded.h"

#ifdef SPECULA_SANITIZE
#include <dlfcn.h>

#include <initializer_list>
#endif

namespace specula::platform {

void keepDriverLoaded()
{
#ifdef SPECULA_SANITIZE
    static const bool kept = [] {
        for (const char* library : {"libEGL_mesa.so.0", "libGLX_mesa.so.0", "libglapi.so.0",
                                    "/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so"})
            dlopen(library, RTLD_LAZY | RTLD_GLOBAL | RTLD_NODELETE);
        return true;
    }();
    (void)kept;
#endif
}

} // namespace specula::platform
