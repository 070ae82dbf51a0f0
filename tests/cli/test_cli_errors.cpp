// Bad input to `specula render`: one clear line on stderr, a non-zero exit, no output file,
// never a crash (exit codes >= 128 would be signals).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "CliRunner.h"

namespace fs = std::filesystem;
using specula::test::runCli;
using specula::test::tempDir;

namespace {

const std::string kAssets = SPECULA_ASSETS_DIR;

void expectCleanFailure(const specula::test::CliResult& r, const std::string& phrase, const fs::path& output)
{
    EXPECT_NE(r.exitCode, 0) << r.err;
    EXPECT_LT(r.exitCode, 128) << "crashed: " << r.err;
    EXPECT_EQ(r.errorLines(), 1) << "stderr:\n" << r.err;
    EXPECT_NE(r.err.find(phrase), std::string::npos) << "expected '" << phrase << "' in:\n" << r.err;
    EXPECT_FALSE(fs::exists(output)) << "left an output file behind";
    // No temporary files either.
    for (const auto& entry : fs::directory_iterator(output.parent_path()))
        EXPECT_EQ(entry.path().filename().string().find(output.filename().string()), std::string::npos) << entry.path();
}

void writeText(const fs::path& path, const std::string& text)
{
    std::ofstream(path) << text;
}

} // namespace

TEST(CliErrors, MissingFile)
{
    const std::string dir = tempDir("missing");
    const auto r = runCli("render " + dir + "/nope.gltf -o " + dir + "/out.png");
    expectCleanFailure(r, "nope.gltf", dir + "/out.png");
}

TEST(CliErrors, UnreadableFile)
{
    // A directory where a file should be cannot be read, even by root.
    const std::string dir = tempDir("unreadable");
    fs::create_directories(dir + "/folder.gltf");
    const auto r = runCli("render " + dir + "/folder.gltf -o " + dir + "/out.png");
    expectCleanFailure(r, "folder.gltf", dir + "/out.png");
}

TEST(CliErrors, NotGltf)
{
    const std::string dir = tempDir("notgltf");
    writeText(dir + "/text.gltf", "this is not json at all\n");
    expectCleanFailure(runCli("render " + dir + "/text.gltf -o " + dir + "/out.png"), "text.gltf", dir + "/out.png");
    writeText(dir + "/text.glb", "this is not a binary glTF\n");
    expectCleanFailure(runCli("render " + dir + "/text.glb -o " + dir + "/out.png"), "text.glb", dir + "/out.png");
}

TEST(CliErrors, UnknownSceneFormat)
{
    const std::string dir = tempDir("format");
    writeText(dir + "/scene.obj", "v 0 0 0\n");
    expectCleanFailure(runCli("render " + dir + "/scene.obj -o " + dir + "/out.png"), "unknown scene format", dir + "/out.png");
}

TEST(CliErrors, TruncatedGlb)
{
    const std::string dir = tempDir("truncated");
    std::ifstream in(kAssets + "/models/Box/Box.glb", std::ios::binary);
    ASSERT_TRUE(in) << "shared assets missing";
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(dir + "/half.glb", std::ios::binary).write(bytes.data(), std::streamsize(bytes.size() / 2));
    expectCleanFailure(runCli("render " + dir + "/half.glb -o " + dir + "/out.png"), "half.glb", dir + "/out.png");
}

TEST(CliErrors, BufferIndexOutOfRange)
{
    const std::string dir = tempDir("bufferindex");
    writeText(dir + "/bad.gltf", R"({
      "asset": {"version": "2.0"},
      "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
      "bufferViews": [{"buffer": 7, "byteLength": 36}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0
    })");
    expectCleanFailure(runCli("render " + dir + "/bad.gltf -o " + dir + "/out.png"), "bad.gltf", dir + "/out.png");
}

