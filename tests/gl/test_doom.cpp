// The Doom model on the GPU (render/DoomPass, shaders/doom/): a Doom frame (indices and levels,
// then the colour-map pass) and per-material Doom materials of a normal frame (inline lookup)
// give, byte for byte, the palette colour the CPU twin (scene::doom::ColorTables::shade at
// colormapIndex's level) gives for the same colours and levels; sprites are quantised and lit
// by their sector; every pixel of a Doom frame of the demo level and of a scene full of
// billboards is a palette colour.
#include "GlTestContext.h"
#include "RadianceFrame.h"
#include "ImageProbe.h"

#include <cmath>
#include <set>

#include "gl/Framebuffer.h"
#include "gl/Texture.h"
#include "render/Renderer.h"
#include "shading/Tonemap.h"
#include "scene/DemoScenes.h"
#include "scene/DoomLevel.h"
#include "scene/Procedural.h"

using namespace specula;
using specula::test::GlTest;
namespace doom = specula::scene::doom;

namespace {

constexpr int kSize = 320;
// Every test surface lies in the plane 4.6 m (147.2 map units) in front of the eye: every pixel
// at that depth (Doom's distance), in light diminishing's step 9 (144 to 160 units) and the
// walls' scale 17 (142.2 to 150.6), so the level of every pixel is exactly known.
constexpr float kDistance = 4.6f;
constexpr float kHalfSide = 0.25f;

render::View testView()
{
    return render::lookAtView({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, glm::radians(60.0f), 1.0f, 0.1f, 20.0f);
}

/// Pixel (x, y), image row 0 at the top, of a point in world space.
glm::ivec2 project(const render::View& view, const glm::vec3& p)
{
    return test::projectToPixel(view, p, kSize, kSize);
}

doom::Rgb pixel(const ImageRGBA8& image, glm::ivec2 p)
{
    const size_t i = (size_t(p.y) * size_t(image.width) + size_t(p.x)) * 4;
    return {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]};
}

struct Patch {
    doom::Rgb color; ///< sRGB
    int light;       ///< sector light level
    glm::vec3 centre;
};

/// 6 × 5 squares facing the eye, kDistance from it, each its own colour and sector light: the
/// colours pseudo-random bytes, black, white and a few palette colours, the lights a spread
/// giving colour-map levels 0, 8, 12, 16, 20, 24, 28 and 31 at this distance.
std::vector<Patch> patches()
{
    const doom::Palette& palette = doom::colorTables().palette;
    const int lights[] = {255, 176, 160, 144, 128, 112, 96, 48, 0};
    std::vector<Patch> out;
    uint32_t seed = 12345;
    auto next = [&] {
        seed = seed * 1664525u + 1013904223u; // Numerical Recipes' LCG: fixed on every platform
        return uint8_t(seed >> 24);
    };
    for (int row = 0; row < 5; ++row) {
        for (int column = 0; column < 6; ++column) {
            const int i = row * 6 + column;
            doom::Rgb c{next(), next(), next()};
            if (i == 0) c = {0, 0, 0};
            if (i == 1) c = {255, 255, 255};
            if (i >= 2 && i < 6) c = palette[size_t(37 * i)];
            const glm::vec3 centre((float(column) - 2.5f) * 0.16f * kDistance, (float(row) - 2.0f) * 0.16f * kDistance, -kDistance);
            out.push_back({c, lights[size_t(i) % std::size(lights)], centre});
        }
    }
    return out;
}

scene::Scene patchScene(bool doomMaterials)
{
    scene::Scene s;
    for (const Patch& p : patches()) {
        scene::Material m;
        m.baseColorFactor = glm::vec4(render::srgbToLinear(p.color[0] / 255.0f), render::srgbToLinear(p.color[1] / 255.0f),
                                      render::srgbToLinear(p.color[2] / 255.0f), 1.0f);
        m.sectorLight = p.light;
        if (doomMaterials) m.shading.model = scene::ShadingModel::Doom;
        // A square in the plane, centred on p.centre, its normal towards the eye (the middle
        // row's is horizontal: lit as a wall; the others' as flats).
        const glm::vec3 look = -glm::normalize(p.centre);
        const glm::vec3 right(1, 0, 0), up(0, 1, 0);
        scene::Primitive quad;
        const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const glm::vec2& c : corners) {
            scene::Vertex v;
            v.position = p.centre + (right * c.x + up * c.y) * kHalfSide;
            v.normal = look;
            quad.vertices.push_back(v);
            quad.bounds.extend(v.position);
        }
        quad.indices = {0, 1, 2, 0, 2, 3};
        scene::addShape(s, quad, m, glm::mat4(1.0f), "patch");
    }
    return s;
}

