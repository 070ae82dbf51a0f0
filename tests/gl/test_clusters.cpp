// Clustered forward shading (docs/clustered-shading.md): the clustered frame against the
// brute-force frame (every light at every pixel, the same effective ranges), the GPU's cluster
// lists against the CPU twin of the culling (shading/LightClusters), 0, 1 and 65,536 lights,
// and the error the light cutoff makes.
#include "GlTestContext.h"
#include "RadianceFrame.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "render/FrameContext.h"
#include "render/LightBuffer.h"
#include "render/Renderer.h"
#include "render/graph/GlGraphBackend.h"
#include "render/passes/LightCullPass.h"
#include "scene/BuiltinScenes.h"
#include "scene/DemoScenes.h"
#include "scene/Procedural.h"
#include "shading/LightClusters.h"

using namespace specula;
using specula::test::GlTest;

namespace {

constexpr float kNear = 0.1f, kFar = 60.0f;

render::View testView(float aspect)
{
    return render::lookAtView({0.0f, 3.0f, 12.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, glm::radians(55.0f), aspect, kNear, kFar);
}

/// 1,000 lights, every kind of trouble for culling: random ranges (and none: the cutoff's),
/// spots of random cones (up to 90°), lights straddling the near plane, behind the camera,
/// larger than the view, far beyond it; a few directional ones first (the clustered lists
/// put them first too, so both frames sum in the same order).
std::vector<render::PlacedLight> randomLights(uint32_t seed, int count)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const glm::vec3 eye(0.0f, 3.0f, 12.0f);
    std::vector<render::PlacedLight> lights;
    for (int i = 0; i < count; ++i) {
        render::PlacedLight p;
        scene::Light& l = p.light;
        l.color = glm::vec3(0.2f + u(rng), 0.2f + u(rng), 0.2f + u(rng));
        l.intensity = 0.5f + 4.0f * u(rng);
        const float kind = u(rng);
        const float where = u(rng);
        if (i < 4) {
            l.type = scene::Light::Type::Directional;
            l.intensity = 0.2f;
            p.direction = glm::normalize(glm::vec3(u(rng) - 0.5f, -1.0f, u(rng) - 0.5f));
            lights.push_back(p);
            continue;
        }
        l.type = kind < 0.5f ? scene::Light::Type::Point : scene::Light::Type::Spot;
        l.range = u(rng) < 0.1f ? 0.0f : 0.5f + 6.0f * u(rng) * u(rng);
        if (where < 0.6f) {
            p.position = glm::vec3(-9.0f + 18.0f * u(rng), 0.1f + 4.0f * u(rng), -20.0f + 30.0f * u(rng));
        } else if (where < 0.75f) {
            // Straddling the near plane: within a range of the eye.
            p.position = eye + glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f) * 0.6f;
            l.range = 0.3f + 3.0f * u(rng);
        } else if (where < 0.9f) {
            // Behind the camera, some reaching into the view.
            p.position = eye + glm::vec3(8.0f * (u(rng) - 0.5f), 4.0f * (u(rng) - 0.5f), 0.5f + 6.0f * u(rng));
        } else if (where < 0.95f) {
            // Larger than the view.
            p.position = glm::vec3(-5.0f + 10.0f * u(rng), 1.0f + 3.0f * u(rng), -5.0f + 10.0f * u(rng));
            l.range = 60.0f + 200.0f * u(rng);
            l.intensity = 0.05f;
        } else {
            // Far off to the side or beyond the far plane.
            p.position = glm::vec3(80.0f * (u(rng) - 0.5f), 2.0f, -40.0f - 60.0f * u(rng));
        }
        const float outer = glm::radians(5.0f + 85.0f * u(rng));
        l.outerConeAngle = outer;
        l.innerConeAngle = outer * u(rng);
        p.direction = glm::normalize(glm::vec3(u(rng) - 0.5f, -u(rng), u(rng) - 0.5f));
        lights.push_back(p);
    }
    return lights;
}

