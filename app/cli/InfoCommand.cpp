#include <cstdio>

#include "Commands.h"
#include "gl/Info.h"
#include "platform/Context.h"

namespace specula::cli {

int runInfo()
{
    auto context = platform::Context::createHeadless({.debug = false});
    const gl::DeviceInfo info = gl::queryDeviceInfo();
    std::printf("context:   %s\n", context->backend().c_str());
    std::printf("vendor:    %s\n", info.vendor.c_str());
    std::printf("renderer:  %s\n", info.renderer.c_str());
    std::printf("version:   %s\n", info.version.c_str());
    std::printf("GLSL:      %s\n", info.glslVersion.c_str());
    std::printf("limits:\n");
    for (const auto& [name, value] : info.limits) std::printf("  %-42s %lld\n", name.c_str(), static_cast<long long>(value));
    std::printf("extensions:\n");
    for (const auto& [name, present] : info.extensions) std::printf("  %-42s %s\n", name.c_str(), present ? "yes" : "no");
    return 0;
}

} // namespace specula::cli
