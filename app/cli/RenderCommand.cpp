#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

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

namespace {

/// What `specula render` names a scene in an output pattern's {scene}: the file's stem, or the
/// built-in's name ("demo" for none).
std::string sceneName(const std::string& scene)
{
    if (scene.empty()) return "demo";
    const std::filesystem::path path(scene);
    return path.has_extension() ? path.stem().string() : scene;
}

/// `pattern` with {scene} and {camera} replaced.
std::filesystem::path expandOutput(const std::string& pattern, const std::string& scene, const std::string& camera)
{
    std::string out = pattern;
    for (const auto& [key, value] : {std::pair<std::string, std::string>{"{scene}", scene}, {"{camera}", camera}})
        for (size_t at = out.find(key); at != std::string::npos; at = out.find(key, at + value.size())) out.replace(at, key.size(), value);
    return out;
}

/// One image of a batch: a view of a loaded scene, written to `output`.
struct Shot {
    render::FrameSettings settings; ///< the scene's, sized for the shot's camera (setup::fitSizeToCamera)
    render::View view;
    std::filesystem::path output;
    std::string label;
};

/// A scene of the batch, loaded, with its shots.
struct LoadedScene {
    std::string name;
    scene::SceneDocument document;
    render::FrameSettings settings;
    setup::AnimationChoice animation;
    int variant = -1; ///< KHR_materials_variants (--variant)
    std::optional<render::EnvironmentMap> environment;
    std::vector<Shot> shots;
};

void writeImage(const std::filesystem::path& output, const ImageRGBA8& image, render::Renderer& renderer)
{
    std::string extension = output.extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".png") {
        writePng(output, image);
    } else if (extension == ".hdr") {
        writeHdr(output, renderer.readRadiance());
    } else {
        writeExr(output, renderer.readRadiance());
    }
}

} // namespace