/// A floor and a few spheres and boxes at many depths, filling the view.
scene::Scene testScene()
{
    scene::Scene s;
    scene::Material m;
    m.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.6f;
    scene::addShape(s, scene::makePlane(200.0f), m, glm::mat4(1.0f), "floor");
    for (int i = 0; i < 6; ++i) {
        scene::Material sm = m;
        sm.metallicFactor = float(i % 2);
        sm.roughnessFactor = 0.3f + 0.1f * float(i);
        const glm::vec3 at(-6.0f + 2.5f * float(i), 1.0f, 4.0f - 5.0f * float(i));
        scene::addShape(s, scene::makeUvSphere(1.0f, 24, 24), sm, glm::translate(glm::mat4(1.0f), at), "sphere");
        scene::addShape(s, scene::makeCube(0.6f), sm, glm::translate(glm::mat4(1.0f), at + glm::vec3(3.0f, -0.4f, 1.0f)), "box");
    }
    // A wall far back, so that deep slices have surfaces too.
    scene::addShape(s, scene::makePlane(200.0f), m,
                    glm::rotate(glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -45.0f}), glm::half_pi<float>(), {1.0f, 0.0f, 0.0f}),
                    "wall");
    return s;
}

render::FrameSettings frameSettings(int width, int height)
{
    render::FrameSettings s = test::radianceFrame(width, height);
    s.shadows.enabled = false;
    s.energyCompensation = false;
    s.ambient = glm::vec3(0.0f);
    return s;
}

struct Comparison {
    double maxRelative = 0.0; ///< largest |clustered − brute| / max(|brute|, floor) over channels
    int differing = 0;        ///< channels beyond the tolerance
    int lit = 0;              ///< channels the lights reach at all
};

// Float tolerance: both frames add the same nonzero terms in the same order, so they agree to
// the last bit where the programs round alike; 1e-3 relative (half floats hold 5e-4) leaves
// room for the two programs' different instruction selection, nothing for a missing light.
constexpr double kTolerance = 1e-3;

Comparison compare(const ImageFloat& clustered, const ImageFloat& brute)
{
    Comparison c;
    for (size_t i = 0; i < brute.pixels.size(); ++i) {
        if (i % 4 == 3) continue;
        const double a = clustered.pixels[i], b = brute.pixels[i];
        if (b > 1e-6) ++c.lit;
        const double relative = std::abs(a - b) / std::max(std::abs(b), 1e-3);
        c.maxRelative = std::max(c.maxRelative, relative);
        if (relative > kTolerance) ++c.differing;
    }
    return c;
}

ImageFloat renderWith(render::Renderer& renderer, const render::View& view, render::FrameSettings settings, render::LightCulling culling)
{
    settings.lightCulling = culling;
    renderer.render(view, settings);
    return renderer.readRadiance();
}

} // namespace

