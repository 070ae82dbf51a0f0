// The PCF filter of lights/shadow.glsl (shadowTent) on its own, in a compute program, against
// its definition: the tent [1 2 1] ⊗ [1 2 1] (SHADOW_TENT 5: [1 2 3 2 1] ⊗ [1 2 3 2 1]) of the
// texels' comparisons with the reference depth, moved bilinearly with the lookup's sub-texel
// position — worked out here texel by texel, in double precision, where the shader folds pairs
// of texels into hardware-compared bilinear taps. The depth map is random noise, so every texel's
// comparison is its own and a wrong weight or position shows.
// Broken on purpose (2026-12-07): the last pair's position without its whole texels (1 + s / w
// → s / w) fails with the largest error 0.55 (tent 3) and 0.38 (tent 5); the first pair's
// weight 3 − s instead of 3 − 2s with 0.54 and 0.23.
#include "GlTestContext.h"

#include <epoxy/gl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "shaders/shared/Bindings.h"

using namespace specula;
using specula::test::GlTest;

namespace {

constexpr int kSize = 64; // the depth map, texels

// The shader tree with a compute program beside it that runs shadowTent once per query
// (xy atlas uv, z reference depth) into a result per query.
std::filesystem::path shaderTreeWithTentProgram()
{
    namespace fs = std::filesystem;
    const fs::path root = fs::temp_directory_path() / ("specula-tent-test-" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::copy(fs::path(SPECULA_SOURCE_DIR) / "shaders", root, fs::copy_options::recursive);
    std::ofstream(root / "tent_test.comp") << R"(#version 450 core
#define SHADOWS
#include "common/frame_block.glsl"
#include "lights/shadow.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Queries { vec4 queries[]; };
layout(std430, binding = 1) writeonly buffer Results { float results[]; };
void main()
{
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(queries.length())) return;
    // The whole map is the view's tile.
    results[i] = shadowTent(vec4(0.0, 0.0, 1.0, 1.0), queries[i].xy, queries[i].z);
}
)";
    return root;
}

/// The filter by its definition: texel weights of the kernel moved by the sub-texel position.
double tentByTexels(const std::vector<float>& depth, const std::vector<double>& kernel, double u, double v, double reference)
{
    const int n = int(kernel.size());
    const auto k = [&](int j) { return j >= 0 && j < n ? kernel[size_t(j)] : 0.0; };
    const double x = u * kSize - 0.5, y = v * kSize - 0.5;
    const int bx = int(std::floor(x)), by = int(std::floor(y));
    const double sx = x - bx, sy = y - by;
    double sum = 0.0, total = 0.0;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double w = ((1.0 - sx) * k(i) + sx * k(i - 1)) * ((1.0 - sy) * k(j) + sy * k(j - 1));
            const int tx = bx - (n - 1) / 2 + i, ty = by - (n - 1) / 2 + j;
            const bool lit = reference <= double(depth[size_t(ty) * kSize + size_t(tx)]); // GL_LEQUAL
            sum += lit ? w : 0.0;
            total += w;
        }
    return sum / total;
}

} // namespace

TEST_F(GlTest, PcfTentIsTheTentOfTexelComparisons)
{
    const std::filesystem::path root = shaderTreeWithTentProgram();
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<float> depth(size_t(kSize) * kSize);
    for (float& d : depth) d = uniform(rng);

    GLuint texture = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &texture);
    glTextureStorage2D(texture, 1, GL_DEPTH_COMPONENT32F, kSize, kSize);
    glTextureSubImage2D(texture, 0, 0, 0, kSize, kSize, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    // As ShadowPass's "shadow compare" sampler.
    glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(texture, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glBindTextureUnit(SPECULA_UNIT_SHADOW_ATLAS, texture);
    glBindSampler(SPECULA_UNIT_SHADOW_ATLAS, 0);

    // Lookups anywhere at least 4 texels inside the map (no clamping to the tile), at random
    // sub-texel positions, and the exact texel centres and edges too.
    std::vector<glm::vec4> queries;
    for (int q = 0; q < 4096; ++q) {
        const float margin = 4.0f / kSize;
        glm::vec2 uv(margin + (1.0f - 2.0f * margin) * uniform(rng), margin + (1.0f - 2.0f * margin) * uniform(rng));
        if (q % 8 == 0) uv = (glm::floor(uv * float(kSize)) + 0.5f) / float(kSize); // a texel centre
        if (q % 8 == 1) uv = glm::floor(uv * float(kSize)) / float(kSize);          // a texel corner
        queries.emplace_back(uv, uniform(rng), 0.0f);
    }
    const gl::Buffer queryBuffer = gl::Buffer::fromSpan(std::span<const glm::vec4>(queries), "tent queries");

    struct Tent {
        const char* define;
        std::vector<double> kernel;
    };
    const Tent tents[] = {{"SHADOW_TENT 3", {1, 2, 1}}, {"SHADOW_TENT 5", {1, 2, 3, 2, 1}}};
    for (const Tent& tent : tents) {
        SCOPED_TRACE(tent.define);
        const gl::Program program({.compute = "tent_test.comp", .defines = {tent.define}, .label = "tent test", .root = root});
        const gl::Buffer results(queries.size() * sizeof(float), nullptr, "tent results");
        glUseProgram(program.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, queryBuffer.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, results.id());
        glDispatchCompute(GLuint(queries.size() / 64), 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        glUseProgram(0);
        const std::vector<std::byte> bytes = results.read(0, queries.size() * sizeof(float));
        std::vector<float> got(queries.size());
        std::memcpy(got.data(), bytes.data(), bytes.size());

        // Tolerance 4e-3: a GPU filters with 8-bit sub-texel weights; llvmpipe's largest
        // error is 1.7e-6 (float weights). A wrong weight or tap position is off by 0.2 or more.
        double worst = 0.0, partial = 0.0;
        int off = 0;
        for (size_t q = 0; q < queries.size(); ++q) {
            const double want = tentByTexels(depth, tent.kernel, queries[q].x, queries[q].y, queries[q].z);
            const double error = std::abs(double(got[q]) - want);
            worst = std::max(worst, error);
            if (want > 0.0 && want < 1.0) ++partial;
            if (error > 4e-3 && off++ < 5)
                ADD_FAILURE() << "lookup (" << queries[q].x << ", " << queries[q].y << ") at depth " << queries[q].z << ": GPU "
                              << got[q] << ", the texels' tent " << want;
        }
        EXPECT_EQ(off, 0);
        EXPECT_GT(partial, 0.8 * double(queries.size())) << "the lookups must fall between lit and shadowed texels";
        std::printf("PCF %s: %zu lookups, largest error %.2e\n", tent.define, queries.size(), worst);
    }
    glDeleteTextures(1, &texture);
    std::filesystem::remove_all(root);
}
