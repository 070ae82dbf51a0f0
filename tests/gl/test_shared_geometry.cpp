// Repeated shapes share one upload (render/GpuScene's GpuGeometry): primitives whose vertices
// and indices are byte for byte the same get one vertex and index buffer, each keeping its own
// material; any other shape, even of the same size, gets its own. Levels of detail are made
// once per shared geometry and every primitive drawing it has them.
#include "GlTestContext.h"
#include "RadianceFrame.h"
#include "ImageProbe.h"

#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "render/GpuScene.h"
#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/Procedural.h"

using namespace specula;
using specula::test::GlTest;

namespace {

constexpr int kSize = 160;

/// Three spheres of one shape and three materials, a sphere of another shape with the same
/// vertex and index counts (moved vertices), and a cube.
scene::Scene repeatedShapes()
{
    scene::Scene s;
    const scene::Primitive sphere = scene::makeUvSphere(0.4f, 48, 32);
    scene::Primitive moved = sphere;
    // Same counts and (left stale on purpose) the same bounds: only the bytes tell them apart.
    for (scene::Vertex& v : moved.vertices) v.position.y *= 0.5f;
    const glm::vec3 colors[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 3; ++i) {
        scene::Material m;
        m.baseColorFactor = glm::vec4(colors[i], 1.0f);
        scene::addShape(s, sphere, m, glm::translate(glm::mat4(1.0f), {-1.0f + float(i), 0.5f, 0.0f}), "sphere");
    }
    scene::Material grey;
    grey.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    scene::addShape(s, moved, grey, glm::translate(glm::mat4(1.0f), {-0.5f, -0.5f, 0.0f}), "squashed sphere");
    scene::addShape(s, scene::makeCube(0.4f), grey, glm::translate(glm::mat4(1.0f), {0.5f, -0.5f, 0.0f}), "cube");
    return s;
}

} // namespace

TEST_F(GlTest, RepeatedShapesShareOneUploadAndKeepTheirMaterials)
{
    const scene::Scene s = repeatedShapes();
    {
        render::GpuScene gpu(s);
        ASSERT_EQ(gpu.primitives().size(), 5u);
        std::set<const render::GpuGeometry*> geometries;
        for (const render::GpuPrimitive& p : gpu.primitives()) geometries.insert(p.geometry.get());
        EXPECT_EQ(geometries.size(), 3u) << "the three spheres share one; the squashed sphere and the cube have their own";
        EXPECT_EQ(gpu.primitives()[0].geometry, gpu.primitives()[2].geometry);
        EXPECT_NE(gpu.primitives()[0].geometry, gpu.primitives()[3].geometry);
        EXPECT_NE(gpu.primitives()[0].material, gpu.primitives()[1].material);

        gpu.buildLevelsOfDetail();
        const auto& lods = gpu.primitives()[0].lods;
        EXPECT_GE(lods.size(), 2u) << "a sphere of 3,072 triangles has coarser levels";
        for (int i : {1, 2}) {
            ASSERT_EQ(gpu.primitives()[size_t(i)].lods.size(), lods.size());
            for (size_t k = 0; k < lods.size(); ++k) EXPECT_EQ(gpu.primitives()[size_t(i)].lods[k].count, lods[k].count);
            EXPECT_EQ(gpu.primitives()[size_t(i)].count, gpu.primitives()[0].count);
        }
    }
    // Each sphere drawn in its own base colour (unlit: the colour itself) from the shared buffers.
    render::FrameSettings settings = test::radianceFrame(kSize, kSize);
    settings.materialOverride.model = scene::ShadingModel::Unlit;
    const render::View view = render::lookAtView({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 1.0f, 0.1f, 20.0f);
    render::Renderer renderer;
    renderer.setScene(s);
    renderer.render(view, settings);
    const ImageFloat image = renderer.readRadiance();
    const glm::vec3 colors[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 3; ++i) {
        const glm::vec3 got = test::pixel(image, test::projectToPixel(view, {-1.0f + float(i), 0.5f, 0.0f}, kSize, kSize));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], colors[i][c], 1e-3f) << "sphere " << i << " channel " << c;
    }
    const glm::vec3 squashed = test::pixel(image, test::projectToPixel(view, {-0.5f, -0.5f, 0.0f}, kSize, kSize));
    EXPECT_NEAR(squashed.r, 0.5f, 1e-3f);
}