// The clustered frame equals the brute-force frame for random scenes of 1,000 lights, at
// several sizes (odd ones too: the last tile row and column are partial), under every
// reflection model that reads lights; with every cluster's box shrunk to half its size the frames
// differ (the comparison can tell a culling that drops lights).
TEST_F(GlTest, ClusteredFrameEqualsBruteForce)
{
    const std::pair<int, int> sizes[] = {{160, 90}, {97, 61}, {53, 128}, {211, 37}};
    uint32_t seed = 1;
    for (const auto& [width, height] : sizes) {
        render::Renderer renderer;
        renderer.setScene(testScene());
        renderer.setLights(randomLights(seed++, 1000));
        const render::View view = testView(float(width) / float(height));
        const render::FrameSettings settings = frameSettings(width, height);
        const ImageFloat brute = renderWith(renderer, view, settings, render::LightCulling::None);
        const ImageFloat clustered = renderWith(renderer, view, settings, render::LightCulling::Clustered);
        const render::FrameStats::Clusters stats = renderer.stats().clusters;
        const Comparison c = compare(clustered, brute);
        EXPECT_EQ(c.differing, 0) << width << "x" << height << ": max relative difference " << c.maxRelative;
        std::printf("%dx%d: clustered vs brute force, max relative difference %.3g; %d lights in view, mean %.1f per cluster\n",
                    width, height, c.maxRelative, stats.lightsInView, stats.meanPerCluster);
        EXPECT_GT(c.lit, int(brute.pixels.size() / 2)) << "the lights must reach most of the frame";
        EXPECT_GT(stats.lightsInView, 100) << width << "x" << height;
        EXPECT_LT(stats.lightsInView, 1000 - 4) << "lights far off must be culled";
        EXPECT_EQ(stats.directional, 4);
        EXPECT_LT(stats.meanPerCluster, double(stats.lightsInView)) << "clusters must cull";

        // Shrunk boxes miss lights that reach their clusters: the frames must differ.
        renderer.setClusterShrinkForTesting(0.5f);
        const Comparison shrunk = compare(renderWith(renderer, view, settings, render::LightCulling::Clustered), brute);
        EXPECT_GT(shrunk.differing, 10) << width << "x" << height << ": shrunk boxes must drop lights (max " << shrunk.maxRelative << ")";
        std::printf("  boxes shrunk by half: %d channels differ, by up to %.3g\n", shrunk.differing, shrunk.maxRelative);
        renderer.setClusterShrinkForTesting(0.0f);
    }

    // The classic models read the same lists: Phong per pixel, Gouraud per vertex (a vertex
    // projects to its cluster; one outside the view gets every light).
    for (const scene::ShadingModel model : {scene::ShadingModel::Phong, scene::ShadingModel::Gouraud}) {
        render::Renderer renderer;
        renderer.setScene(testScene());
        renderer.setLights(randomLights(99, 1000));
        render::FrameSettings settings = frameSettings(120, 70);
        settings.materialOverride.model = model;
        const render::View view = testView(120.0f / 70.0f);
        const ImageFloat brute = renderWith(renderer, view, settings, render::LightCulling::None);
        const Comparison c = compare(renderWith(renderer, view, settings, render::LightCulling::Clustered), brute);
        EXPECT_EQ(c.differing, 0) << scene::shadingModelName(model) << ": max relative difference " << c.maxRelative;
        renderer.setClusterShrinkForTesting(0.5f);
        const Comparison shrunk = compare(renderWith(renderer, view, settings, render::LightCulling::Clustered), brute);
        EXPECT_GT(shrunk.differing, 10) << scene::shadingModelName(model) << ": shrunk boxes must drop lights";
    }
}

namespace {

/// Runs the culling pass alone for `lights` seen by `view` at width × height.
struct CullRun {
    render::FrameStores stores;
    render::GlGraphBackend backend{stores.state};
    render::LightCullPass pass;

    void run(const std::vector<render::PlacedLight>& lights, const render::View& view, int width, int height)
    {
        stores.lights.setAll(lights);
        cull(view, width, height);
    }

    /// The pass on the lights already set.
    void cull(const render::View& view, int width, int height)
    {
        render::FrameSettings settings = frameSettings(width, height);
        render::FrameStats stats;
        const render::FrameContext frame{view, settings, width, height, 1, 1.0f, stores, backend, stats};
        render::FrameGraph graph;
        pass.addTo(graph, frame);
        graph.compile();
        backend.beginFrame(graph);
        graph.execute(backend);
        backend.endFrame();
    }
};

/// Whether light `c` and cluster box `b` are within rounding of the test's edge: it decides
/// differently for the box grown and shrunk by 10⁻⁴ of its size (or the sphere against the frustum).
bool borderline(const shared::CullLight& c, const shared::ClusterBounds& b)
{
    const glm::vec4 pad = (b.hi - b.lo) * 1e-4f + 1e-5f;
    const shared::ClusterBounds grown{b.lo - pad, b.hi + pad}, shrunk{b.lo + pad, b.hi - pad};
    return shared::lightTouchesCluster(c, grown) != shared::lightTouchesCluster(c, shrunk);
}

} // namespace

