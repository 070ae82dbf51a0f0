// The C++ mirrors of shaders/shared/ agree with the layout the GL compiler gives the blocks:
// std140 uniform blocks, and the lights' std430 storage buffer.
#include "GlTestContext.h"

#include <epoxy/gl.h>

#include "gl/Program.h"
#include "shaders/shared/Bindings.h"
#include "shaders/shared/FrameData.h"
#include "shaders/shared/LightData.h"
#include "shaders/shared/MaterialData.h"
#include "shaders/shared/PostData.h"

using namespace specula;
using specula::test::GlTest;

namespace {

GLint memberOffset(GLuint program, GLenum interface, const char* name)
{
    const GLuint index = glGetProgramResourceIndex(program, interface, name);
    if (index == GL_INVALID_INDEX) return -1;
    const GLenum property = GL_OFFSET;
    GLint offset = -1;
    glGetProgramResourceiv(program, interface, index, 1, &property, 1, nullptr, &offset);
    return offset;
}

GLint resourceProperty(GLuint program, GLenum interface, const char* name, GLenum property)
{
    const GLuint index = glGetProgramResourceIndex(program, interface, name);
    if (index == GL_INVALID_INDEX) return -1;
    GLint value = -1;
    glGetProgramResourceiv(program, interface, index, 1, &property, 1, nullptr, &value);
    return value;
}

GLint blockSize(GLuint program, GLenum interface, const char* name)
{
    return resourceProperty(program, interface, name, GL_BUFFER_DATA_SIZE);
}

} // namespace

TEST_F(GlTest, SharedStructsMatchGlslLayout)
{
    const gl::Program program({.vertex = "forward/pbr.vert", .fragment = "forward/pbr.frag"});
    const GLuint id = program.id();
    using shared::FrameData;
    using shared::GpuMaterial;

    EXPECT_EQ(blockSize(id, GL_UNIFORM_BLOCK, "FrameBlock"), GLint(sizeof(FrameData)));
    EXPECT_EQ(memberOffset(id, GL_UNIFORM, "frame.viewProjection"), GLint(offsetof(FrameData, viewProjection)));
    EXPECT_EQ(memberOffset(id, GL_UNIFORM, "frame.cameraPosition"), GLint(offsetof(FrameData, cameraPosition)));
    EXPECT_EQ(memberOffset(id, GL_UNIFORM, "frame.ambient"), GLint(offsetof(FrameData, ambient)));

    EXPECT_EQ(blockSize(id, GL_UNIFORM_BLOCK, "MaterialBlock"), GLint(sizeof(GpuMaterial)));
    EXPECT_EQ(memberOffset(id, GL_UNIFORM, "material.params"), GLint(offsetof(GpuMaterial, params)));
    EXPECT_EQ(memberOffset(id, GL_UNIFORM, "material.flags"), GLint(offsetof(GpuMaterial, flags)));
    EXPECT_EQ(memberOffset(id, GL_UNIFORM, "material.uvTransform[0]"), GLint(offsetof(GpuMaterial, uvTransform)));
}

TEST_F(GlTest, PostStructsMatchGlslLayout)
{
    using shared::ExposureParams;
    using shared::SsaoData;
    const gl::Program ssao({.compute = "post/ssao.comp"});
    EXPECT_EQ(blockSize(ssao.id(), GL_UNIFORM_BLOCK, "SsaoBlock"), GLint(sizeof(SsaoData)));
    EXPECT_EQ(memberOffset(ssao.id(), GL_UNIFORM, "ssao.size"), GLint(offsetof(SsaoData, size)));
    EXPECT_EQ(memberOffset(ssao.id(), GL_UNIFORM, "ssao.params"), GLint(offsetof(SsaoData, params)));
    EXPECT_EQ(memberOffset(ssao.id(), GL_UNIFORM, "ssao.options"), GLint(offsetof(SsaoData, options)));
    EXPECT_EQ(memberOffset(ssao.id(), GL_UNIFORM, "ssao.kernel[0]"), GLint(offsetof(SsaoData, kernel)));
    const gl::Program adapt({.compute = "post/exposure_adapt.comp"});
    EXPECT_EQ(blockSize(adapt.id(), GL_UNIFORM_BLOCK, "ExposureParamsBlock"), GLint(sizeof(ExposureParams)));
    EXPECT_EQ(memberOffset(adapt.id(), GL_UNIFORM, "params.adaptation"), GLint(offsetof(ExposureParams, adaptation)));
    EXPECT_EQ(memberOffset(adapt.id(), GL_UNIFORM, "params.clampEv"), GLint(offsetof(ExposureParams, clampEv)));
    EXPECT_EQ(blockSize(adapt.id(), GL_SHADER_STORAGE_BLOCK, "ExposureBlock"), GLint(sizeof(shared::ExposureState)));
}

