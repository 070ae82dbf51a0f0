// Bloom (render/BloomPass) on synthetic HDR images read back as floats: energy conservation,
// symmetry, no NaN or Inf, odd sizes; and through the Renderer: off = unchanged frame.
#include "GlTestContext.h"

#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/State.h"
#include "gl/Texture.h"
#include "render/passes/BloomPass.h"
#include "render/Renderer.h"
#include "scene/Procedural.h"

using namespace specula;
using specula::test::GlTest;

namespace {

/// An RGBA16F image, black but for `pixels` (x, y, value in all three colour channels).
struct Spot {
    int x, y;
    float value;
};

gl::Texture makeHdr(int width, int height, const std::vector<Spot>& spots, float background = 0.0f)
{
    gl::TextureDesc desc;
    desc.width = width;
    desc.height = height;
    desc.format = gl::Format::RGBA16F;
    desc.label = "test hdr";
    gl::Texture texture(desc);
    std::vector<float> pixels(size_t(width) * size_t(height) * 4, background);
    for (size_t i = 3; i < pixels.size(); i += 4) pixels[i] = 1.0f;
    for (const Spot& s : spots)
        for (int c = 0; c < 3; ++c) pixels[(size_t(s.y) * size_t(width) + size_t(s.x)) * 4 + size_t(c)] = s.value;
    texture.upload(0, 0, 4, gl::PixelType::Float, pixels.data());
    return texture;
}

double sumChannel(const std::vector<float>& pixels, int channel)
{
    double sum = 0.0;
    for (size_t i = size_t(channel); i < pixels.size(); i += 4) sum += pixels[i];
    return sum;
}

bool allFinite(const std::vector<float>& pixels)
{
    for (float v : pixels)
        if (!std::isfinite(v)) return false;
    return true;
}

BloomSettings conserving(float intensity, int levels)
{
    BloomSettings s;
    s.enabled = true;
    s.intensity = intensity;
    s.levels = levels;
    s.fireflyFilter = false; // Karis's average takes energy from isolated pixels by design
    return s;
}

} // namespace

TEST_F(GlTest, BloomOfOnePixelConservesEnergy)
{
    // Total added energy = intensity × input, within 1%, for several level counts and sizes,
    // odd ones included. (Intensities are large enough that half-float rounding of the bright
    // pixel plus its own glow, ±1/32 at 100, stays well below 1% of the added energy.)
    struct Case {
        int width, height, levels;
        float intensity;
    };
    for (const Case c : {Case{256, 256, 5, 0.1f}, Case{640, 480, 6, 0.25f}, Case{255, 193, 4, 0.5f},
                         Case{1023, 577, 8, 0.2f}}) {
        gl::State state;
        render::BloomPass bloom;
        const float value = 100.0f;
        gl::Texture hdr = makeHdr(c.width, c.height, {{c.width / 2, c.height / 2, value}});
        bloom.apply(state, hdr, conserving(c.intensity, c.levels), 1.0f);
        const auto out = hdr.readFloat(0, 4);
        ASSERT_TRUE(allFinite(out));
        for (int ch = 0; ch < 3; ++ch) {
            const double added = sumChannel(out, ch) - value;
            EXPECT_NEAR(added / (c.intensity * value), 1.0, 0.01)
                << c.width << "x" << c.height << " levels " << c.levels << " channel " << ch;
        }
        EXPECT_EQ(debug().errorCount(), 0);
    }
}

TEST_F(GlTest, BloomOfOnePixelIsRadiallySymmetric)
{
    // A 2×2 block at the centre of a 256² image is centred on a texel corner of every level,
    // so each filter sees it symmetrically: the glow is exactly symmetric under the square's
    // 8 symmetries. Along the axes and the diagonals at equal radius it must also agree, to
    // the extent square filters are round.
    const int size = 256, c = size / 2;
    gl::State state;
    render::BloomPass bloom;
    gl::Texture hdr = makeHdr(size, size, {{c - 1, c - 1, 50.0f}, {c, c - 1, 50.0f}, {c - 1, c, 50.0f}, {c, c, 50.0f}});
    bloom.apply(state, hdr, conserving(1.0f, 6), 1.0f, /*glowOnly*/ true);
    const auto out = hdr.readFloat(0, 4);
    auto at = [&](int x, int y) { return out[(size_t(y) * size + size_t(x)) * 4]; };
    // Offsets from the centre point c (between pixels c - 1 and c): pixel c + d and c - 1 - d.
    for (int d = 0; d < 100; d += 3) {
        for (int e = 0; e <= d; e += 7) {
            const float v = at(c + d, c + e);
            const float relative = 1e-3f * v + 1e-6f;
            EXPECT_NEAR(at(c - 1 - d, c + e), v, relative) << d << "," << e;
            EXPECT_NEAR(at(c + d, c - 1 - e), v, relative) << d << "," << e;
            EXPECT_NEAR(at(c + e, c + d), v, relative) << d << "," << e; // the diagonal mirror
            EXPECT_NEAR(at(c - 1 - e, c - 1 - d), v, relative) << d << "," << e;
        }
    }
    // Isotropy: at radius r along an axis and along a diagonal (bilinear between pixels).
    auto sample = [&](float fx, float fy) {
        const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
        const float tx = fx - float(x0), ty = fy - float(y0);
        return (1 - tx) * (1 - ty) * at(x0, y0) + tx * (1 - ty) * at(x0 + 1, y0) + (1 - tx) * ty * at(x0, y0 + 1) +
               tx * ty * at(x0 + 1, y0 + 1);
    };
    const float centre = float(c) - 0.5f; // pixel-centre coordinates of the block's centre
    for (float radius : {4.0f, 8.0f, 16.0f, 32.0f, 64.0f}) {
        const float axis = sample(centre + radius, centre);
        const float diagonal = sample(centre + radius / std::sqrt(2.0f), centre + radius / std::sqrt(2.0f));
        EXPECT_NEAR(diagonal / axis, 1.0f, 0.15f) << "radius " << radius;
    }
}

