// The C++ mirrors of shaders/shared/ agree with the layout the GL compiler gives the blocks:
// std140 uniform blocks (the lights' std430 buffer: test_lights.cpp).
#include "GlTestContext.h"

#include <epoxy/gl.h>

#include "gl/Program.h"
#include "shaders/shared/Bindings.h"
#include "shaders/shared/FrameData.h"
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
    // The clearcoat variant reads the record's clearcoat vec4, the iridescence variant its last
    // vec4 and the last texture's transform.
    const gl::Program coated({.vertex = "forward/pbr.vert", .fragment = "forward/pbr.frag", .defines = {"CLEARCOAT"}});
    EXPECT_EQ(blockSize(coated.id(), GL_UNIFORM_BLOCK, "MaterialBlock"), GLint(sizeof(GpuMaterial)));
    EXPECT_EQ(memberOffset(coated.id(), GL_UNIFORM, "material.clearcoat"), GLint(offsetof(GpuMaterial, clearcoat)));
    const gl::Program sheened({.vertex = "forward/pbr.vert", .fragment = "forward/pbr.frag", .defines = {"SHEEN"}});
    EXPECT_EQ(blockSize(sheened.id(), GL_UNIFORM_BLOCK, "MaterialBlock"), GLint(sizeof(GpuMaterial)));
    EXPECT_EQ(memberOffset(sheened.id(), GL_UNIFORM, "material.sheen"), GLint(offsetof(GpuMaterial, sheen)));
    // The anisotropy variant reads its vec4 after clearcoat's and transform 10 of 13.
    const gl::Program brushed({.vertex = "forward/pbr.vert", .fragment = "forward/pbr.frag", .defines = {"ANISOTROPY"}});
    EXPECT_EQ(blockSize(brushed.id(), GL_UNIFORM_BLOCK, "MaterialBlock"), GLint(sizeof(GpuMaterial)));
    EXPECT_EQ(memberOffset(brushed.id(), GL_UNIFORM, "material.anisotropy"), GLint(offsetof(GpuMaterial, anisotropy)));
    const gl::Program filmed({.vertex = "forward/pbr.vert", .fragment = "forward/pbr.frag", .defines = {"IRIDESCENCE"}});
    EXPECT_EQ(blockSize(filmed.id(), GL_UNIFORM_BLOCK, "MaterialBlock"), GLint(sizeof(GpuMaterial)));
    EXPECT_EQ(memberOffset(filmed.id(), GL_UNIFORM, "material.iridescence"), GLint(offsetof(GpuMaterial, iridescence)));
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
