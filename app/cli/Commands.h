#pragma once
#include <string>

#include "SceneSetup.h"

namespace specula::cli {

struct RenderArgs {
    std::string scene;
    std::string output = "out.png";
    FrameOptions frame;
};

struct BenchArgs {
    std::vector<std::string> scenes{"demo", "learnopengl", "learnopengl-ibl"};
    std::string output = "bench.json";
    int frames = 60;
    int warmup = 5;
    FrameOptions frame;
};

struct BakeArgs {
    std::string env;
    std::string preset = "default";
    std::string cacheDirectory;
};

int runRender(const RenderArgs& args);
int runBake(const BakeArgs& args);
int runInfo();
int runBench(const BenchArgs& args);

} // namespace specula::cli