TEST_F(GlTest, BloomOfASinglePixelIsCentredAndRound)
{
    // One pixel (not a block) is not centred on the levels' texel corners, so the symmetry is
    // only approximate: the glow's centroid stays within half a pixel of it, and at equal
    // distance in the four axis directions and the four diagonal ones the glow agrees within
    // 15% of its mean there.
    const int size = 256, c = 128;
    gl::State state;
    render::BloomPass bloom;
    gl::Texture hdr = makeHdr(size, size, {{c, c, 100.0f}});
    bloom.apply(state, hdr, conserving(1.0f, 6), 1.0f, /*glowOnly*/ true);
    const auto out = hdr.readFloat(0, 4);
    double sum = 0, sx = 0, sy = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double v = out[(size_t(y) * size + size_t(x)) * 4];
            sum += v;
            sx += v * x;
            sy += v * y;
        }
    EXPECT_NEAR(sx / sum, double(c), 0.5);
    EXPECT_NEAR(sy / sum, double(c), 0.5);
    auto at = [&](int x, int y) { return out[(size_t(y) * size + size_t(x)) * 4]; };
    for (int d : {3, 8, 16, 32, 64}) {
        const int e = int(std::lround(double(d) / std::sqrt(2.0)));
        const float values[8] = {at(c + d, c), at(c - d, c), at(c, c + d), at(c, c - d),
                                 at(c + e, c + e), at(c - e, c + e), at(c + e, c - e), at(c - e, c - e)};
        float mean = 0;
        for (float v : values) mean += v / 8.0f;
        for (float v : values) EXPECT_NEAR(v / mean, 1.0f, 0.15f) << "distance " << d;
    }
}

TEST_F(GlTest, BloomNeverMakesNanOrInf)
{
    // The largest half float, alone and as a whole bright image, with and without the firefly
    // filter and a threshold: every sum is clamped below Inf, every division guarded.
    gl::State state;
    render::BloomPass bloom;
    for (bool karis : {false, true}) {
        for (float threshold : {0.0f, 1.0f}) {
            BloomSettings s = conserving(1.0f, 8);
            s.fireflyFilter = karis;
            s.threshold = threshold;
            gl::Texture single = makeHdr(64, 48, {{31, 23, 65504.0f}, {0, 0, 65504.0f}, {63, 47, 65504.0f}});
            bloom.apply(state, single, s, 1.0f);
            auto out = single.readFloat(0, 4);
            EXPECT_TRUE(allFinite(out)) << "karis " << karis << " threshold " << threshold;
            gl::Texture full = makeHdr(33, 17, {}, 65504.0f);
            bloom.apply(state, full, s, 1.0f);
            out = full.readFloat(0, 4);
            EXPECT_TRUE(allFinite(out)) << "karis " << karis << " threshold " << threshold;
            EXPECT_NEAR(out[4 * 100], 65504.0f, 1.0f);
        }
    }
}

TEST_F(GlTest, BloomFireflyFilterTamesSinglePixels)
{
    // Karis's average: an isolated very bright pixel blooms far less than its energy, while a
    // uniform bright area keeps (nearly) all of it.
    gl::State state;
    render::BloomPass bloom;
    BloomSettings s = conserving(0.5f, 5);
    s.fireflyFilter = true;
    gl::Texture single = makeHdr(128, 128, {{64, 64, 1000.0f}});
    bloom.apply(state, single, s, 1.0f, true);
    // Where all five 4×4 boxes of the 13-tap filter hold the pixel, their weights are equal and
    // it passes; elsewhere it is weighted down by 1 / (1 + luma).
    EXPECT_LT(sumChannel(single.readFloat(0, 4), 0), 0.4 * 0.5 * 1000.0);
    gl::Texture uniform = makeHdr(128, 128, {}, 2.0f);
    bloom.apply(state, uniform, s, 1.0f, true);
    EXPECT_NEAR(sumChannel(uniform.readFloat(0, 4), 0) / (0.5 * 2.0 * 128 * 128), 1.0, 0.01);
}

