// Golden images: the command line renders fixed scenes and each image is compared with the
// reviewed one in tests/golden/images/, with a mean and an outlier threshold and a written
// reason for each. A failure writes the actual image and a difference image (|Δ| × 8) under
// build/test-output/golden/. Goldens change only on purpose: scripts/update-goldens.sh
// rewrites them (SPECULA_UPDATE_GOLDENS=1), and the new images are looked at before commit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <string>

#include "cli/CliRunner.h"
#include "core/ImageIO.h"

namespace fs = std::filesystem;
using namespace specula;
using specula::test::runCli;

namespace {

const std::string kAssets = SPECULA_ASSETS_DIR;
const std::string kScenes = std::string(SPECULA_SOURCE_DIR) + "/tests/assets"; // the repository's own

struct Golden {
    std::string name;      ///< tests/golden/images/<name>.png
    std::string arguments; ///< for `specula render`, before -o
    /// Thresholds, in 8-bit levels. llvmpipe compiles shaders for the CPU it runs on (vector
    /// width, FMA), so another machine rounds differently: edges of triangles and the
    /// palette's nearest colour can flip for a few pixels, and smooth gradients move by a level.
    /// Measured on the development machine (AMD EPYC, AVX2) against itself limited to SSE4.1
    /// (GALLIUM_OVERRIDE_CPU_CAPS=sse4.1): mean 0.000, worst pixel 9 levels (demo), 0 outliers;
    /// one thread against many (LP_NUM_THREADS=1): identical.
    double meanLevels = 0.5;       ///< mean |Δ| over all channels
    double outlierFraction = 0.002; ///< pixels with a channel off by more than kOutlierLevels
    std::string reason;
};
constexpr int kOutlierLevels = 24;

std::vector<Golden> goldens()
{
    const std::string size = " --width 320 --height 180";
    return {
        {"demo", "demo" + size, 0.5, 0.002,
         "the built-in demo: procedural sky (IBL), five lights of three kinds, billboards, default "
         "tone mapping — any change in shading, image-based light or sprites shows"},
        {"learnopengl", "learnopengl" + size, 0.5, 0.002, "the tutorial's PBR scene: four point lights, Schlick-GGX"},
        {"learnopengl-ibl-lobby", "learnopengl-ibl --env " + kAssets + "/env/lobby_1k.hdr" + size, 0.5, 0.002,
         "the tutorial's IBL scene under a real HDR: the bake (cube, prefilter, SH, DFG) and the skybox"},
        {"DamagedHelmet-venice", kAssets + "/models/DamagedHelmet/DamagedHelmet.glb --env " + kAssets +
                                     "/env/venice_1k.hdr" + size,
         0.5, 0.002, "a textured glTF model (all five maps) under an HDR"},
        {"demo-post", "demo --bloom on --ssao on --fxaa on --auto-exposure on" + size, 0.75, 0.004,
         "the post-processing chain; automatic exposure adapts from a histogram, so a level's "
         "rounding anywhere can move the whole frame a little more than a plain render"},
        {"demo-blinn-phong", "demo --shading blinn-phong" + size, 0.5, 0.002, "a classic shading model on the same scene"},
        {"DamagedHelmet-normals", kAssets + "/models/DamagedHelmet/DamagedHelmet.glb --debug-view normal" + size, 0.5, 0.002,
         "world-space normals after normal mapping: tangents, handedness and the normal texture"},
        {"doom-pbr", "doom --shading pbr" + size, 0.5, 0.002,
         "the Doom level lit by its lamps' point lights with the physically based model: textures "
         "without filtering, cutout sprites, no environment"},
        {"ShadowsDirectional", kAssets + "/models/ShadowsDirectional/shadows-directional.gltf --env-color 0.1,0.1,0.1" + size, 0.5,
         0.002, "the sun's cascaded shadow maps on the model made to show them (its glTF camera and light), PCF"},
        {"ShadowsSpot", kAssets + "/models/ShadowsSpot/shadows-spot.gltf --env-color 0.1,0.1,0.1" + size, 0.5, 0.002,
         "a spot light's shadow map: the sphere's shadow inside the cone's lit disc, the cone's wedge"},
        {"transmission", kScenes + "/transparency/transmission.json" + size, 0.5, 0.002,
         "transparent surfaces (docs/transparency.md): a volume of amber glass (KHR_materials_volume), a "
         "frosted thin pane, a refracting glass ball and a clear blended shell that keeps its highlight"},
        {"transmission-oit", kScenes + "/transparency/transmission.json --transparency oit" + size, 0.5, 0.002,
         "the same with weighted blended order-independent transparency for the blended shell"},
        {"doom", "doom" + size, 1.0, 0.01,
         "Doom's 8-bit frame: a colour that rounds differently picks a neighbouring palette entry, "
         "a jump of several levels, so more outliers are allowed than for smooth images"},
    };
}

// gtest prints a failing parameter: its name, not its bytes.
void PrintTo(const Golden& g, std::ostream* os) { *os << g.name; }

fs::path goldenPath(const std::string& name) { return fs::path(SPECULA_GOLDEN_DIR) / (name + ".png"); }

} // namespace