TEST(CliErrors, MissingTextureWarnsAndRenders)
{
    const std::string dir = tempDir("missingtexture");
    fs::copy_file(kAssets + "/models/BoxTextured/BoxTextured.gltf", dir + "/BoxTextured.gltf");
    fs::copy_file(kAssets + "/models/BoxTextured/BoxTextured0.bin", dir + "/BoxTextured0.bin");
    // CesiumLogoFlat.png deliberately not copied.
    const auto r = runCli("render " + dir + "/BoxTextured.gltf --width 64 --height 64 -o " + dir + "/out.png");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("warning"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("CesiumLogoFlat.png"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(dir + "/out.png"));
}

TEST(CliErrors, UnknownFlag)
{
    const std::string dir = tempDir("flag");
    const auto r = runCli("render --bogus-flag -o " + dir + "/out.png");
    expectCleanFailure(r, "--bogus-flag", dir + "/out.png");
}

TEST(CliErrors, UnwritableOutput)
{
    const std::string dir = tempDir("unwritable");
    const auto r = runCli("render --width 32 --height 32 -o " + dir + "/no/such/dir/out.png");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_LT(r.exitCode, 128);
    EXPECT_EQ(r.errorLines(), 1) << r.err;
    EXPECT_NE(r.err.find("out.png"), std::string::npos) << r.err;
    expectCleanFailure(runCli("render --width 32 --height 32 -o " + dir + "/out.jpg"), "out.jpg", dir + "/out.jpg");
}

TEST(CliErrors, BadValues)
{
    const std::string dir = tempDir("values");
    expectCleanFailure(runCli("render --tonemap sepia -o " + dir + "/out.png"), "sepia", dir + "/out.png");
    expectCleanFailure(runCli("render --msaa 3 -o " + dir + "/out.png"), "--msaa", dir + "/out.png");
    expectCleanFailure(runCli("render --camera 5 -o " + dir + "/out.png"), "camera 5", dir + "/out.png");
    expectCleanFailure(runCli("render --brdf-g beckmann -o " + dir + "/out.png"), "beckmann", dir + "/out.png");
}

TEST(CliErrors, UnsupportedExtensions)
{
    // Required: refused with one line naming it. Optional: one warning naming it, however many
    // primitives use it, and the file renders.
    const std::string dir = tempDir("extensions");
    const std::string triangle = R"(
      "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "extensions": {"EXT_made_up": {}}},
                                 {"attributes": {"POSITION": 0}, "extensions": {"EXT_made_up": {}}}]}],
      "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0
    })";
    writeText(dir + "/required.gltf", R"({"asset": {"version": "2.0"}, "extensionsUsed": ["EXT_made_up"],
      "extensionsRequired": ["EXT_made_up"],)" + triangle);
    expectCleanFailure(runCli("render " + dir + "/required.gltf -o " + dir + "/out.png"),
                       "requires the unsupported extension EXT_made_up", dir + "/out.png");
    writeText(dir + "/basisu.gltf", R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_texture_basisu"],
      "extensionsRequired": ["KHR_texture_basisu"],)" + triangle);
    expectCleanFailure(runCli("render " + dir + "/basisu.gltf -o " + dir + "/out.png"),
                       "requires the unsupported extension KHR_texture_basisu (KTX2", dir + "/out.png");

    writeText(dir + "/optional.gltf", R"({"asset": {"version": "2.0"}, "extensionsUsed": ["EXT_made_up"],)" + triangle);
    const auto r = runCli("render " + dir + "/optional.gltf --width 32 --height 32 -o " + dir + "/out.png");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    size_t mentions = 0;
    for (size_t at = r.err.find("EXT_made_up"); at != std::string::npos; at = r.err.find("EXT_made_up", at + 1)) ++mentions;
    EXPECT_EQ(mentions, 1u) << r.err;
    EXPECT_NE(r.err.find("warning"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(dir + "/out.png"));
}

TEST(CliErrors, CompressedModelsRender)
{
    const std::string dir = tempDir("compressed");
    for (const std::string& model : {kAssets + "/models/PmndrsSuzi/suzi_draco.glb",
                                    std::string(SPECULA_SOURCE_DIR) + "/tests/assets/gltf/logo_webp_meshopt.glb"}) {
        const auto r = runCli("render " + model + " --width 32 --height 32 -o " + dir + "/out.png");
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
        EXPECT_TRUE(fs::exists(dir + "/out.png"));
        fs::remove(dir + "/out.png");
    }
}
