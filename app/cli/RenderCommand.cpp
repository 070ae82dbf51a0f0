#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "Commands.h"
#include "PassTable.h"
#include "core/Error.h"
#include "core/ImageIO.h"
#include "core/Log.h"
#include "core/ProcessClock.h"
#include "core/Timer.h"
#include "gl/Debug.h"
#include "platform/Context.h"

namespace specula::cli {

int runRender(const RenderArgs& args)
{
    const std::filesystem::path output = args.output;
    checkOutputPath(output); // before any long work

    Stopwatch load;
    scene::SceneDocument document = setup::loadSceneOrBuiltin(args.scene, args.frame.load, args.frame.lights);
    const render::FrameSettings settings = setup::resolveSettings(document, args.frame);
    const setup::AnimationChoice animation = setup::resolveAnimation(document.scene, args.frame);
    const std::optional<render::EnvironmentMap> environment = setup::loadEnvironment(document, args.frame);
    const render::BakeSettings bake = setup::resolveBakeSettings(args.frame);
    int defaultLights = 0;
    const render::View view = setup::prepareView(document, args.frame, settings, &defaultLights, environment.has_value());
    log::info("loaded {} in {:.0f} ms: {} meshes, {} triangles, {} lights{}", args.scene.empty() ? "demo" : args.scene,
              load.elapsedMs(), document.scene.meshes.size(), document.scene.triangleCount(), document.scene.lights.size(),
              defaultLights ? " (default rig)" : "");

    auto context = platform::Context::createHeadless();
    gl::DebugMonitor debug;
    render::Renderer renderer;
    renderer.setCacheDirectory(setup::cacheDirectory(args.frame));
    renderer.setScene(document.scene);
    renderer.setPose(animation.index, animation.seconds);
    if (environment) renderer.setEnvironment(*environment, bake, setup::cacheDirectory(args.frame));
    if (!args.printGraph.empty()) {
        const std::string dot = renderer.frameGraphDot(view, settings);
        if (args.printGraph == "-") {
            std::fwrite(dot.data(), 1, dot.size(), stdout);
        } else {
            std::ofstream out(args.printGraph, std::ios::binary);
            out << dot;
            if (!out) throw Error("cannot write the frame graph to {}", args.printGraph);
        }
    }
    renderer.render(view, settings);
    const ImageRGBA8 image = renderer.readImage(); // waits for the GPU: the frame is done
    const double firstFrameMs = msSinceProcessStart();

    std::string extension = output.extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".png") {
        writePng(output, image);
    } else if (extension == ".hdr") {
        writeHdr(output, renderer.readRadiance());
    } else {
        writeExr(output, renderer.readRadiance());
    }
    // A Doom frame renders one sample a pixel, with no tone curve, whatever was asked for.
    const bool doomFrame =
        settings.materialOverride.model == scene::ShadingModel::Doom && settings.debugView == DebugView::None;
    const int samples = doomFrame ? 1 : settings.msaa;
    if (doomFrame)
        log::info("first frame {:.0f} ms after start; wrote {} ({}x{}, Doom's 8-bit frame: palette colours only)", firstFrameMs,
                  output.string(), settings.width, settings.height);
    else
        log::info("first frame {:.0f} ms after start; wrote {} ({}x{}, {} sample{}, {} tone mapping)", firstFrameMs,
                  output.string(), settings.width, settings.height, settings.msaa, settings.msaa == 1 ? "" : "s",
                  render::tonemapName(settings.tonemap));
    const render::FrameStats::Shadows& shadows = renderer.stats().shadows;
    if (shadows.lights > 0 || shadows.dropped > 0)
        log::info("shadows: {} light{} with a map, {} view{} in a {}² atlas{}", shadows.lights, shadows.lights == 1 ? "" : "s",
                  shadows.views, shadows.views == 1 ? "" : "s", shadows.atlasSize,
                  shadows.dropped > 0 ? fmt::format("; {} casting light{} left without one (over --shadows-max-lights or no room)",
                                                    shadows.dropped, shadows.dropped == 1 ? "" : "s")
                                      : std::string());
    if (settings.debugView == DebugView::ShadowAtlas && shadows.lights == 0)
        log::warn("--debug-view shadow-atlas: no light of this scene casts a shadow, so the image is the frame itself");
    if (args.stats) {
        // After the written frame, so its start-up figure is unchanged; the first timed frame
        // would include shader compilation, so one untimed frame goes first.
        renderer.render(view, settings);
        renderer.setGpuTiming(true);
        renderer.setPassWallClock(true);
        PassTimes times;
        for (int frame = 0; frame < kStatsFrames; ++frame) {
            renderer.render(view, settings);
            times.add(renderer.stats());
        }
        printPassTable(fmt::format("Time per pass, median of {} frames ({}x{}, {} sample{}):", kStatsFrames, settings.width,
                                   settings.height, samples, samples == 1 ? "" : "s"),
                       times.medians());
        const std::string clusters = clusterStatsLine(renderer.stats().clusters);
        if (!clusters.empty()) std::printf("%s\n", clusters.c_str());
    }
    if (debug.errorCount() > 0) {
        // GL errors are bugs: never pass one off as a good image.
        std::filesystem::remove(output);
        throw Error("OpenGL reported {} error(s); first: {}", debug.errorCount(), debug.errors().front());
    }
    return 0;
}

} // namespace specula::cli