TEST_F(GlTest, BloomThresholdKeepsDimPixelsOut)
{
    gl::State state;
    render::BloomPass bloom;
    BloomSettings s = conserving(1.0f, 4);
    s.threshold = 1.0f;
    s.knee = 0.5f;
    gl::Texture dim = makeHdr(64, 64, {}, 0.4f); // below threshold - knee: no glow at all
    bloom.apply(state, dim, s, 1.0f, true);
    EXPECT_LT(sumChannel(dim.readFloat(0, 4), 0), 1e-3);
    gl::Texture bright = makeHdr(64, 64, {}, 4.0f); // far above: glows with (4 - 1) / 4 of its energy
    bloom.apply(state, bright, s, 1.0f, true);
    EXPECT_NEAR(sumChannel(bright.readFloat(0, 4), 0) / (3.0 * 64 * 64), 1.0, 0.01);
    // The threshold applies after exposure: at exposure 1/8 the same pixels are dim.
    gl::Texture exposed = makeHdr(64, 64, {}, 4.0f);
    bloom.apply(state, exposed, s, 1.0f / 8.0f, true);
    EXPECT_LT(sumChannel(exposed.readFloat(0, 4), 0), 1e-3);
}

TEST_F(GlTest, BloomHandlesOddSizesWithoutLosingEdges)
{
    // Bright pixels in the last column and row of odd-sized images still bloom (rounded-up
    // levels keep a texel below them); sizes down to 1×1 run without GL errors.
    gl::State state;
    render::BloomPass bloom;
    for (auto [w, h] : {std::pair{1023, 577}, std::pair{577, 1023}, std::pair{31, 7}, std::pair{3, 2}, std::pair{1, 1},
                        std::pair{2, 1}, std::pair{1, 9}}) {
        std::vector<Spot> spots = {{w - 1, h / 2, 10.0f}};
        if (w / 2 != w - 1 || h - 1 != h / 2) spots.push_back({w / 2, h - 1, 10.0f});
        const double energy = 10.0 * double(spots.size());
        gl::Texture hdr = makeHdr(w, h, spots);
        bloom.apply(state, hdr, conserving(0.2f, 8), 1.0f, true);
        const auto out = hdr.readFloat(0, 4);
        EXPECT_TRUE(allFinite(out)) << w << "x" << h;
        const double glow = sumChannel(out, 0);
        if (render::BloomPass::levelsFor(w, h, 8) > 0) {
            // Half of each spot's glow would leave the image; the pyramid reflects it back in
            // (exactly at even borders, to a few per cent where a level ends mid-texel).
            EXPECT_NEAR(glow / (0.2 * energy), 1.0, 0.08) << w << "x" << h;
        } else {
            EXPECT_EQ(glow, 0.0) << "a 1×1 frame has nothing to spread into";
        }
        // Glow reaches the far side of the last column: the edge was not dropped.
        if (w >= 31) {
            EXPECT_GT(out[(size_t(h / 2) * size_t(w) + size_t(w - 1)) * 4], 0.0f) << w << "x" << h;
        }
    }
    EXPECT_EQ(debug().errorCount(), 0);
}

TEST_F(GlTest, BloomOffLeavesTheFrameUnchanged)
{
    // The same scene with bloom off (but odd parameters) renders the same bytes and floats
    // as with default settings; with bloom on, a bright emitter glows onto its surroundings.
    scene::Scene s;
    scene::Material m;
    m.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    m.emissiveFactor = glm::vec3(1.0f);
    m.emissiveStrength = 50.0f;
    scene::addShape(s, scene::makeUvSphere(0.2f, 32, 16), m, glm::mat4(1.0f), "lamp");
    const render::View view = render::lookAtView({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 1.0f, 0.1f, 10.0f);
    render::Renderer renderer;
    renderer.setScene(s);
    for (int msaa : {1, 4}) {
        render::FrameSettings plain;
        plain.width = plain.height = 96;
        plain.msaa = msaa;
        renderer.render(view, plain);
        const ImageRGBA8 image = renderer.readImage();
        const ImageFloat radiance = renderer.readRadiance();

        render::FrameSettings off = plain;
        off.bloom.intensity = 3.0f;
        off.bloom.levels = 2;
        off.bloom.threshold = 0.5f;
        renderer.render(view, off);
        EXPECT_EQ(renderer.readImage().pixels, image.pixels) << "msaa " << msaa;
        EXPECT_EQ(renderer.readRadiance().pixels, radiance.pixels) << "msaa " << msaa;
        for (const auto& pass : renderer.stats().passes) EXPECT_STRNE(pass.name, "bloom");

        render::FrameSettings on = plain;
        on.bloom.enabled = true;
        on.bloom.intensity = 0.2f;
        renderer.render(view, on);
        const ImageFloat bloomed = renderer.readRadiance();
        const size_t corner = 4 * (10 * 96 + 10); // far from the lamp, black without bloom
        EXPECT_EQ(radiance.pixels[corner], 0.0f);
        EXPECT_GT(bloomed.pixels[corner], 0.0f);
    }
}