// Each cluster's list holds exactly the lights whose bounds touch its box: the GPU's lists equal
// the CPU twin's (shading/LightClusters.cpp, the same test compiled as C++), but for pairs
// within float rounding of the test's edge, which are counted and must be rare.
TEST_F(GlTest, ClusterListsMatchTheCpuTwin)
{
    const std::pair<int, int> sizes[] = {{160, 90}, {333, 197}, {1280, 720}};
    uint32_t seed = 7;
    for (const auto& [width, height] : sizes) {
        CullRun run;
        const std::vector<render::PlacedLight> lights = randomLights(seed++, 1000);
        const render::View view = testView(float(width) / float(height));
        run.run(lights, view, width, height);

        std::vector<shared::GpuLight> packed;
        for (const render::PlacedLight& p : lights) packed.push_back(render::LightBuffer::pack(p, -1, run.stores.lights.cutoff()));
        const render::ClusterGrid& grid = run.pass.grid();
        ASSERT_EQ(grid, render::ClusterGrid::make(width, height, view.projection));
        const render::ClusterLists expected = render::cullLights(grid, run.pass.bounds(), view.view, view.projection, packed);
        const std::vector<uint32_t> words = run.pass.readWords();
        ASSERT_GE(words.size(), size_t(SPECULA_CLUSTER_HEADER_WORDS + 2 * grid.count()));
        const uint32_t base = words[SPECULA_CLUSTER_WORD_BASE];
        EXPECT_EQ(base, uint32_t(SPECULA_CLUSTER_HEADER_WORDS + 2 * grid.count()));
        ASSERT_EQ(words[SPECULA_CLUSTER_WORD_DIRECTIONAL], expected.directional.size());
        EXPECT_EQ(int(words[SPECULA_CLUSTER_WORD_DIRECTIONAL]), run.stores.lights.directionalCount()) << "the shaders' uniform";
        for (size_t k = 0; k < expected.directional.size(); ++k) EXPECT_EQ(words[base + k], expected.directional[k]);

        // Lights by index, as the culling sees them (for the borderline test).
        std::vector<shared::CullLight> cull(packed.size());
        for (size_t i = 0; i < packed.size(); ++i) cull[i] = render::cullLight(packed[i], view.view, uint32_t(i));

        size_t entries = 0, longest = 0, borderlinePairs = 0;
        for (int k = 0; k < grid.count(); ++k) {
            const uint32_t first = words[size_t(SPECULA_CLUSTER_HEADER_WORDS + 2 * k)];
            const uint32_t count = words[size_t(SPECULA_CLUSTER_HEADER_WORDS + 2 * k + 1)];
            ASSERT_LE(size_t(first) + count, words.size());
            const std::vector<uint32_t> got(words.begin() + first, words.begin() + first + count);
            entries += count;
            longest = std::max<size_t>(longest, count);
            EXPECT_TRUE(std::is_sorted(got.begin(), got.end())) << "cluster " << k << ": lists are in light order";
            const std::vector<uint32_t>& want = expected.clusters[size_t(k)];
            if (got == want) continue;
            // Every difference must be a pair on the edge of the test.
            std::vector<uint32_t> onlyGot, onlyWant;
            std::set_difference(got.begin(), got.end(), want.begin(), want.end(), std::back_inserter(onlyGot));
            std::set_difference(want.begin(), want.end(), got.begin(), got.end(), std::back_inserter(onlyWant));
            for (const uint32_t i : onlyGot) {
                ++borderlinePairs;
                EXPECT_TRUE(borderline(cull[i], run.pass.bounds()[size_t(k)])) << "cluster " << k << " lists light " << i << ", the CPU does not";
            }
            for (const uint32_t i : onlyWant) {
                ++borderlinePairs;
                EXPECT_TRUE(borderline(cull[i], run.pass.bounds()[size_t(k)])) << "cluster " << k << " misses light " << i;
            }
        }
        EXPECT_LE(borderlinePairs, expected.entries() / 1000 + 2) << width << "x" << height;
        EXPECT_NEAR(double(entries), double(expected.entries()), double(borderlinePairs));
        EXPECT_EQ(words[SPECULA_CLUSTER_WORD_ENTRIES], entries);
        EXPECT_EQ(words[SPECULA_CLUSTER_WORD_MAX], longest);
        EXPECT_EQ(run.pass.counts().entries, entries);
        EXPECT_NEAR(double(words[SPECULA_CLUSTER_WORD_VISIBLE]), double(expected.visible), 2.0);
        // The culling culls: far fewer entries than lights × clusters, and some clusters list none.
        EXPECT_LT(entries, size_t(grid.count()) * expected.visible / 4);
        EXPECT_GT(entries, 0u);
    }
}

