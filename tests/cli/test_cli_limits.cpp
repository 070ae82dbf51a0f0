// Files from anywhere (issue 16): a glTF's URIs and a scene file's paths stay inside the
// folder of the file that names them unless --allow-external-files; what a file declares is
// refused over the limits (--max-buffer-bytes, --max-accessor-count, --max-image-size,
// --max-texture-memory) before anything is allocated; a texture over the GL limit is
// downscaled; numbers must be finite; and a render killed while writing leaves no file.
// Each refusal: one line naming the URI or the limit and its flag, a non-zero exit, no output.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "CliRunner.h"
#include "core/ImageIO.h"

extern char** environ;

namespace fs = std::filesystem;
using specula::test::CliResult;
using specula::test::runCli;
using specula::test::tempDir;

namespace {

const fs::path kFiles = fs::path(SPECULA_SOURCE_DIR) / "fuzz/files";

std::string readText(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeText(const fs::path& path, const std::string& text)
{
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

/// The triangle of fuzz/files (model.gltf: buffer.bin, texture.png, 4x4) copied into `dir`,
/// with `from` in its JSON replaced by `to`.
fs::path model(const fs::path& dir, const std::string& from = "", const std::string& to = "")
{
    fs::create_directories(dir);
    fs::copy_file(kFiles / "buffer.bin", dir / "buffer.bin", fs::copy_options::overwrite_existing);
    fs::copy_file(kFiles / "texture.png", dir / "texture.png", fs::copy_options::overwrite_existing);
    std::string json = readText(kFiles / "model.gltf");
    if (!from.empty()) json = replaced(json, from, to);
    writeText(dir / "model.gltf", json);
    return dir / "model.gltf";
}

CliResult render(const fs::path& scene, const fs::path& output, const std::string& flags = "")
{
    return runCli("render " + scene.string() + " -o " + output.string() + " --width 32 --height 24 --no-cache " + flags);
}

void expectRefusal(const CliResult& r, const std::vector<std::string>& phrases, const fs::path& output)
{
    EXPECT_NE(r.exitCode, 0) << r.err;
    EXPECT_LT(r.exitCode, 128) << "crashed: " << r.err;
    EXPECT_EQ(r.errorLines(), 1) << "stderr:\n" << r.err;
    for (const std::string& phrase : phrases)
        EXPECT_NE(r.err.find(phrase), std::string::npos) << "expected '" << phrase << "' in:\n" << r.err;
    EXPECT_FALSE(fs::exists(output)) << "left an output file behind";
}

void expectRendered(const CliResult& r, const fs::path& output)
{
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(output)) << r.err;
}

} // namespace

// -- untrusted files stay in their folder --------------------------------------------------

TEST(CliLimits, GltfBufferUriLeavingTheFolderIsRefused)
{
    const fs::path dir = tempDir("limits-escape");
    model(dir); // ../buffer.bin seen from dir/model/ is this one
    const fs::path gltf = model(dir / "model", "\"uri\": \"buffer.bin\"", "\"uri\": \"../buffer.bin\"");
    expectRefusal(render(gltf, dir / "out.png"), {"model.gltf", "buffers[0].uri '../buffer.bin'", "--allow-external-files"},
                  dir / "out.png");
    expectRendered(render(gltf, dir / "out.png", "--allow-external-files"), dir / "out.png");
}

TEST(CliLimits, GltfImageUriToEtcPasswdIsRefused)
{
    // The issue's example: tinygltf opened it.
    const fs::path dir = tempDir("limits-passwd");
    const fs::path gltf = model(dir, "\"uri\": \"texture.png\"", "\"uri\": \"../../../../etc/passwd\"");
    expectRefusal(render(gltf, dir / "out.png"), {"images[0].uri '../../../../etc/passwd'", "leaves the folder",
                                                  "--allow-external-files"}, dir / "out.png");
}

TEST(CliLimits, GltfAbsoluteAndPercentEncodedUrisAreRefused)
{
    const fs::path dir = tempDir("limits-absolute");
    const fs::path absolute = model(dir / "a", "\"uri\": \"buffer.bin\"", "\"uri\": \"" + (dir / "a/buffer.bin").string() + "\"");
    expectRefusal(render(absolute, dir / "out.png"), {"buffers[0].uri", "is an absolute path", "--allow-external-files"},
                  dir / "out.png");
    // tinygltf percent-decodes URIs: %2e%2e is "..".
    model(dir / "b");
    const fs::path encoded = model(dir / "b/inner", "\"uri\": \"buffer.bin\"", "\"uri\": \"%2e%2e/buffer.bin\"");
    expectRefusal(render(encoded, dir / "out.png"), {"buffers[0].uri '%2e%2e/buffer.bin'", "leaves the folder"}, dir / "out.png");
}

TEST(CliLimits, GltfUriSchemesAreRefusedEvenWhenExternalFilesAreAllowed)
{
    const fs::path dir = tempDir("limits-scheme");
    for (const std::string uri : {"file:///etc/passwd", "http://example.com/buffer.bin"}) {
        const fs::path gltf = model(dir, "\"uri\": \"buffer.bin\"", "\"uri\": \"" + uri + "\"");
        for (const std::string flags : {"", "--allow-external-files"})
            expectRefusal(render(gltf, dir / "out.png", flags), {"buffers[0].uri '" + uri + "'", "URI scheme"}, dir / "out.png");
    }
}

TEST(CliLimits, GltfSymbolicLinkOutOfTheFolderIsRefused)
{
    const fs::path dir = tempDir("limits-symlink");
    model(dir / "outside");
    const fs::path gltf = model(dir / "model");
    fs::remove(dir / "model/texture.png");
    fs::create_symlink(dir / "outside/texture.png", dir / "model/texture.png");
    expectRefusal(render(gltf, dir / "out.png"), {"images[0].uri 'texture.png'", "leaves the folder"}, dir / "out.png");
    // A link that stays inside is fine.
    fs::remove(dir / "model/texture.png");
    fs::copy_file(dir / "outside/texture.png", dir / "model/real.png");
    fs::create_symlink("real.png", dir / "model/texture.png");
    expectRendered(render(gltf, dir / "out.png"), dir / "out.png");
}

TEST(CliLimits, SceneFilePathsLeavingTheFolderAreRefused)
{
    const fs::path dir = tempDir("limits-scene");
    model(dir / "models");
    fs::copy_file(kFiles / "env.hdr", dir / "env.hdr");
    writeText(dir / "scenes/model.json", R"({"models": [{"path": "../models/model.gltf"}]})");
    expectRefusal(render(dir / "scenes/model.json", dir / "out.png"),
                  {"models[0].path '../models/model.gltf'", "leaves the folder", "--allow-external-files"}, dir / "out.png");
    expectRendered(render(dir / "scenes/model.json", dir / "out.png", "--allow-external-files"), dir / "out.png");
    fs::remove(dir / "out.png");

    writeText(dir / "scenes/env.json", "{\"environment\": {\"file\": \"" + (dir / "env.hdr").string() + "\"}}");
    expectRefusal(render(dir / "scenes/env.json", dir / "out.png"), {"environment.file", "is an absolute path", "--allow-external-files"},
                  dir / "out.png");
    writeText(dir / "scenes/billboard.json", R"({"billboards": [{"image": "../models/texture.png", "position": [0, 0, 0]}]})");
    expectRefusal(render(dir / "scenes/billboard.json", dir / "out.png"), {"billboards[0].image '../models/texture.png'"},
                  dir / "out.png");
    // Inside the folder: fine.
    writeText(dir / "scene.json", R"({"models": [{"path": "models/model.gltf"}], "environment": {"file": "env.hdr"}})");
    expectRendered(render(dir / "scene.json", dir / "out.png"), dir / "out.png");
}

TEST(CliLimits, GltfInsideASceneFileStaysInItsOwnFolder)
{
    // The scene file may name the model; the model's URIs are held to the model's folder.
    const fs::path dir = tempDir("limits-nested");
    model(dir);
    model(dir / "models", "\"uri\": \"buffer.bin\"", "\"uri\": \"../buffer.bin\"");
    writeText(dir / "scene.json", R"({"models": [{"path": "models/model.gltf"}]})");
    expectRefusal(render(dir / "scene.json", dir / "out.png"), {"models[0]", "buffers[0].uri '../buffer.bin'"}, dir / "out.png");
}

// -- resource limits -------------------------------------------------------------------------

TEST(CliLimits, BufferOverTheLimitIsRefused)
{
    const fs::path dir = tempDir("limits-buffer");
    const fs::path gltf = model(dir); // a buffer of 104 bytes
    expectRefusal(render(gltf, dir / "out.png", "--max-buffer-bytes 100"),
                  {"buffers[0] declares 104 bytes, over the limit of 100 (--max-buffer-bytes)"}, dir / "out.png");
    // A forged byteLength of 1 TB is refused by the default limit, before tinygltf reads anything.
    const fs::path forged = model(dir / "forged", "\"byteLength\": 104", "\"byteLength\": 1000000000000");
    expectRefusal(render(forged, dir / "out.png"), {"buffers[0] declares 1000000000000 bytes", "--max-buffer-bytes"}, dir / "out.png");
    // Units: 1KiB holds it.
    expectRendered(render(gltf, dir / "out.png", "--max-buffer-bytes 1KiB"), dir / "out.png");
}

TEST(CliLimits, BufferFileLargerThanTheLimitIsNotRead)
{
    // byteLength says 104, the file holds 4 KiB: the file's size is checked before it is read.
    const fs::path dir = tempDir("limits-buffer-file");
    const fs::path gltf = model(dir);
    std::ofstream(dir / "buffer.bin", std::ios::app | std::ios::binary) << std::string(4096, '\0');
    expectRefusal(render(gltf, dir / "out.png", "--max-buffer-bytes 1000"), {"buffer.bin is 4200 bytes, over the limit of 1000"},
                  dir / "out.png");
}

TEST(CliLimits, AccessorOverTheLimitIsRefused)
{
    const fs::path dir = tempDir("limits-accessor");
    const fs::path gltf = model(dir);
    expectRefusal(render(gltf, dir / "out.png", "--max-accessor-count 2"),
                  {"accessors[0] declares 3 elements, over the limit of 2 (--max-accessor-count)"}, dir / "out.png");
    const fs::path forged = model(dir / "forged", "\"count\": 3, \"type\": \"VEC2\"", "\"count\": 4000000000, \"type\": \"VEC2\"");
    expectRefusal(render(forged, dir / "out.png"), {"accessors[2] declares 4000000000 elements", "--max-accessor-count"}, dir / "out.png");
}

TEST(CliLimits, ImageOverTheLimitsIsRefusedBeforeDecoding)
{
    const fs::path dir = tempDir("limits-image");
    const fs::path gltf = model(dir); // texture.png is 4x4
    expectRefusal(render(gltf, dir / "out.png", "--max-image-size 3"),
                  {"image 0 is 4x4 pixels, over the limit of 3 per side (--max-image-size)"}, dir / "out.png");
    expectRefusal(render(gltf, dir / "out.png", "--max-texture-memory 32"), {"image 0 (4x4)", "over the limit of 32 (--max-texture-memory)"},
                  dir / "out.png");
    // A PNG of 100 bytes whose header says 40000 x 1: refused by the default limit from the
    // header. (stb_image itself refuses images over 1 GiB decoded, 40000 x 40000 say.)
    std::string png = readText(dir / "texture.png");
    const unsigned char size[8] = {0, 0, 0x9c, 0x40, 0, 0, 0, 1};
    png.replace(16, 8, reinterpret_cast<const char*>(size), 8); // IHDR width and height (its CRC no longer matches)
    std::ofstream(dir / "texture.png", std::ios::binary) << png;
    expectRefusal(render(gltf, dir / "out.png"), {"image 0 is 40000x1 pixels", "--max-image-size"}, dir / "out.png");
}

TEST(CliLimits, TextureOverTheGlLimitIsDownscaledWithAWarning)
{
    // 16400 x 2 is over llvmpipe's GL_MAX_TEXTURE_SIZE (16384) and under --max-image-size.
    const fs::path dir = tempDir("limits-downscale");
    const fs::path gltf = model(dir);
    specula::ImageRGBA8 wide;
    wide.width = 16400;
    wide.height = 2;
    wide.pixels.assign(size_t(wide.width) * 2 * 4, 200);
    specula::writePng(dir / "texture.png", wide);
    const CliResult r = render(gltf, dir / "out.png");
    expectRendered(r, dir / "out.png");
    EXPECT_NE(r.err.find("is 16400x2, larger than this GPU's texture limit of 16384; downscaled to 16384x1"), std::string::npos) << r.err;
    EXPECT_EQ(r.errorLines(), 0) << r.err; // a warning, and no GL error (which fails a render)
}

// -- numbers ---------------------------------------------------------------------------------

TEST(CliLimits, NonFiniteNumbersAreRefused)
{
    const fs::path dir = tempDir("limits-numbers");
    for (const std::string flags : {"--exposure nan", "--exposure inf", "--env-intensity nan", "--env-rotation 1e999",
                                    "--bloom-intensity nan", "--ssao-radius -inf", "--ev100 NaN", "--bloom-threshold 0x1p99999"})
        expectRefusal(runCli("render -o " + (dir / "out.png").string() + " --width 8 --height 8 " + flags), {"not a finite number"},
                      dir / "out.png");
    expectRefusal(runCli("render -o " + (dir / "out.png").string() + " --env-color nan,1,1"), {"--env-color"}, dir / "out.png");
    // The scene file's numbers: JSON has no NaN or infinity, but 1e300 is one as a float.
    writeText(dir / "scene.json", R"({"render": {"exposure": 1e300}})");
    expectRefusal(render(dir / "scene.json", dir / "out.png"), {"render.exposure"}, dir / "out.png");
}

// -- crash safety of outputs -----------------------------------------------------------------

TEST(CliLimits, RenderKilledWhileWritingLeavesNoPartialFile)
{
    // A large EXR takes long enough to write (ZIP compression of 4096 x 4096 halves) that the
    // process can be caught with its output file open, and killed with SIGKILL: nothing can
    // clean up after that. The old image must survive unchanged, and no other file appear.
    const fs::path dir = tempDir("limits-kill");
    const fs::path output = dir / "out.exr";
    writeText(output, "the previous image");
    const std::string cli = SPECULA_CLI_PATH;
    std::vector<std::string> args = {cli, "render", "-o", output.string(), "--width", "4096", "--height", "4096", "--msaa", "1",
                                     "--env", "none", "--no-cache"};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, cli.c_str(), &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);

    // Wait for a descriptor open on a new file in the output's directory (not the old image)
    // with bytes in it: the image is being written (checkOutputPath's probe, earlier, is empty).
    bool caught = false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
    const fs::path fds = fs::path("/proc") / std::to_string(pid) / "fd";
    while (!caught && std::chrono::steady_clock::now() < deadline) {
        std::error_code ec;
        for (const auto& fd : fs::directory_iterator(fds, ec)) {
            const fs::path target = fs::read_symlink(fd.path(), ec);
            if (ec || target.parent_path() != dir || target == output) continue;
            const uintmax_t size = fs::file_size(fd.path(), ec); // follows the link, to the file open
            if (!ec && size > 0) caught = true;
        }
        if (ec && waitpid(pid, nullptr, WNOHANG) == pid) break; // exited first
        if (!caught) std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    ASSERT_TRUE(caught) << "never saw the render write its file";
    ::kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "finished before it was killed";

    std::vector<std::string> entries;
    for (const auto& entry : fs::directory_iterator(dir)) entries.push_back(entry.path().filename().string());
    EXPECT_EQ(entries, std::vector<std::string>{"out.exr"}) << "a partial or temporary file was left";
    EXPECT_EQ(readText(output), "the previous image");
}
