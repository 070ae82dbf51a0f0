#pragma once
// One headless context shared by all GL tests of the process, with the debug monitor on.
// A test that cannot get a context fails (never skips): CI must render for real.
#include <gtest/gtest.h>

#include <memory>

#include "gl/Debug.h"
#include "platform/Context.h"

namespace specula::test {

class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite();
    void SetUp() override;
    /// Fails the test if the GL debug output reported any error.
    void TearDown() override;
    gl::DebugMonitor& debug();
};

} // namespace specula::test