// A light that gives no light — intensity 0, a black colour, or a hidden node's light (packed
// with intensity 0) — is in no list and not counted in view: the lists are those of the same
// lights all lit, less the dark ones, and the frame still equals brute force.
TEST_F(GlTest, DarkAndHiddenLightsAreInNoList)
{
    const int width = 333, height = 197;
    const render::View view = testView(float(width) / float(height));
    const std::vector<render::PlacedLight> lit = randomLights(13, 600);
    std::vector<render::PlacedLight> dark = lit;
    std::vector<bool> isDark(lit.size(), false);
    for (size_t i = 0; i < dark.size(); ++i) {
        if (dark[i].light.type == scene::Light::Type::Directional || i % 3 != 0) continue;
        isDark[i] = true;
        if (i % 9 == 0) dark[i].light.intensity = 0.0f;
        else if (i % 9 == 3) dark[i].light.color = glm::vec3(0.0f);
        else dark[i].visible = false;
    }
    CullRun litRun, darkRun;
    litRun.run(lit, view, width, height);
    darkRun.run(dark, view, width, height);
    const std::vector<uint32_t> litWords = litRun.pass.readWords(), darkWords = darkRun.pass.readWords();
    const int clusters = litRun.pass.grid().count();
    ASSERT_EQ(darkWords[SPECULA_CLUSTER_WORD_DIRECTIONAL], litWords[SPECULA_CLUSTER_WORD_DIRECTIONAL]);
    size_t darkListed = 0, entries = 0;
    int differing = 0, firstDiffering = -1;
    for (int k = 0; k < clusters; ++k) {
        const auto list = [k](const std::vector<uint32_t>& words) {
            const uint32_t first = words[size_t(SPECULA_CLUSTER_HEADER_WORDS + 2 * k)];
            const uint32_t count = words[size_t(SPECULA_CLUSTER_HEADER_WORDS + 2 * k + 1)];
            return std::vector<uint32_t>(words.begin() + first, words.begin() + first + count);
        };
        std::vector<uint32_t> want;
        for (const uint32_t i : list(litWords)) {
            if (isDark[i]) ++darkListed;
            else want.push_back(i);
        }
        const std::vector<uint32_t> got = list(darkWords);
        entries += got.size();
        if (got == want) continue;
        if (differing++ == 0) firstDiffering = k;
    }
    EXPECT_EQ(differing, 0) << "clusters whose list is not the lit one's less the dark lights, the first " << firstDiffering;
    EXPECT_GT(darkListed, 1000u) << "the dark lights must reach clusters when lit, or the test shows nothing";
    EXPECT_EQ(darkWords[SPECULA_CLUSTER_WORD_ENTRIES], entries);

    // In view: the lit run's count less the dark lights in the frustum (the CPU's sphere test).
    const std::array<glm::vec4, 6> planes = render::viewFrustumPlanes(view.projection);
    int darkInView = 0;
    for (size_t i = 0; i < lit.size(); ++i) {
        if (!isDark[i]) continue;
        const shared::GpuLight packed = render::LightBuffer::pack(lit[i], -1, litRun.stores.lights.cutoff());
        if (render::sphereInFrustum(planes, render::cullLight(packed, view.view, uint32_t(i)).sphere)) ++darkInView;
    }
    EXPECT_GT(darkInView, 50);
    EXPECT_NEAR(double(darkWords[SPECULA_CLUSTER_WORD_VISIBLE]), double(litWords[SPECULA_CLUSTER_WORD_VISIBLE]) - darkInView, 2.0);

    // The CPU twin agrees, and the frame is brute force's.
    std::vector<shared::GpuLight> packed;
    for (const render::PlacedLight& p : dark) packed.push_back(render::LightBuffer::pack(p, -1, darkRun.stores.lights.cutoff()));
    const render::ClusterLists twin = render::cullLights(darkRun.pass.grid(), darkRun.pass.bounds(), view.view, view.projection, packed);
    EXPECT_NEAR(double(twin.visible), double(darkWords[SPECULA_CLUSTER_WORD_VISIBLE]), 2.0);
    for (int k = 0; k < clusters; ++k)
        for (const uint32_t i : twin.clusters[size_t(k)]) EXPECT_FALSE(isDark[i]) << "the CPU twin lists dark light " << i;

    render::Renderer renderer;
    renderer.setScene(testScene());
    renderer.setLights(dark);
    const render::FrameSettings settings = frameSettings(160, 90);
    const render::View small = testView(160.0f / 90.0f);
    const ImageFloat brute = renderWith(renderer, small, settings, render::LightCulling::None);
    const ImageFloat clustered = renderWith(renderer, small, settings, render::LightCulling::Clustered);
    const Comparison c = compare(clustered, brute);
    EXPECT_EQ(c.differing, 0) << c.maxRelative;
    EXPECT_GT(c.lit, 0);
}

