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
    std::vector<std::string> scenes{"demo", "learnopengl"};
    std::string output = "bench.json";
    int frames = 60;
    int warmup = 5;
    FrameOptions frame;
};

int runRender(const RenderArgs& args);
int runInfo();
int runBench(const BenchArgs& args);

} // namespace specula::cli
