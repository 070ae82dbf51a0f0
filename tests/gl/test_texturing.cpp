// Texturing through the forward pass: sRGB decoding, KHR_texture_transform, and the mip level
// chosen along triangle edges (a regression: llvmpipe zeroes storage-buffer loads in helper
// invocations, which once gave the pixels on a quad's diagonal the coarsest mip).
#include "GlTestContext.h"
#include "RadianceFrame.h"

#include <glm/gtc/matrix_transform.hpp>

#include "render/Renderer.h"
#include "shading/Tonemap.h"
#include "scene/Procedural.h"

using namespace specula;
using specula::test::GlTest;

namespace {

/// A camera-facing emissive textured plane: the pixel is the texture (times 1 cd/m²).
scene::Scene texturedPlane(scene::Image image, scene::UvTransform transform)
{
    scene::Scene s;
    s.images.push_back(std::move(image));
    scene::Sampler sampler;
    sampler.magFilter = scene::Filter::Nearest;
    sampler.minFilter = scene::Filter::Linear;
    s.samplers.push_back(sampler);
    scene::Material m;
    m.baseColorFactor = glm::vec4(0, 0, 0, 1);
    m.emissiveFactor = glm::vec3(1.0f);
    m.emissiveTexture.image = 0;
    m.emissiveTexture.sampler = 0;
    m.emissiveTexture.transform = transform;
    const glm::mat4 facing = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0));
    scene::addShape(s, scene::makePlane(2.0f), m, facing, "plane");
    return s;
}

ImageFloat renderPlane(const scene::Scene& s, int size)
{
    render::Renderer renderer;
    renderer.setScene(s);
    render::View view;
    view.view = glm::lookAt(glm::vec3(0, 0, 2), glm::vec3(0), glm::vec3(0, 1, 0));
    view.projection = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.1f, 10.0f);
    view.position = {0, 0, 2};
    render::FrameSettings settings = test::radianceFrame(size, size);
    renderer.render(view, settings);
    return renderer.readRadiance();
}

} // namespace

TEST_F(GlTest, MagnifiedCheckerHasNoMipArtifactsOnTheDiagonal)
{
    // 32x32 texels in 4x4 blocks of black and white, magnified 8x with nearest filtering:
    // every pixel must be black or white. A wrong (coarse) mip would give grey.
    scene::Image checker;
    checker.width = checker.height = 32;
    checker.pixels.resize(32 * 32 * 4);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            for (int c = 0; c < 4; ++c) checker.pixels[size_t((y * 32 + x) * 4 + c)] = (((x / 4) + (y / 4)) & 1) ? 255 : 0;
    scene::UvTransform transform;
    transform.offset = {0.25f, 0.0f};
    transform.scale = {0.5f, 0.5f};
    const ImageFloat image = renderPlane(texturedPlane(checker, transform), 128);
    int grey = 0;
    for (size_t i = 0; i < image.pixels.size(); i += 4)
        if (image.pixels[i] > 0.02f && image.pixels[i] < 0.98f) ++grey;
    EXPECT_EQ(grey, 0) << "pixels neither black nor white";
}

TEST_F(GlTest, TextureTransformAndSrgbDecoding)
{
    // Left half of the image sRGB 188 (linear 0.5029), right half 0. Offset 0.5 in u
    // swaps the halves: the left of the screen must show the right of the image.
    scene::Image halves;
    halves.width = 2;
    halves.height = 1;
    halves.pixels = {188, 188, 188, 255, 0, 0, 0, 255};
    scene::UvTransform transform;
    transform.offset = {0.5f, 0.0f};
    const ImageFloat image = renderPlane(texturedPlane(halves, transform), 16);
    const float expected = render::srgbToLinear(188.0f / 255.0f);
    const size_t row = 8 * 16 * 4;
    EXPECT_NEAR(image.pixels[row + 2 * 4], 0.0f, 1e-3f);
    EXPECT_NEAR(image.pixels[row + 13 * 4], expected, 2e-3f);
}
