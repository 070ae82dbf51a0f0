#pragma once
#include <string>

#include "setup/SceneSetup.h"

namespace specula::cli {

struct RenderArgs {
    /// One image per scene (and per camera with --camera all); none: the demo. With more than
    /// one image, `output` names them with {scene} and {camera} (docs/specula.1).
    std::vector<std::string> scenes;
    std::string output = "out.png";
    setup::FrameOptions frame;
    bool stats = false; ///< print the GPU time of each pass (median of kStatsFrames more frames)
    std::string printGraph; ///< write the frame's graph of passes as Graphviz dot here ("-": stdout)
};

constexpr int kStatsFrames = 9;

struct BenchArgs {
    std::vector<std::string> scenes{"demo", "learnopengl", "learnopengl-ibl"};
    std::string output = "bench.json";
    int frames = 60;
    int warmup = 5;
    setup::FrameOptions frame;
};

struct BakeArgs {
    std::string env;
    std::string preset = "default";
    std::string cacheDirectory;
    std::string envSun = "keep"; ///< extract: the map less its sun, the cache entry `--env-sun extract` reads
};

/// specula gallery: one tile per shading model (and BRDF term with `variants`), labelled.
struct GalleryArgs {
    std::string scene;
    std::string output = "gallery.png";
    bool variants = false;
    int columns = 3;
    setup::FrameOptions frame;
};

int runRender(const RenderArgs& args);
int runGallery(const GalleryArgs& args);
int runBake(const BakeArgs& args);
int runInfo();
int runBench(const BenchArgs& args);

} // namespace specula::cli
