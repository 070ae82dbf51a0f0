#include "GlTestContext.h"

#include <epoxy/gl.h>

using specula::test::GlTest;

TEST_F(GlTest, HasCore45)
{
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    EXPECT_GE(major * 10 + minor, 45);
}