// The lists are made again only when a light, the view or the grid changes: a still frame
// keeps them, and after each change they are those a first culling makes.
TEST_F(GlTest, ClusterListsAreKeptWhileNothingChanges)
{
    const int width = 160, height = 90;
    std::vector<render::PlacedLight> lights = randomLights(11, 300);
    const render::View view = testView(float(width) / float(height));
    // The words the lists use (header, records, indices): the buffer's tail is never written.
    const auto used = [](std::vector<uint32_t> words) {
        words.resize(size_t(words[SPECULA_CLUSTER_WORD_BASE]) + words[SPECULA_CLUSTER_WORD_DIRECTIONAL] +
                     words[SPECULA_CLUSTER_WORD_ENTRIES]);
        return words;
    };
    const auto fresh = [&](const std::vector<render::PlacedLight>& l, const render::View& v) {
        CullRun once;
        once.run(l, v, width, height);
        return used(once.pass.readWords());
    };
    CullRun run;
    run.run(lights, view, width, height);
    EXPECT_EQ(run.pass.runs(), 1);
    run.cull(view, width, height);
    run.cull(view, width, height);
    EXPECT_EQ(run.pass.runs(), 1) << "a still frame culls again";
    EXPECT_EQ(used(run.pass.readWords()), fresh(lights, view));

    // One light moved far across the view: the lists change, and are made again.
    lights[5].position += glm::vec3(3.0f, 0.0f, -2.0f);
    run.stores.lights.set(5, lights[5]);
    run.cull(view, width, height);
    EXPECT_EQ(run.pass.runs(), 2);
    const std::vector<uint32_t> moved = fresh(lights, view);
    EXPECT_EQ(used(run.pass.readWords()), moved);

    // The camera turned: made again.
    render::View turned = view;
    turned.view = glm::rotate(view.view, 0.2f, glm::vec3(0.0f, 1.0f, 0.0f));
    run.cull(turned, width, height);
    EXPECT_EQ(run.pass.runs(), 3);
    EXPECT_EQ(used(run.pass.readWords()), fresh(lights, turned));
    EXPECT_NE(used(run.pass.readWords()), moved);

    // Another size: a new grid, made again; the cutoff (every light's range): made again.
    run.cull(turned, width * 2, height);
    EXPECT_EQ(run.pass.runs(), 4);
    run.stores.lights.setCutoff(1e-2f);
    run.cull(turned, width * 2, height);
    EXPECT_EQ(run.pass.runs(), 5);
}

