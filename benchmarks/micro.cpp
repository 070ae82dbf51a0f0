// CPU-side micro-benchmarks (Google Benchmark): the work Specula does before the GPU sees
// anything. GPU frame and start-up times are measured by `specula bench`.
#include <benchmark/benchmark.h>

#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "shading/EnvironmentMap.h"
#include "scene/DoomPalette.h"
#include "scene/GltfImporter.h"
#include "scene/Pose.h"
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

/// CPU skinning (and a morph target) of DamagedHelmet-sized data, as GpuScene::setPose runs it
/// per pose: the helmet's one primitive given 4 (arg 4) or 8 influences per vertex on 4 joints,
/// plus, with arg 1 of the second argument, one POSITION+NORMAL morph target at weight 0.5.
static void BM_DeformDamagedHelmet(benchmark::State& state)
{
    const std::string path = kAssets + "/models/DamagedHelmet/DamagedHelmet.glb";
    if (!std::filesystem::exists(path)) {
        state.SkipWithError("shared assets missing");
        return;
    }
    scene::Primitive p = scene::loadGltf(path).meshes[0].primitives[0];
    const size_t n = p.vertices.size();
    p.influences = int(state.range(0));
    p.joints.resize(n * size_t(p.influences));
    p.weights.resize(n * size_t(p.influences));
    for (size_t i = 0; i < p.joints.size(); ++i) {
        p.joints[i] = uint16_t(i % 4);
        p.weights[i] = 1.0f / float(p.influences);
    }
    if (state.range(1)) {
        scene::MorphTarget target;
        target.positions.assign(n, glm::vec3(0.01f));
        target.normals.assign(n, glm::vec3(0.0f, 0.1f, 0.0f));
        p.targets.push_back(target);
    }
    std::vector<glm::mat4> joints(4);
    for (int j = 0; j < 4; ++j) joints[size_t(j)] = glm::rotate(glm::mat4(1.0f), 0.1f * float(j), glm::vec3(0, 1, 0));
    std::vector<scene::Vertex> out;
    scene::Bounds bounds;
    for (auto _ : state) {
        scene::deformPrimitive(p, joints, {0.5f}, out, bounds);
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(n));
}
BENCHMARK(BM_DeformDamagedHelmet)->Args({4, 0})->Args({8, 0})->Args({4, 1})->Unit(benchmark::kMillisecond);

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
