// The windowed context (GLFW). Tests run under Xvfb (scripts/test.sh); without a display
// this fails rather than skips, so CI cannot pass without testing it.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include "platform/Context.h"

using namespace specula;

TEST(WindowContext, OpensWithGl45Core)
{
    std::unique_ptr<platform::Context> context;
    ASSERT_NO_THROW(context = platform::Context::createWindow({.width = 320, .height = 200, .visible = false}))
        << "no display? run the tests through scripts/test.sh (Xvfb)";
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_GE(major * 10 + minor, 45);
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
    EXPECT_EQ(context->backend(), "GLFW");
    const glm::ivec2 size = context->framebufferSize();
    EXPECT_EQ(size.x, 320);
    EXPECT_EQ(size.y, 200);
    glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    unsigned char pixel[4] = {};
    glReadPixels(10, 10, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    EXPECT_EQ(pixel[1], 255);
    context->swapBuffers();
}
