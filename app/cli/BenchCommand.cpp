// specula bench: start-up to first frame and steady frame times, per built-in scene.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <filesystem>
#include <numeric>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "Commands.h"
#include "PassTable.h"
#include "core/Error.h"
#include "core/Log.h"
#include "core/ProcessClock.h"
#include "core/Timer.h"
#include "gl/Info.h"
#include "platform/Context.h"

#include <epoxy/gl.h>

namespace specula::cli {
namespace {

struct Summary {
    double median = 0, p10 = 0, p90 = 0, mean = 0, min = 0, max = 0;
};

Summary summarize(std::vector<double> values)
{
    Summary s;
    if (values.empty()) return s;
    std::sort(values.begin(), values.end());
    auto at = [&](double q) { return values[size_t(q * double(values.size() - 1) + 0.5)]; };
    s.median = at(0.5);
    s.p10 = at(0.1);
    s.p90 = at(0.9);
    s.min = values.front();
    s.max = values.back();
    s.mean = std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
    return s;
}

nlohmann::json toJson(const Summary& s)
{
    return {{"median", s.median}, {"p10", s.p10}, {"p90", s.p90}, {"mean", s.mean}, {"min", s.min}, {"max", s.max}};
}

} // namespace

int runBench(const BenchArgs& args)
{
    if (args.frames < 1) throw Error("--frames must be at least 1");
    if (args.frame.allCameras) throw Error("--camera all is for render (one image per camera); bench times one view: give an index");
    nlohmann::json results = nlohmann::json::array();
    std::string rendererName;
    std::vector<std::pair<std::string, std::vector<PassSummary>>> passTables;
    std::vector<std::string> clusterLines;
    const double processStartMs = msSinceProcessStart();
    for (size_t i = 0; i < args.scenes.size(); ++i) {
        const std::string& name = args.scenes[i];
        // Start-up: a fresh context, the scene built or loaded, the environment baked (cold:
        // an empty bake cache) or read from the cache (warm), uploaded, shaders compiled, first
        // frame finished. The first scene's cold figure also counts process launch.
        const std::filesystem::path cache =
            std::filesystem::temp_directory_path() / ("specula-bench-cache-" + std::to_string(::getpid()));
        std::filesystem::remove_all(cache);
        struct Started {
            std::unique_ptr<platform::Context> context;
            std::unique_ptr<render::Renderer> renderer;
            scene::SceneDocument document;
            render::FrameSettings settings;
            render::View view;
            double ms = 0, contextMs = 0, loadMs = 0;
            render::BakeReport bake;
            bool environment = false;
        };
        auto start = [&]() {
            Started s;
            Stopwatch startup;
            s.context = platform::Context::createHeadless({.debug = false});
            s.contextMs = startup.elapsedMs();
            s.document = setup::loadSceneOrBuiltin(name, args.frame.load, args.frame.lights);
            s.settings = setup::resolveSettings(s.document, args.frame);
            const auto environment = setup::loadEnvironment(s.document, args.frame);
            s.environment = environment.has_value();
            const setup::AnimationChoice animation = setup::resolveAnimation(s.document.scene, args.frame);
            s.view = setup::prepareView(s.document, args.frame, s.settings, nullptr, s.environment, animation);
            s.loadMs = startup.elapsedMs() - s.contextMs;
            s.renderer = std::make_unique<render::Renderer>();
            s.renderer->setCacheDirectory(cache);
            s.renderer->setScene(s.document.scene);
            s.renderer->setPose(animation.index, animation.seconds);
            s.renderer->setVariant(setup::resolveVariant(s.document.scene, args.frame));
            if (environment) s.bake = s.renderer->setEnvironment(*environment, setup::resolveBakeSettings(args.frame), cache);
            s.renderer->render(s.view, s.settings);
            glFinish();
            s.ms = startup.elapsedMs();
            return s;
        };
        Started cold = start();
        const double sinceLaunchMs = i == 0 ? msSinceProcessStart() : -1.0;
        const bool hasEnvironment = cold.environment;
        const double bakeMs = cold.bake.milliseconds;
        const double coldMs = cold.ms;
        double warmMs = coldMs;
        if (hasEnvironment) {
            // GL objects go before their context.
            cold.renderer.reset();
            cold.context.reset();
            cold = start(); // the same cache directory: the bake is read back
            warmMs = cold.ms;
        }
        std::filesystem::remove_all(cache);
        Started& s = cold;
        render::Renderer& renderer = *s.renderer;
        const render::FrameSettings& settings = s.settings;
        const render::View& view = s.view;
        scene::SceneDocument& document = s.document;
        const double startupMs = coldMs, contextMs = s.contextMs, loadMs = s.loadMs;
        if (rendererName.empty()) rendererName = gl::queryDeviceInfo().renderer;

        for (int w = 0; w < args.warmup; ++w) renderer.render(view, settings);
        glFinish();
        renderer.setGpuTiming(true);
        std::vector<double> cpu, gpu;
        std::map<std::string, std::vector<double>> passes;
        PassTimes passTimes;
        for (int f = 0; f < args.frames; ++f) {
            Stopwatch frame;
            renderer.render(view, settings); // waits for the timer queries, so the GPU is done
            glFinish();
            cpu.push_back(frame.elapsedMs());
            double total = 0;
            for (const auto& pass : renderer.stats().passes) {
                passes[pass.name].push_back(pass.gpuMs);
                total += pass.gpuMs;
            }
            gpu.push_back(total);
        }
        // Pass by pass, once more: the wall clock drains the GPU around every pass, which
        // would distort the frame times above.
        renderer.setPassWallClock(true);
        for (int f = 0; f < args.frames; ++f) {
            renderer.render(view, settings);
            passTimes.add(renderer.stats());
        }
        renderer.setPassWallClock(false);
        const std::vector<PassSummary> passMedians = passTimes.medians();
        const render::FrameStats::Clusters clusters = renderer.stats().clusters;
        nlohmann::json passWallJson;
        for (const PassSummary& pass : passMedians) passWallJson[pass.name] = pass.wallMs;
        passTables.emplace_back(fmt::format("{} ({}x{}x{}, {} light{}, {} of {} triangles drawn): time per pass, median of {} frames:",
                                            name, settings.width, settings.height, settings.msaa, renderer.lightCount(),
                                            renderer.lightCount() == 1 ? "" : "s", renderer.stats().triangles,
                                            document.scene.triangleCount(), args.frames),
                                passMedians);
        clusterLines.push_back(clusterStatsLine(clusters));
        const Summary cpuSummary = summarize(cpu), gpuSummary = summarize(gpu);
        nlohmann::json passJson;
        for (const auto& [pass, values] : passes) passJson[pass] = toJson(summarize(values));
        results.push_back({{"scene", name},
                           {"width", settings.width},
                           {"height", settings.height},
                           {"msaa", settings.msaa},
                           {"triangles", document.scene.triangleCount()},
                           {"trianglesDrawn", renderer.stats().triangles},
                           {"drawCalls", renderer.stats().drawCalls},
                           {"startupMs", startupMs},
                           {"environment", hasEnvironment},
                           {"bakeColdMs", hasEnvironment ? bakeMs : 0.0},
                           {"startupWarmMs", warmMs},
                           {"startupContextMs", contextMs},
                           {"startupLoadMs", loadMs},
                           {"sinceLaunchMs", sinceLaunchMs},
                           {"frames", args.frames},
                           {"frameCpuMs", toJson(cpuSummary)},
                           {"frameGpuMs", toJson(gpuSummary)},
                           {"fps", 1000.0 / cpuSummary.median},
                           {"passesGpuMs", passJson},
                           {"passesWallMedianMs", passWallJson},
                           {"lights", renderer.lightCount()},
                           {"clusters",
                            {{"grid", {clusters.tilesX, clusters.tilesY, clusters.slices}},
                             {"lightsInView", clusters.lightsInView},
                             {"directional", clusters.directional},
                             {"maxPerCluster", clusters.maxPerCluster},
                             {"meanPerCluster", clusters.meanPerCluster},
                             {"entries", clusters.entries}}}});
        log::info("{}: start-up {:.0f} ms, frame median {:.2f} ms", name, startupMs, cpuSummary.median);
    }
    (void)processStartMs;

    nlohmann::json document = {{"renderer", rendererName}, {"results", results}};
    std::ofstream out(args.output);
    if (!out) throw Error("cannot write {}", args.output);
    out << document.dump(2) << "\n";

    std::printf("renderer: %s\n", rendererName.c_str());
    std::printf("%-16s %10s %9s %9s %9s %13s %13s %11s %7s\n", "scene", "size", "bake", "cold", "warm", "frame median",
                "frame p10-p90", "GPU median", "fps");
    for (const auto& r : results) {
        const std::string size = std::to_string(r["width"].get<int>()) + "x" + std::to_string(r["height"].get<int>()) + "x" +
                                 std::to_string(r["msaa"].get<int>());
        const std::string spread = fmt::format("{:.1f}-{:.1f}", r["frameCpuMs"]["p10"].get<double>(), r["frameCpuMs"]["p90"].get<double>());
        std::printf("%-16s %10s %6.0f ms %6.0f ms %6.0f ms %10.2f ms %10s ms %8.2f ms %7.1f\n", r["scene"].get<std::string>().c_str(),
                    size.c_str(), r["bakeColdMs"].get<double>(), r["startupMs"].get<double>(), r["startupWarmMs"].get<double>(),
                    r["frameCpuMs"]["median"].get<double>(), spread.c_str(), r["frameGpuMs"]["median"].get<double>(),
                    r["fps"].get<double>());
    }
    for (size_t i = 0; i < passTables.size(); ++i) {
        printPassTable(passTables[i].first, passTables[i].second);
        if (!clusterLines[i].empty()) std::printf("%s\n", clusterLines[i].c_str());
    }
    std::printf("wrote %s\n", args.output.c_str());
    return 0;
}

} // namespace specula::cli