render::FrameSettings plainSettings()
{
    // Nothing between the forward pass and the bytes: one sample, no curve, no exposure.
    render::FrameSettings s = test::radianceFrame(kSize, kSize);
    return s;
}

/// Every pixel of `image` is a palette colour; returns how many colours it holds.
size_t expectOnlyPaletteColours(const ImageRGBA8& image, const char* what)
{
    const doom::Palette& palette = doom::colorTables().palette;
    const std::set<doom::Rgb> colours(palette.begin(), palette.end());
    std::set<doom::Rgb> seen;
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
        const doom::Rgb c = {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]};
        if (!colours.count(c)) {
            ADD_FAILURE() << what << ": pixel " << i / 4 << " (" << int(c[0]) << ", " << int(c[1]) << ", " << int(c[2])
                          << ") is not a palette colour";
            return seen.size();
        }
        seen.insert(c);
    }
    return seen.size();
}

} // namespace

// The colour-map pass's output against the CPU twin, and per-material Doom materials of a
// normal frame (the same GLSL, inline) against both: equal bytes, everywhere.
TEST_F(GlTest, DoomFrameAndInlineDoomMaterialsMatchTheCpuTwin)
{
    const doom::ColorTables& tables = doom::colorTables();
    const render::View view = testView();
    render::Renderer renderer;

    // A Doom frame: the override turns every material into the Doom model.
    renderer.setScene(patchScene(false));
    render::FrameSettings doomFrame = plainSettings();
    doomFrame.materialOverride.model = scene::ShadingModel::Doom;
    renderer.render(view, doomFrame);
    const ImageRGBA8 indexed = renderer.readImage();
    const ImageFloat radiance = renderer.readRadiance();

    // The same surfaces as Doom materials in an otherwise normal frame.
    renderer.setScene(patchScene(true));
    renderer.render(view, plainSettings());
    const ImageRGBA8 inline_ = renderer.readImage();

    std::set<int> levels;
    for (const Patch& p : patches()) {
        // The middle row's normals are horizontal: lit as walls (no fake contrast: none is along
        // an axis); the others as flats. At this depth both tables agree.
        const bool wall = std::abs(p.centre.y) < 1e-6f;
        const int level = wall ? doom::wallColormapIndex(p.light, kDistance * 32.0) : doom::colormapIndex(p.light, kDistance * 32.0);
        levels.insert(level);
        const doom::Rgb expected = tables.palette[tables.shade(p.color, level)];
        // The centre and the corners of the square's inner half.
        const glm::vec3 right(1, 0, 0), up(0, 1, 0);
        for (const glm::vec2 c :
             {glm::vec2(0, 0), glm::vec2(-0.5f, -0.5f), glm::vec2(0.5f, -0.5f), glm::vec2(0.5f, 0.5f), glm::vec2(-0.5f, 0.5f)}) {
            const glm::ivec2 at = project(view, p.centre + (right * c.x + up * c.y) * kHalfSide);
            const doom::Rgb got = pixel(indexed, at);
            EXPECT_EQ(got, expected) << "colour (" << int(p.color[0]) << ", " << int(p.color[1]) << ", " << int(p.color[2])
                                     << "), light " << p.light << ", level " << level << ": got (" << int(got[0]) << ", "
                                     << int(got[1]) << ", " << int(got[2]) << ")";
        }
    }
    EXPECT_EQ(levels, (std::set<int>{0, 8, 12, 16, 20, 24, 28, 31}));
    // The inline lookup equals the pass, pixel for pixel (background black in both).
    ASSERT_EQ(indexed.pixels.size(), inline_.pixels.size());
    size_t differing = 0;
    for (size_t i = 0; i < indexed.pixels.size(); ++i) differing += indexed.pixels[i] != inline_.pixels[i];
    EXPECT_EQ(differing, 0u);
    // The colour-map pass writes the HDR target too: the same colours as linear radiance
    // (half floats: 2e-3 relative is a tenth of a byte in sRGB).
    for (const Patch& p : patches()) {
        const glm::ivec2 at = project(view, p.centre);
        const doom::Rgb c = pixel(indexed, at);
        for (size_t ch = 0; ch < 3; ++ch) {
            const float expected = render::srgbToLinear(c[ch] / 255.0f);
            EXPECT_NEAR(radiance.pixels[(size_t(at.y) * kSize + size_t(at.x)) * 4 + ch], expected, 2e-3f * expected + 1e-6f);
        }
    }
}

