// CPU-side micro-benchmarks (Google Benchmark): the work Specula does before the GPU sees
// anything. GPU frame and start-up times are measured by `specula bench`.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "shading/EnvironmentMap.h"
#include "scene/DoomPalette.h"
#include "scene/GltfImporter.h"
#include "scene/Procedural.h"
#include "scene/Tangents.h"

using namespace specula;

namespace {
const std::string kAssets = SPECULA_ASSETS_DIR;
}

static void BM_ProjectSh9(benchmark::State& state)
{
    const render::EnvironmentMap map = render::proceduralSky({}, int(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(render::projectSh9(map));
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(map.texels.size()));
}
BENCHMARK(BM_ProjectSh9)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond);

static void BM_GenerateTangents(benchmark::State& state)
{
    const scene::Primitive sphere = scene::makeUvSphere(1.0f, int(state.range(0)), int(state.range(0)) / 2);
    for (auto _ : state) {
        scene::Primitive p = sphere;
        scene::generateTangents(p);
        benchmark::DoNotOptimize(p.vertices.data());
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(sphere.indices.size() / 3));
}
BENCHMARK(BM_GenerateTangents)->Arg(64)->Arg(256)->Unit(benchmark::kMillisecond);

static void BM_LoadDamagedHelmet(benchmark::State& state)
{
    const std::string path = kAssets + "/models/DamagedHelmet/DamagedHelmet.glb";
    if (!std::filesystem::exists(path)) {
        state.SkipWithError("shared assets missing");
        return;
    }
    for (auto _ : state) benchmark::DoNotOptimize(scene::loadGltf(path));
}
BENCHMARK(BM_LoadDamagedHelmet)->Unit(benchmark::kMillisecond);

static void BM_LoadHdrEnvironment(benchmark::State& state)
{
    const std::string path = kAssets + "/env/venice_1k.hdr";
    if (!std::filesystem::exists(path)) {
        state.SkipWithError("shared assets missing");
        return;
    }
    for (auto _ : state) benchmark::DoNotOptimize(render::loadEnvironmentMap(path));
}
BENCHMARK(BM_LoadHdrEnvironment)->Unit(benchmark::kMillisecond);

// The Doom model's nearest-index table (64³ cells, an exact search of 256 colours each), built
// once per process by scene::doom::colorTables().
static void BM_DoomNearestTable(benchmark::State& state)
{
    const scene::doom::Palette palette = scene::doom::makePalette();
    for (auto _ : state) benchmark::DoNotOptimize(scene::doom::makeNearestTable(palette).data());
    state.SetItemsProcessed(int64_t(state.iterations()) * scene::doom::kNearestCells * scene::doom::kNearestCells *
                            scene::doom::kNearestCells);
}
BENCHMARK(BM_DoomNearestTable)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
