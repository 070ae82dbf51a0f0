// `specula render --variant NAME|INDEX|none` (KHR_materials_variants): the variant reaches the
// frame (by name and by index alike, none = the file's materials), and an unknown one is one
// line and a non-zero exit naming the variants there are.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "CliRunner.h"

namespace fs = std::filesystem;
using specula::test::runCli;
using specula::test::tempDir;

namespace {

const std::string kVariants = std::string(SPECULA_SOURCE_DIR) + "/tests/assets/gltf/variants.gltf";
const std::string kSmall = " --width 64 --height 64 --env none --no-cache";

std::string render(const std::string& dir, const std::string& name, const std::string& flags)
{
    const std::string out = dir + "/" + name + ".png";
    const auto r = runCli("render " + kVariants + " -o " + out + kSmall + " " + flags);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.errorLines(), 0) << r.err;
    std::ifstream in(out, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

TEST(CliVariants, VariantChoosesTheMaterials)
{
    const std::string dir = tempDir("variants");
    const std::string plain = render(dir, "plain", "");
    const std::string none = render(dir, "none", "--variant none");
    const std::string green = render(dir, "green", "--variant Green");
    const std::string greenByIndex = render(dir, "green-index", "--variant 0");
    const std::string blue = render(dir, "blue", "--variant Blue");
    ASSERT_FALSE(plain.empty());
    EXPECT_EQ(none, plain);
    EXPECT_EQ(greenByIndex, green);
    EXPECT_NE(green, plain);
    EXPECT_NE(blue, plain);
    EXPECT_NE(blue, green);
}

TEST(CliVariants, UnknownVariantIsOneLineError)
{
    const std::string dir = tempDir("variants-error");
    for (const char* flag : {"--variant Purple", "--variant 3"}) {
        const auto r = runCli("render " + kVariants + " -o " + dir + "/out.png" + kSmall + " " + flag);
        EXPECT_NE(r.exitCode, 0) << flag;
        EXPECT_LT(r.exitCode, 128) << "crashed: " << r.err;
        EXPECT_EQ(r.errorLines(), 1) << r.err;
        EXPECT_NE(r.err.find("(the scene has: 0 'Green', 1 'Blue', 2 'Hidden')"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir + "/out.png"));
    }
    // A scene without variants says so.
    const auto r = runCli("render demo -o " + dir + "/demo.png" + kSmall + " --variant Green");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("--variant: no material variant 'Green' (the scene has none)"), std::string::npos) << r.err;
}