class GoldenTest : public ::testing::TestWithParam<Golden> {};

TEST_P(GoldenTest, MatchesTheReviewedImage)
{
    const Golden& g = GetParam();
    const fs::path outDir = fs::path(SPECULA_TEST_OUTPUT_DIR) / "golden";
    fs::create_directories(outDir);
    const fs::path actualPath = outDir / (g.name + "-actual.png");
    // --no-cache: every run bakes, as a fresh machine does.
    const auto r = runCli("render " + g.arguments + " --no-cache -o " + actualPath.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const ImageRGBA8 actual = readPng(actualPath);

    const char* update = std::getenv("SPECULA_UPDATE_GOLDENS");
    if (update && std::string(update) == "1") {
        writePng(goldenPath(g.name), actual);
        std::printf("  wrote %s: look at it before committing\n", goldenPath(g.name).c_str());
        return;
    }
    ASSERT_TRUE(fs::exists(goldenPath(g.name))) << goldenPath(g.name) << " is missing (scripts/update-goldens.sh makes it)";
    const ImageRGBA8 expected = readPng(goldenPath(g.name));
    ASSERT_EQ(actual.width, expected.width);
    ASSERT_EQ(actual.height, expected.height);

    ImageRGBA8 diff = actual;
    double sum = 0.0;
    size_t outliers = 0;
    int worst = 0;
    for (size_t p = 0; p < actual.pixels.size(); p += 4) {
        int pixelWorst = 0;
        for (size_t c = 0; c < 3; ++c) {
            const int d = std::abs(int(actual.pixels[p + c]) - int(expected.pixels[p + c]));
            sum += d;
            pixelWorst = std::max(pixelWorst, d);
            diff.pixels[p + c] = uint8_t(std::min(255, d * 8));
        }
        diff.pixels[p + 3] = 255;
        outliers += pixelWorst > kOutlierLevels;
        worst = std::max(worst, pixelWorst);
    }
    const size_t pixels = actual.pixels.size() / 4;
    const double mean = sum / double(pixels * 3), fraction = double(outliers) / double(pixels);
    std::printf("  %s: mean |diff| %.3f levels, %zu pixels (%.3f%%) off by more than %d, worst %d\n", g.name.c_str(), mean,
                outliers, 100.0 * fraction, kOutlierLevels, worst);
    const bool ok = mean <= g.meanLevels && fraction <= g.outlierFraction;
    if (!ok) writePng(outDir / (g.name + "-diff.png"), diff);
    EXPECT_LE(mean, g.meanLevels) << g.name << " (" << g.reason << "); see " << (outDir / (g.name + "-diff.png"));
    EXPECT_LE(fraction, g.outlierFraction) << g.name << " (" << g.reason << "); see " << (outDir / (g.name + "-diff.png"));
    if (ok) fs::remove(actualPath);
}

INSTANTIATE_TEST_SUITE_P(Scenes, GoldenTest, ::testing::ValuesIn(goldens()),
                         [](const ::testing::TestParamInfo<Golden>& info) {
                             std::string name = info.param.name;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });
