#include "FuzzSupport.h"

#include <spdlog/spdlog.h>

namespace specula::fuzz {

scene::LoadOptions loadOptions()
{
    scene::LoadOptions options;
    options.limits.maxBufferBytes = uint64_t(64) << 20;
    options.limits.maxAccessorCount = uint64_t(1) << 20;
    options.limits.maxImageSize = 4096;
    options.limits.maxTextureBytes = uint64_t(256) << 20;
    return options;
}

void quietLogs()
{
    static const bool once = [] {
        spdlog::set_level(spdlog::level::off);
        return true;
    }();
    (void)once;
}

} // namespace specula::fuzz