// Sprites in a Doom frame: texel × tint through the table, at one level per sprite from its
// group's sector light and its distance, texels unfiltered; blended ones cut out.
TEST_F(GlTest, DoomFrameQuantisesBillboardsLitByTheirSector)
{
    const doom::ColorTables& tables = doom::colorTables();
    const doom::Rgb texel{200, 90, 40};
    scene::Scene s;
    scene::Image image;
    image.name = "solid";
    image.width = image.height = 4;
    for (int i = 0; i < 16; ++i) image.pixels.insert(image.pixels.end(), {texel[0], texel[1], texel[2], 255});
    s.images.push_back(image);
    const int lights[] = {255, 144, 96};
    for (int i = 0; i < 3; ++i) {
        scene::BillboardGroup group;
        group.name = "solid " + std::to_string(i);
        group.kind = scene::BillboardKind::PointSprite;
        group.size = glm::vec2(0.5f);
        group.image = 0;
        group.sectorLight = lights[i];
        // The third is blended: an 8-bit frame cuts it out, its opaque texels stay.
        group.alphaMode = i == 2 ? scene::AlphaMode::Blend : scene::AlphaMode::Mask;
        group.billboards.push_back({glm::vec3(float(i - 1) * 0.3f * kDistance, 0.0f, -kDistance)});
        s.billboards.push_back(group);
    }
    render::Renderer renderer;
    renderer.setScene(s);
    render::FrameSettings settings = plainSettings();
    settings.materialOverride.model = scene::ShadingModel::Doom;
    const render::View view = testView();
    renderer.render(view, settings);
    const ImageRGBA8 frame = renderer.readImage();
    for (int i = 0; i < 3; ++i) {
        // Things are lit by the walls' scale table (R_ProjectSprite's spritelights).
        const int level = doom::wallColormapIndex(lights[i], kDistance * 32.0);
        const doom::Rgb expected = tables.palette[tables.shade(texel, level)];
        const doom::Rgb got = pixel(frame, project(view, s.billboards[size_t(i)].billboards[0].position));
        EXPECT_EQ(got, expected) << "light " << lights[i] << ", level " << level << ": got (" << int(got[0]) << ", "
                                 << int(got[1]) << ", " << int(got[2]) << ")";
    }
    expectOnlyPaletteColours(frame, "sprites");
}

// Walls and flats: a flat, a wall along each map axis (fake contrast) and a diagonal wall, all
// 100 map units in front of the eye and all of light 160, take levels 9, 12, 4 and 8 (hand-computed in
// DoomLighting.WallsAndThingsTakeTheScaleTable): four colours of the same grey.
TEST_F(GlTest, DoomWallsTakeTheScaleTableAndFakeContrast)
{
    const doom::ColorTables& tables = doom::colorTables();
    const float d = 100.0f / 32.0f; // metres
    struct Square {
        glm::vec3 centre, normal, right;
        int level;
    };
    // Each square faces the eye side of its normal: a flat below the eye seen from above, walls
    // in front and to the side.
    const glm::vec3 diagonal = glm::normalize(glm::vec3(1, 0, 1));
    const Square squares[] = {
        {glm::vec3(0.0f, -0.4f, -1.0f) * d, {0, 1, 0}, {1, 0, 0}, 9},                  // flat
        {glm::vec3(0.25f, 0.0f, -1.0f) * d, {0, 0, 1}, {1, 0, 0}, 12},                 // wall along x
        {glm::vec3(-0.45f, 0.0f, -1.0f) * d, {1, 0, 0}, {0, 0, -1}, 4},                // wall along z (map y)
        {glm::vec3(-0.1f, 0.5f, -1.0f) * d, diagonal, {diagonal.z, 0, -diagonal.x}, 8}, // diagonal wall
    };
    const doom::Rgb grey{150, 150, 150};
    scene::Scene s;
    for (const Square& q : squares) {
        scene::Material m;
        m.baseColorFactor = glm::vec4(glm::vec3(render::srgbToLinear(150.0f / 255.0f)), 1.0f);
        m.sectorLight = 160;
        const glm::vec3 up = glm::cross(q.normal, q.right);
        scene::Primitive quad;
        for (const glm::vec2& c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
            scene::Vertex v;
            // 8 cm across: every point's depth within 1.3 units of 100, inside both tables'
            // steps there (flats 96–112, walls 98.5–102.4).
            v.position = q.centre + (q.right * c.x + up * c.y) * 0.04f;
            v.normal = q.normal;
            quad.vertices.push_back(v);
            quad.bounds.extend(v.position);
        }
        quad.indices = {0, 1, 2, 0, 2, 3};
        m.doubleSided = true;
        scene::addShape(s, quad, m, glm::mat4(1.0f), "square");
    }
    render::Renderer renderer;
    renderer.setScene(s);
    render::FrameSettings settings = plainSettings();
    settings.materialOverride.model = scene::ShadingModel::Doom;
    const render::View view = testView();
    renderer.render(view, settings);
    const ImageRGBA8 frame = renderer.readImage();
    std::set<doom::Rgb> colours;
    for (const Square& q : squares) {
        const doom::Rgb expected = tables.palette[tables.shade(grey, q.level)];
        const doom::Rgb got = pixel(frame, project(view, q.centre));
        EXPECT_EQ(got, expected) << "level " << q.level << ": got (" << int(got[0]) << ", " << int(got[1]) << ", "
                                 << int(got[2]) << ")";
        colours.insert(got);
    }
    EXPECT_EQ(colours.size(), 4u); // the four levels are four colours: the test can tell them apart
}