// The light buffer as the compiled shaders see it (lights/light_list.glsl), in the fragment
// shader and in the Gouraud vertex shader: a LightHeader, then GpuLight records every
// sizeof(GpuLight) bytes from sizeof(LightHeader), the array runtime-sized; the offsets
// render::LightBuffer writes at.
TEST_F(GlTest, LightBufferMatchesGlslStd430Layout)
{
    using shared::GpuLight;
    using shared::LightHeader;
    const gl::Program pbr({.vertex = "forward/pbr.vert", .fragment = "forward/pbr.frag"});
    const gl::Program gouraud({.vertex = "forward/pbr.vert", .fragment = "forward/pbr.frag", .defines = {"SHADING_GOURAUD"}});
    for (const gl::Program* program : {&pbr, &gouraud}) {
        SCOPED_TRACE(program == &pbr ? "pbr" : "gouraud");
        const GLuint id = program->id();
        constexpr GLenum kBlock = GL_SHADER_STORAGE_BLOCK, kVariable = GL_BUFFER_VARIABLE;
        EXPECT_EQ(glGetProgramResourceIndex(id, GL_UNIFORM_BLOCK, "LightsBlock"), GL_INVALID_INDEX) << "still a uniform block";
        EXPECT_EQ(resourceProperty(id, kBlock, "LightsBlock", GL_BUFFER_BINDING), SPECULA_BINDING_LIGHTS);
        // A runtime-sized last member counts as one element (GL 4.5, 7.6.2.3).
        EXPECT_EQ(blockSize(id, kBlock, "LightsBlock"), GLint(sizeof(LightHeader) + sizeof(GpuLight)));
        EXPECT_EQ(memberOffset(id, kVariable, "LightsBlock.header.count"), GLint(offsetof(LightHeader, count)));
        const struct {
            const char* name;
            size_t offset;
        } members[] = {{"LightsBlock.lights[0].positionRange", offsetof(GpuLight, positionRange)},
                       {"LightsBlock.lights[0].directionType", offsetof(GpuLight, directionType)},
                       {"LightsBlock.lights[0].colorIntensity", offsetof(GpuLight, colorIntensity)},
                       {"LightsBlock.lights[0].spot", offsetof(GpuLight, spot)}};
        for (const auto& m : members) {
            EXPECT_EQ(memberOffset(id, kVariable, m.name), GLint(sizeof(LightHeader) + m.offset)) << m.name;
            EXPECT_EQ(resourceProperty(id, kVariable, m.name, GL_TOP_LEVEL_ARRAY_STRIDE), GLint(sizeof(GpuLight))) << m.name;
            EXPECT_EQ(resourceProperty(id, kVariable, m.name, GL_TOP_LEVEL_ARRAY_SIZE), 0) << m.name << ": not runtime-sized";
        }
    }
    // The Gouraud variant lights in the vertex shader, so that stage reads the buffer too.
    EXPECT_EQ(resourceProperty(gouraud.id(), GL_SHADER_STORAGE_BLOCK, "LightsBlock", GL_REFERENCED_BY_VERTEX_SHADER), 1);
}
