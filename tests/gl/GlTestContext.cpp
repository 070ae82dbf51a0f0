#include "GlTestContext.h"

#include "core/Log.h"

namespace specula::test {
namespace {

struct Shared {
    std::unique_ptr<platform::Context> context;
    std::unique_ptr<gl::DebugMonitor> debug;
    std::string failure;
};

Shared& shared()
{
    static Shared s;
    return s;
}

} // namespace

void GlTest::SetUpTestSuite()
{
    log::init();
    Shared& s = shared();
    if (s.context || !s.failure.empty()) return;
    try {
        s.context = platform::Context::createHeadless();
        s.debug = std::make_unique<gl::DebugMonitor>();
    } catch (const std::exception& e) {
        s.failure = e.what();
    }
}

void GlTest::SetUp()
{
    ASSERT_TRUE(shared().context) << "no OpenGL context: " << shared().failure;
    shared().debug->clear();
}

void GlTest::TearDown()
{
    if (!shared().debug) return;
    const auto errors = shared().debug->errors();
    EXPECT_TRUE(errors.empty()) << errors.size() << " GL error(s), first: " << (errors.empty() ? "" : errors.front());
}

gl::DebugMonitor& GlTest::debug()
{
    return *shared().debug;
}

} // namespace specula::test