// Every pixel of a Doom frame is a palette colour: the demo level (textured walls, floors,
// ceilings and its sprites) and the demo scene (its trees, blended lanterns, neon rods and, with
// gizmos, the lights' discs), and both hold many of them.
TEST_F(GlTest, DoomFramesShowOnlyPaletteColours)
{
    render::FrameSettings settings;
    settings.width = 160;
    settings.height = 100;
    settings.materialOverride.model = scene::ShadingModel::Doom; // also forces one sample, no tone curve

    const scene::Scene level = doom::makeDemoLevel();
    render::Renderer renderer;
    renderer.setScene(level);
    renderer.setGpuTiming(true);
    renderer.render(render::defaultView(level, 0, 1.6f), settings);
    EXPECT_GT(expectOnlyPaletteColours(renderer.readImage(), "doom level"), 20u); // textures, light diminishing
    // Indices and levels first, then the colour-map pass; no tone mapper.
    std::vector<std::string> passes;
    for (const render::PassTiming& t : renderer.stats().passes) passes.push_back(t.name);
    EXPECT_EQ(passes, (std::vector<std::string>{"forward", "colour map"}));
    renderer.setGpuTiming(false);

    const scene::Scene demo = scene::makeDemoScene();
    renderer.setScene(demo);
    settings.gizmos = true;
    renderer.render(render::defaultView(demo, 0, 1.6f), settings);
    const ImageRGBA8 image = renderer.readImage();
    EXPECT_GT(expectOnlyPaletteColours(image, "demo scene with billboards"), 10u);
}

// The GL pieces the Doom frame needs: a 3D unsigned-integer texture uploads and reads back as
// it was given, and an RG8UI target clears to integers.
TEST_F(GlTest, IntegerTexturesAndTargets)
{
    gl::TextureDesc desc;
    desc.type = gl::TextureType::Texture3D;
    desc.format = gl::Format::R8UI;
    desc.width = 4;
    desc.height = 3;
    desc.layers = 2;
    gl::Texture volume(desc);
    std::vector<uint8_t> values(4 * 3 * 2);
    for (size_t i = 0; i < values.size(); ++i) values[i] = uint8_t(7 * i + 1);
    volume.upload(0, 0, 1, gl::PixelType::UnsignedByte, values.data());
    EXPECT_EQ(volume.readBytes(0, 1), values);

    desc = {};
    desc.format = gl::Format::RG8UI;
    desc.width = desc.height = 2;
    gl::Texture target(desc);
    gl::Framebuffer framebuffer("rg8ui");
    framebuffer.attachColor(0, target).check();
    framebuffer.clearColorUint(0, 201, 17, 0, 0);
    EXPECT_EQ(target.readBytes(0, 2), (std::vector<uint8_t>{201, 17, 201, 17, 201, 17, 201, 17}));
}
