#include "GlTestContext.h"
#include <cstdio>
#include "gl/State.h"
#include "gl/Texture.h"
#include "render/BloomPass.h"
using namespace specula;
using specula::test::GlTest;
TEST_F(GlTest, ZzScratch)
{
    for (int size : {256, 512, 1024}) for (int levels : {1, 2, 3, 4, 5, 6, 7, 8}) for (float value : {1.0f, 100.0f}) {
        gl::State state; render::BloomPass bloom;
        gl::TextureDesc desc; desc.width = size; desc.height = size; desc.format = gl::Format::RGBA16F;
        gl::Texture t(desc);
        std::vector<float> px(size_t(size) * size * 4, 0.0f);
        px[(size_t(size/2) * size + size/2) * 4] = value;
        t.upload(0, 0, 4, gl::PixelType::Float, px.data());
        render::BloomSettings s; s.enabled = true; s.intensity = 1.0f; s.levels = levels; s.fireflyFilter = false;
        bloom.apply(state, t, s, 1.0f, true);
        auto out = t.readFloat(0, 4);
        double sum = 0; for (size_t i = 0; i < out.size(); i += 4) sum += out[i];
        std::printf("size %d levels %d value %g: ratio %.5f\n", size, levels, value, sum / value);
    }
}
