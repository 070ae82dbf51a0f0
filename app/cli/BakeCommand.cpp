#include <cstdio>

#include "Commands.h"
#include "core/Error.h"
#include "gl/Debug.h"
#include "gl/State.h"
#include "platform/Context.h"
#include "render/ImageBasedLighting.h"
#include "setup/SceneSetup.h"

namespace specula::cli {

int runBake(const BakeArgs& args)
{
    const auto preset = render::bakePreset(args.preset);
    if (!preset) throw Error("unknown --bake-preset '{}' (default, reference)", args.preset);
    render::EnvironmentMap map = args.env == "sky" ? render::proceduralSky() : render::loadEnvironmentMap(args.env);
    // The entry `--env-sun extract` reads: the map less its sun (the light's direction and lux
    // depend on the frame's rotation and intensity, not on the bake).
    if (setup::extractsSun(args.envSun)) setup::extractEnvironmentSun(map, 0.0f, 1.0f);
    const std::filesystem::path directory = args.cacheDirectory.empty() ? render::defaultCacheDirectory() : std::filesystem::path(args.cacheDirectory);
    auto context = platform::Context::createHeadless();
    gl::DebugMonitor debug;
    gl::State state;
    render::ImageBasedLighting ibl;
    ibl.setLutCacheDirectory(directory);
    const render::BakeReport report = ibl.setEnvironment(state, map, *preset, directory);
    // The glTF BRDF's table; other BRDF variants' tables are baked (and cached) on first use.
    ibl.dfg(state, render::ResolvedShading{});
    if (debug.errorCount() > 0) throw Error("OpenGL reported {} error(s); first: {}", debug.errorCount(), debug.errors().front());
    std::printf("%s %s (%s, %.0f ms)\n", report.fromCache ? "already cached:" : "wrote", report.cacheFile.string().c_str(),
                preset->name.c_str(), report.milliseconds);
    return 0;
}

} // namespace specula::cli