int runRender(const RenderArgs& args)
{
    const std::vector<std::string> scenes = args.scenes.empty() ? std::vector<std::string>{""} : args.scenes;
    const bool patterned = args.output.find("{scene}") != std::string::npos || args.output.find("{camera}") != std::string::npos;
    if (!patterned) checkOutputPath(args.output); // before any long work

    // Every scene is read and every output named before anything renders: a bad file or a
    // clash of names stops the batch before its long work.
    std::vector<LoadedScene> loaded;
    std::set<std::filesystem::path> outputs;
    size_t images = 0;
    for (const std::string& sceneArg : scenes) {
        Stopwatch load;
        LoadedScene& s = loaded.emplace_back();
        s.name = sceneName(sceneArg);
        s.document = setup::loadSceneOrBuiltin(sceneArg, args.frame.load, args.frame.lights);
        s.settings = setup::resolveSettings(s.document, args.frame);
        s.animation = setup::resolveAnimation(s.document.scene, args.frame);
        s.variant = setup::resolveVariant(s.document.scene, args.frame);
        s.environment = setup::loadEnvironment(s.document, args.frame);
        std::vector<int> cameras{args.frame.camera};
        if (args.frame.allCameras) {
            cameras.clear();
            for (size_t i = 0; i < s.document.scene.cameraInstances().size(); ++i) cameras.push_back(int(i));
            if (cameras.empty()) cameras.push_back(-1); // no camera: the framed view
        }
        int defaultLights = 0;
        for (const int camera : cameras) {
            setup::FrameOptions options = args.frame;
            options.camera = camera;
            Shot shot;
            shot.settings = s.settings;
            setup::fitSizeToCamera(shot.settings, s.document, options);
            shot.view = setup::prepareView(s.document, options, shot.settings, &defaultLights, s.environment.has_value(), s.animation);
            const std::string cameraName = camera >= 0 ? std::to_string(camera) : "framed";
            shot.output = patterned ? expandOutput(args.output, s.name, cameraName) : std::filesystem::path(args.output);
            shot.label = args.frame.allCameras ? s.name + " camera " + cameraName : s.name;
            if (!outputs.insert(shot.output).second)
                throw Error("two images would be written to {}: with several scenes or --camera all, -o needs {{scene}} and/or "
                            "{{camera}} in it (e.g. -o out/{{scene}}-{{camera}}.png)",
                            shot.output.string());
            checkOutputPath(shot.output);
            s.shots.push_back(std::move(shot));
            ++images;
        }
        log::info("loaded {} in {:.0f} ms: {} meshes, {} triangles, {} lights{}", sceneArg.empty() ? "demo" : sceneArg,
                  load.elapsedMs(), s.document.scene.meshes.size(), s.document.scene.triangleCount(),
                  s.document.scene.lights.size(), defaultLights ? " (default rig)" : "");
    }
    if (!args.printGraph.empty() && images > 1) throw Error("--print-graph writes one frame's graph: give one scene and one camera");

    // One context and one renderer for the batch: its programs and tables are made once.
    auto context = platform::Context::createHeadless();
    gl::DebugMonitor debug;
    render::Renderer renderer;
    renderer.setCacheDirectory(setup::cacheDirectory(args.frame));
    const render::BakeSettings bake = setup::resolveBakeSettings(args.frame);
    size_t written = 0;
    for (LoadedScene& s : loaded) {
        renderer.setScene(s.document.scene);
        renderer.setPose(s.animation.index, s.animation.seconds);
        renderer.setVariant(s.variant);
        if (s.environment)
            renderer.setEnvironment(*s.environment, bake, setup::cacheDirectory(args.frame));
        else
            renderer.clearEnvironment();
        for (const Shot& shot : s.shots) {
            const render::FrameSettings& settings = shot.settings;
            const render::View& view = shot.view;
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
            writeImage(shot.output, image, renderer);
            ++written;
            const std::string progress = images > 1 ? fmt::format("[{}/{}] {}: ", written, images, shot.label) : std::string();
            const char* when = written == 1 ? "first frame" : "frame";
            // A Doom frame renders one sample a pixel, with no tone curve, whatever was asked for.
            const bool doomFrame =
                settings.materialOverride.model == scene::ShadingModel::Doom && settings.debugView == DebugView::None;
            const int samples = doomFrame ? 1 : settings.msaa;
            if (doomFrame)
                log::info("{}{} {:.0f} ms after start; wrote {} ({}x{}, Doom's 8-bit frame: palette colours only)", progress, when,
                          firstFrameMs, shot.output.string(), settings.width, settings.height);
            else
                log::info("{}{} {:.0f} ms after start; wrote {} ({}x{}, {} sample{}, {} tone mapping)", progress, when, firstFrameMs,
                          shot.output.string(), settings.width, settings.height, settings.msaa, settings.msaa == 1 ? "" : "s",
                          render::tonemapName(settings.tonemap));
            const render::FrameStats::Shadows& shadows = renderer.stats().shadows;
            if (shadows.lights > 0 || shadows.dropped > 0)
                log::info("shadows: {} light{} with a map, {} view{} in a {}² atlas{}", shadows.lights, shadows.lights == 1 ? "" : "s",
                          shadows.views, shadows.views == 1 ? "" : "s", shadows.atlasSize,
                          shadows.dropped > 0
                              ? fmt::format("; {} casting light{} left without one (over --shadows-max-lights or no room)",
                                            shadows.dropped, shadows.dropped == 1 ? "" : "s")
                              : std::string());
            if (settings.debugView == DebugView::ShadowAtlas && shadows.lights == 0)
                log::warn("--debug-view shadow-atlas: no light of this scene casts a shadow, so the image is the frame itself");
            const bool firstLightView = settings.debugView == DebugView::BrdfD || settings.debugView == DebugView::BrdfG ||
                                        settings.debugView == DebugView::BrdfF;
            if (firstLightView && renderer.lightCount() == 0)
                log::warn("--debug-view {}: the term is the first punctual light's and this scene has none, so the image is "
                          "black (scenes without lights get the default rig with --env none)",
                          debugViewName(settings.debugView));
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
                renderer.setGpuTiming(false);
                renderer.setPassWallClock(false);
                printPassTable(fmt::format("{}Time per pass, median of {} frames ({}x{}, {} sample{}, {} triangles drawn):", progress,
                                           kStatsFrames, settings.width, settings.height, samples, samples == 1 ? "" : "s",
                                           renderer.stats().triangles),
                               times.medians());
                const std::string clusters = clusterStatsLine(renderer.stats().clusters);
                if (!clusters.empty()) std::printf("%s\n", clusters.c_str());
            }
            if (debug.errorCount() > 0) {
                // GL errors are bugs: never pass one off as a good image.
                std::filesystem::remove(shot.output);
                throw Error("OpenGL reported {} error(s); first: {}", debug.errorCount(), debug.errors().front());
            }
        }
    }
    return 0;
}

} // namespace specula::cli