// No lights, one light, and 65,536: each frame equals its brute-force frame, and the lists
// grow past the first buffer's size with a warning rather than being cut short.
TEST_F(GlTest, ZeroOneAndManyLightsCluster)
{
    const render::View view = testView(64.0f / 36.0f);
    const render::FrameSettings settings = frameSettings(64, 36);
    {
        render::Renderer renderer;
        renderer.setScene(testScene());
        renderer.setLights({});
        const ImageFloat brute = renderWith(renderer, view, settings, render::LightCulling::None);
        const ImageFloat clustered = renderWith(renderer, view, settings, render::LightCulling::Clustered);
        EXPECT_EQ(compare(clustered, brute).differing, 0);
        EXPECT_EQ(renderer.stats().clusters.lightsInView, 0);
        EXPECT_EQ(renderer.stats().clusters.entries, 0u);
        EXPECT_EQ(renderer.stats().clusters.maxPerCluster, 0);
    }
    {
        render::Renderer renderer;
        renderer.setScene(testScene());
        render::PlacedLight one;
        one.light.type = scene::Light::Type::Point;
        one.light.intensity = 20.0f;
        one.light.range = 5.0f;
        one.position = {1.0f, 1.5f, 2.0f};
        renderer.setLights({one});
        const ImageFloat brute = renderWith(renderer, view, settings, render::LightCulling::None);
        const ImageFloat clustered = renderWith(renderer, view, settings, render::LightCulling::Clustered);
        const Comparison c = compare(clustered, brute);
        EXPECT_EQ(c.differing, 0) << c.maxRelative;
        EXPECT_GT(c.lit, 0);
        EXPECT_EQ(renderer.stats().clusters.lightsInView, 1);
        EXPECT_EQ(renderer.stats().clusters.maxPerCluster, 1);
    }
    {
        // The many-lights scene with 65,536 lights (a 1 km square), seen from its camera.
        scene::SceneDocument document = *scene::builtinScene("many-lights", 65536);
        render::Renderer renderer;
        renderer.setScene(document.scene);
        ASSERT_EQ(renderer.lightCount(), 65536);
        const render::View camera = render::defaultView(document.scene, -1, 64.0f / 36.0f);
        const ImageFloat brute = renderWith(renderer, camera, settings, render::LightCulling::None);
        const ImageFloat clustered = renderWith(renderer, camera, settings, render::LightCulling::Clustered);
        const Comparison c = compare(clustered, brute);
        EXPECT_EQ(c.differing, 0) << c.maxRelative;
        EXPECT_GT(c.lit, int(brute.pixels.size() / 8));
        const render::FrameStats::Clusters stats = renderer.stats().clusters;
        EXPECT_GT(stats.lightsInView, 200);
        EXPECT_LT(stats.lightsInView, 65536 / 4);

        // 2,000 lights whose ranges span the whole view: every cluster lists all of them, far
        // more entries (7 million) than the first buffer holds (2^20 words). The lists grow
        // and stay exact.
        std::vector<render::PlacedLight> lights = randomLights(5, 2000);
        for (render::PlacedLight& p : lights) {
            if (p.light.type == scene::Light::Type::Directional) continue;
            p.light.type = scene::Light::Type::Point;
            p.light.range = 500.0f;
            p.light.intensity = 1e-3f;
        }
        renderer.setLights(lights);
        const ImageFloat bruteAll = renderWith(renderer, view, settings, render::LightCulling::None);
        const ImageFloat clusteredAll = renderWith(renderer, view, settings, render::LightCulling::Clustered);
        EXPECT_GT(renderer.stats().clusters.entries, size_t(1) << 20);
        const Comparison all = compare(clusteredAll, bruteAll);
        EXPECT_EQ(all.differing, 0) << all.maxRelative;
    }
}

