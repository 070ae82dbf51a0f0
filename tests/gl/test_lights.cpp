// Lights in a std140 uniform buffer: many of them, and editing one touches only its bytes.
#include "GlTestContext.h"

#include <cstring>

#include "render/LightBuffer.h"

using namespace specula;
using specula::test::GlTest;

TEST_F(GlTest, EditingOneLightRewritesOnlyItsBytes)
{
    render::LightBuffer lights;
    std::vector<render::PlacedLight> placed;
    for (int i = 0; i < 200; ++i) {
        render::PlacedLight p;
        p.light.type = scene::Light::Type(i % 3);
        p.light.intensity = float(i);
        p.position = glm::vec3(float(i), 1.0f, 2.0f);
        placed.push_back(p);
    }
    lights.setAll(placed);
    ASSERT_EQ(lights.count(), 200);
    const auto before = lights.buffer().read(0, lights.buffer().size());
    const size_t updatedBefore = lights.buffer().bytesUpdated();

    render::PlacedLight edited = placed[137];
    edited.light.color = {0.1f, 0.2f, 0.3f};
    edited.light.intensity = 999.0f;
    lights.set(137, edited);

    // The upload was exactly one GpuLight at its offset...
    EXPECT_EQ(lights.buffer().bytesUpdated() - updatedBefore, sizeof(shared::GpuLight));
    EXPECT_EQ(lights.buffer().lastUpdate().offset, lights.offsetOf(137));
    EXPECT_EQ(lights.offsetOf(137), 16 + 137 * sizeof(shared::GpuLight));
    // ...and reading the GPU copy back, no other byte changed.
    const auto after = lights.buffer().read(0, lights.buffer().size());
    const size_t begin = lights.offsetOf(137), end = begin + sizeof(shared::GpuLight);
    size_t changed = 0;
    for (size_t i = 0; i < after.size(); ++i) {
        if (before[i] != after[i]) {
            ++changed;
            EXPECT_TRUE(i >= begin && i < end) << "byte " << i << " outside light 137 changed";
        }
    }
    EXPECT_GT(changed, 0u);
    shared::GpuLight gpu;
    std::memcpy(&gpu, after.data() + begin, sizeof gpu);
    EXPECT_EQ(gpu.colorIntensity, glm::vec4(0.1f, 0.2f, 0.3f, 999.0f));
}

TEST_F(GlTest, TooManyLightsAreCappedNotOverflowed)
{
    render::LightBuffer lights;
    lights.setAll(std::vector<render::PlacedLight>(SPECULA_MAX_LIGHTS + 10));
    EXPECT_EQ(lights.count(), SPECULA_MAX_LIGHTS);
}