// A few lights that reach the whole view: once a culling has listed (nearly) every light in
// every cluster, the next frames shade with every light (no index each), and the image is the
// same; when a light stops reaching most of the view, the lists come back.
TEST_F(GlTest, EveryLightEverywhereShadesWithoutLists)
{
    const render::View view = testView(64.0f / 36.0f);
    const render::FrameSettings settings = frameSettings(64, 36);
    render::Renderer renderer;
    renderer.setScene(testScene());
    std::vector<render::PlacedLight> lights;
    for (int i = 0; i < 4; ++i) {
        render::PlacedLight p;
        p.light.type = scene::Light::Type::Point;
        p.light.intensity = 30.0f;
        p.position = {-6.0f + 4.0f * float(i), 4.0f, 2.0f}; // no range: 100 m from the cutoff, the whole view
        lights.push_back(p);
    }
    renderer.setLights(lights);
    const ImageFloat brute = renderWith(renderer, view, settings, render::LightCulling::None);
    const ImageFloat first = renderWith(renderer, view, settings, render::LightCulling::Clustered);
    EXPECT_FALSE(renderer.stats().clusters.everyLight) << "the first frame has no culling before it";
    const ImageFloat second = renderWith(renderer, view, settings, render::LightCulling::Clustered);
    EXPECT_TRUE(renderer.stats().clusters.everyLight);
    EXPECT_EQ(renderer.stats().clusters.entries, size_t(4 * renderer.stats().clusters.tilesX * renderer.stats().clusters.tilesY *
                                                        renderer.stats().clusters.slices));
    EXPECT_EQ(compare(first, brute).differing, 0);
    EXPECT_EQ(compare(second, brute).differing, 0);
    // One light now reaches only part of the view: the lists again.
    lights[0].light.range = 3.0f;
    lights[1].light.range = 3.0f;
    renderer.setLights(lights);
    renderWith(renderer, view, settings, render::LightCulling::Clustered);
    const ImageFloat back = renderWith(renderer, view, settings, render::LightCulling::Clustered);
    EXPECT_FALSE(renderer.stats().clusters.everyLight);
    EXPECT_EQ(compare(back, renderWith(renderer, view, settings, render::LightCulling::None)).differing, 0);
}

// A light without a range ends where its illuminance falls to cutoff × its illuminance at
// 1 m; the error that makes (against the infinite light) is below cutoff × that illuminance at
// every pixel, and not nothing (the cutoff does cut).
TEST_F(GlTest, LightCutoffErrorIsBelowTheCutoff)
{
    scene::Scene s;
    scene::Material m;
    m.baseColorFactor = glm::vec4(1.0f);
    m.metallicFactor = 0.0f;
    m.specularFactor = 0.0f; // Lambert only: radiance = E (n·l) / π
    scene::addShape(s, scene::makePlane(100.0f), m, glm::mat4(1.0f), "floor");
    render::Renderer renderer;
    renderer.setScene(s);
    render::PlacedLight light;
    light.light.type = scene::Light::Type::Point;
    light.light.intensity = 50.0f; // cd: 50 lux at 1 m
    light.position = {0.0f, 6.0f, 0.0f};
    renderer.setLights({light});
    const render::View view = render::lookAtView({0.0f, 12.0f, 0.01f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, glm::radians(120.0f),
                                                 1.0f, 0.1f, 100.0f);
    for (const float cutoff : {1e-2f, 4e-3f}) {
        render::FrameSettings settings = frameSettings(96, 96);
        settings.lightCutoff = 0.0f; // infinite
        const ImageFloat infinite = renderWith(renderer, view, settings, render::LightCulling::Clustered);
        settings.lightCutoff = cutoff;
        const ImageFloat cut = renderWith(renderer, view, settings, render::LightCulling::Clustered);
        // The bound on radiance: cutoff × 50 lux × (n·l ≤ 1) / π, plus half-float rounding. The
        // largest error is at the range (n·l there is 6 m / range, 0.6 and 0.38).
        const double bound = double(cutoff) * 50.0 / glm::pi<double>();
        double worst = 0.0;
        for (size_t i = 0; i < cut.pixels.size(); ++i) {
            if (i % 4 == 3) continue;
            const double error = std::abs(double(cut.pixels[i]) - double(infinite.pixels[i]));
            worst = std::max(worst, error - 1e-3 * double(infinite.pixels[i]));
        }
        EXPECT_LE(worst, bound) << "cutoff " << cutoff;
        EXPECT_GT(worst, 0.2 * bound) << "cutoff " << cutoff << ": the range must cut something off";
    }
}
