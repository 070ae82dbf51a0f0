#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <dlfcn.h>
#include "core/StbImage.h"
#include <unistd.h>

#include "TestFiles.h"
#include "core/ImageIO.h"

namespace fs = std::filesystem;
using namespace specula;
using test::errorOf;
using test::readFile;
using test::TempDir;
using test::writeFile;

namespace {

const fs::path kAssets = SPECULA_ASSETS_DIR;

ImageRGBA8 testPattern8(int width, int height)
{
    ImageRGBA8 image{width, height, {}};
    std::mt19937 random(7);
    for (int i = 0; i < width * height * 4; ++i) image.pixels.push_back(uint8_t(random()));
    return image;
}

/// Linear values over nine decades with random alpha, so the round trips see the exponent range.
ImageFloat testPatternFloat(int width, int height)
{
    ImageFloat image{width, height, {}};
    std::mt19937 random(11);
    std::uniform_real_distribution<float> exponent(-4.0f, 4.5f);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int i = 0; i < width * height; ++i) {
        for (int c = 0; c < 3; ++c) image.pixels.push_back(std::pow(10.0f, exponent(random)));
        image.pixels.push_back(unit(random));
    }
    return image;
}

// Rec. 709 luminance, as the asset README's statistics use.
double luminance(const float* rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

void expectSaneEnvironment(const ImageFloat& image, int width, int height, double meanLuminance)
{
    ASSERT_EQ(image.width, width);
    ASSERT_EQ(image.height, height);
    ASSERT_EQ(image.pixels.size(), size_t(width) * size_t(height) * 4);
    double sum = 0.0;
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
        for (int c = 0; c < 4; ++c) {
            ASSERT_TRUE(std::isfinite(image.pixels[i + c])) << "pixel " << i / 4;
            ASSERT_GE(image.pixels[i + c], 0.0f) << "pixel " << i / 4;
        }
        ASSERT_EQ(image.pixels[i + 3], 1.0f) << "files without alpha read as opaque";
        sum += luminance(&image.pixels[i]);
    }
    // Means from the assets README (unweighted by solid angle). Clamping the few negative
    // DWAB pixels to zero raises an EXR's mean slightly, hence 5%.
    EXPECT_NEAR(sum / double(width * height), meanLuminance, 0.05 * meanLuminance);
}

} // namespace

TEST(ImageIo, PngRoundTripIsExact)
{
    TempDir dir;
    const ImageRGBA8 image = testPattern8(37, 23);
    writePng(dir / "a.png", image);
    const ImageRGBA8 back = readPng(dir / "a.png");
    EXPECT_EQ(back.width, 37);
    EXPECT_EQ(back.height, 23);
    EXPECT_EQ(back.pixels, image.pixels);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.png"});
}

TEST(ImageIo, HdrRoundTripWithinRgbePrecision)
{
    TempDir dir;
    ImageFloat image = testPatternFloat(41, 19);
    image.pixels[0] = -2.0f; // RGBE cannot store negatives: written as 0
    writeHdr(dir / "a.hdr", image);
    const ImageFloat back = readFloatImage(dir / "a.hdr");
    ASSERT_EQ(back.width, 41);
    ASSERT_EQ(back.height, 19);
    ASSERT_EQ(back.pixels.size(), image.pixels.size());
    EXPECT_EQ(back.pixels[0], 0.0f);
    image.pixels[0] = 0.0f;
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
        // RGBE: an 8-bit mantissa per channel under the largest channel's exponent, truncated
        // when written, so each channel is off by less than max(r, g, b) / 128.
        const float maxChannel = std::max({image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]});
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(back.pixels[i + c], image.pixels[i + c], maxChannel / 128.0f) << "pixel " << i / 4;
        EXPECT_EQ(back.pixels[i + 3], 1.0f) << "alpha is not stored";
    }
}

TEST(ImageIo, ExrRoundTripWithinHalfPrecision)
{
    TempDir dir;
    ImageFloat image = testPatternFloat(33, 17);
    image.pixels[0] = 1.0e6f; // beyond the half range: clamped to the largest half
    writeExr(dir / "a.exr", image);
    const ImageFloat back = readFloatImage(dir / "a.exr");
    ASSERT_EQ(back.width, 33);
    ASSERT_EQ(back.height, 17);
    ASSERT_EQ(back.pixels.size(), image.pixels.size());
    EXPECT_EQ(back.pixels[0], 65504.0f);
    for (size_t i = 1; i < image.pixels.size(); ++i) {
        // Half floats round to nearest with an 11-bit significand: relative error ≤ 2^-11 for
        // normal numbers (all values here are ≥ 1e-4 > 2^-14, the smallest normal half).
        const float expected = image.pixels[i];
        EXPECT_NEAR(back.pixels[i], expected, std::ldexp(expected, -11)) << "value " << i;
    }
}

TEST(ImageIo, WritesReplaceExistingFiles)
{
    TempDir dir;
    writePng(dir / "a.png", testPattern8(4, 4));
    const ImageRGBA8 second = testPattern8(8, 2);
    writePng(dir / "a.png", second);
    EXPECT_EQ(readPng(dir / "a.png").pixels, second.pixels);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.png"});
}

TEST(ImageIo, UnknownExtension)
{
    TempDir dir;
    const fs::path path = dir / "x.jpg";
    const std::string expected = "cannot write " + path.string() + ": unknown image format (use .png, .hdr or .exr)";
    EXPECT_EQ(errorOf([&] { writePng(path, testPattern8(2, 2)); }), expected);
    EXPECT_EQ(errorOf([&] { writeExr(path, testPatternFloat(2, 2)); }), expected);
    EXPECT_EQ(errorOf([&] { checkOutputPath(path); }), expected);
    EXPECT_EQ(errorOf([&] { checkOutputPath(dir / "noextension"); }),
              "cannot write " + (dir / "noextension").string() + ": unknown image format (use .png, .hdr or .exr)");
    EXPECT_EQ(errorOf([&] { writeHdr(dir / "x.exr", testPatternFloat(2, 2)); }),
              "cannot write " + (dir / "x.exr").string() + ": this writer writes .hdr files");
    EXPECT_TRUE(dir.entries().empty());
}

TEST(ImageIo, EmptyImageIsAnError)
{
    TempDir dir;
    EXPECT_EQ(errorOf([&] { writePng(dir / "a.png", ImageRGBA8{}); }),
              "cannot write " + (dir / "a.png").string() + ": the image is empty (0x0)");
    EXPECT_TRUE(dir.entries().empty());
}

TEST(ImageIo, UnwritableDirectory)
{
    TempDir dir;
    fs::path locked = dir / "locked";
    fs::create_directory(locked);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
    if (geteuid() == 0) {
        // Root ignores permission bits; sysfs refuses new files even to root.
        if (!fs::is_directory("/sys/kernel")) GTEST_SKIP() << "running as root without /sys";
        locked = "/sys/kernel";
    }
    for (const char* name : {"x.png", "x.hdr", "x.exr"}) {
        const fs::path path = locked / name;
        const std::string expected = "cannot write " + path.string() + ": Permission denied";
        EXPECT_EQ(errorOf([&] { checkOutputPath(path); }), expected);
        const std::string error = errorOf([&] {
            if (path.extension() == ".png") writePng(path, testPattern8(2, 2));
            if (path.extension() == ".hdr") writeHdr(path, testPatternFloat(2, 2));
            if (path.extension() == ".exr") writeExr(path, testPatternFloat(2, 2));
        });
        EXPECT_EQ(error, expected);
        EXPECT_FALSE(fs::exists(path));
    }
    if (locked.string().starts_with(dir.path().string())) {
        EXPECT_TRUE(fs::is_empty(locked));
    }
}

TEST(ImageIo, MissingDirectory)
{
    TempDir dir;
    const fs::path path = dir / "nope" / "x.png";
    EXPECT_EQ(errorOf([&] { checkOutputPath(path); }),
              "cannot write " + path.string() + ": directory " + (dir / "nope").string() + " does not exist");
    EXPECT_EQ(errorOf([&] { writePng(path, testPattern8(2, 2)); }),
              "cannot write " + path.string() + ": No such file or directory");
}

TEST(ImageIo, NoTempFileLeftAfterFailure)
{
    // The destination is a directory: the temp file is written completely, then the rename
    // fails, and the temp file must go.
    TempDir dir;
    for (const char* name : {"d.png", "d.hdr", "d.exr"}) fs::create_directory(dir / name);
    const std::string prefix = "cannot write " + dir.path().string();
    EXPECT_EQ(errorOf([&] { writePng(dir / "d.png", testPattern8(16, 16)); }), prefix + "/d.png: Is a directory");
    EXPECT_EQ(errorOf([&] { writeHdr(dir / "d.hdr", testPatternFloat(16, 16)); }), prefix + "/d.hdr: Is a directory");
    EXPECT_EQ(errorOf([&] { writeExr(dir / "d.exr", testPatternFloat(16, 16)); }), prefix + "/d.exr: Is a directory");
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"d.exr", "d.hdr", "d.png"}));
    for (const char* name : {"d.png", "d.hdr", "d.exr"}) EXPECT_TRUE(fs::is_empty(dir / name));
}

TEST(ImageIo, CheckOutputPathAcceptsWritableTargets)
{
    TempDir dir;
    EXPECT_NO_THROW(checkOutputPath(dir / "a.png"));
    EXPECT_NO_THROW(checkOutputPath(dir / "b.HDR"));
    EXPECT_NO_THROW(checkOutputPath(dir / "c.exr"));
    EXPECT_TRUE(dir.entries().empty()) << "the probe file must not stay";
    fs::create_directory(dir / "sub.png");
    EXPECT_EQ(errorOf([&] { checkOutputPath(dir / "sub.png"); }),
              "cannot write " + (dir / "sub.png").string() + ": is a directory");
}

TEST(ImageIo, ReadErrors)
{
    TempDir dir;
    const fs::path missing = dir / "missing.png";
    EXPECT_EQ(errorOf([&] { readPng(missing); }), "cannot read " + missing.string() + ": No such file or directory");
    EXPECT_EQ(errorOf([&] { readFloatImage(dir / "missing.exr"); }),
              "cannot read " + (dir / "missing.exr").string() + ": No such file or directory");

    const fs::path text = dir / "text.png";
    writeFile(text, "hello, world\n");
    EXPECT_TRUE(errorOf([&] { readPng(text); }).starts_with("cannot read " + text.string() + ": not a readable image"));
    // Formats stb_image reads but glTF and scene files do not use are not decoded (a 16-bit
    // PGM made Debian 12's stb_image overrun its own buffer).
    writeFile(dir / "p.png", std::string_view("P5 2 1 65535\n\x01\x02\x03\x04", 17));
    EXPECT_EQ(errorOf([&] { readPng(dir / "p.png"); }),
              "cannot read " + (dir / "p.png").string() + ": not a readable image (not a PNG or JPEG file)");
    EXPECT_EQ(errorOf([&] { readFloatImage(text); }),
              "cannot read " + text.string() + ": not a Radiance .hdr or OpenEXR image");

    // An 8-bit image is not a float image, whatever its name.
    writePng(dir / "a.png", testPattern8(2, 2));
    fs::rename(dir / "a.png", dir / "a.hdr");
    EXPECT_EQ(errorOf([&] { readFloatImage(dir / "a.hdr"); }),
              "cannot read " + (dir / "a.hdr").string() + ": not a Radiance .hdr or OpenEXR image");

    EXPECT_EQ(errorOf([&] { readPng(dir.path()); }), "cannot read " + dir.path().string() + ": is a directory");
}

TEST(ImageIo, TruncatedPngIsAnError)
{
    TempDir dir;
    writePng(dir / "a.png", testPattern8(64, 64));
    const std::string bytes = readFile(dir / "a.png");
    for (size_t size : {size_t(0), size_t(8), size_t(40), bytes.size() / 2, bytes.size() - 1}) {
        writeFile(dir / "t.png", std::string_view(bytes).substr(0, size));
        EXPECT_TRUE(errorOf([&] { readPng(dir / "t.png"); }).starts_with("cannot read " + (dir / "t.png").string() + ": "))
            << "truncated to " << size << " bytes";
    }
}

TEST(ImageIo, TruncatedHdrIsAnError)
{
    TempDir dir;
    const std::string bytes = readFile(kAssets / "env" / "studio_1k.hdr");
    ASSERT_GT(bytes.size(), 100000u);
    // Cut inside the header, inside a scanline, and where stb_image would not notice by itself.
    const fs::path path = dir / "t.hdr";
    writeFile(path, std::string_view(bytes).substr(0, 5));
    EXPECT_EQ(errorOf([&] { readFloatImage(path); }),
              "cannot read " + path.string() + ": not a Radiance .hdr or OpenEXR image");
    for (size_t size : {size_t(70), size_t(200), bytes.size() / 3, bytes.size() / 2, bytes.size() - 1}) {
        writeFile(path, std::string_view(bytes).substr(0, size));
        EXPECT_EQ(errorOf([&] { readFloatImage(path); }), "cannot read " + path.string() + ": the file is truncated")
            << "truncated to " << size << " bytes";
    }
}

TEST(ImageIo, CorruptHdrIsAnError)
{
    // A zero run length, which makes Debian's stb_image loop forever.
    TempDir dir;
    std::string bytes = readFile(kAssets / "env" / "studio_1k.hdr");
    const std::string resolution = "-Y 512 +X 1024\n";
    const auto at = std::search(bytes.begin(), bytes.end(), resolution.begin(), resolution.end());
    ASSERT_NE(at, bytes.end());
    const size_t firstCount = size_t(at - bytes.begin()) + resolution.size() + 4; // after the scanline header
    bytes[firstCount] = 0;
    writeFile(dir / "c.hdr", bytes);
    EXPECT_EQ(errorOf([&] { readFloatImage(dir / "c.hdr"); }),
              "cannot read " + (dir / "c.hdr").string() + ": corrupt run-length data");
}

TEST(ImageIo, HdrWhoseHeaderEndsWithANulLineIsWalkedAsStbImageReadsIt)
{
    // fuzz_hdr's finding (a timeout): the line after FORMAT= starts with NUL bytes, which ends
    // the header for stb_image (it reads lines as C strings) but did not for the check that
    // walks the run-length data first, so the walk started at the wrong line, found nothing,
    // and stb_image then looped forever on a zero run length at the end of the data.
    TempDir dir;
    static const char kInput[] =
        "\x23\x3f\x52\x41\x44\x49\x41\x4e\x43\x45\x0a\x23\x20\x4d\x61\x6f\x74\x6f\x73\x68\x6f\x70\x0a\x47"
        "\x41\x4d\x4d\x41\x3d\x31\x0a\x50\x52\x49\x4d\x41\x52\x49\x45\x53\x3d\x30\x20\x30\x20\x30\x20\x30"
        "\x20\x30\x20\x30\x20\x30\x20\x30\x0a\x46\x4f\x52\x4d\x41\x54\x3d\x33\x32\x2d\x62\x69\x74\x5f\x72"
        "\x6c\x65\x5f\x72\x67\x62\x65\x0a\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00"
        "\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00"
        "\x00\x00\x00\x00\x00\x00\x00\x00\x0a\x2d\x59\x20\x35\x31\x32\x20\x2b\x58\x20\x31\x30\x32\x34\x0a"
        "\x02\x02\x04\x00\x32\x2d\x62\x69\x74\x5f\x72\x6c\x65\x5f\x72\x67\x62\x65\x0a\x45\x58\x50\x4f\x53"
        "\x55\x52\x45\x3d\x32\x2e\x30\x0a\x0a\x2d\x65\x01\x66\x85\x65\x0e\x66\x66\x65\x65\x65\x66\x81\x08"
        "\x02\x03\x5a\x80\x65\x65\x31\x66\x66\xb6\x66\x65\x65\x65\x87\x66\x84\x67\x01\x66\x87\x67\x05\x68"
        "\x67\x67\x67\x68\x87\x36\x0a\x02\x02\x67\x8d\x66\x00\x01\x67\x90\x10\x66\x01\x65\x85\x66\x02\x65"
        "\x66\x94\x65\x8c";
    writeFile(dir / "f.hdr", std::string_view(kInput, sizeof kInput - 1));
    EXPECT_EQ(errorOf([&] { readFloatImage(dir / "f.hdr"); }), "cannot read " + (dir / "f.hdr").string() + ": the file is truncated");
}

TEST(ImageIo, TruncatedExrIsAnError)
{
    TempDir dir;
    const std::string bytes = readFile(kAssets / "env" / "studio.exr");
    ASSERT_GT(bytes.size(), 10000u);
    const fs::path path = dir / "t.exr";
    const std::string expected = "cannot read " + path.string() + ": the file is truncated";
    for (size_t size : {size_t(4), size_t(100), size_t(400), bytes.size() / 3, bytes.size() / 2, bytes.size() - 1}) {
        writeFile(path, std::string_view(bytes).substr(0, size));
        EXPECT_EQ(errorOf([&] { readFloatImage(path); }), expected) << "truncated to " << size << " bytes";
    }
    // Our own ZIP-compressed files too.
    writeExr(dir / "a.exr", testPatternFloat(64, 64));
    const std::string ours = readFile(dir / "a.exr");
    writeFile(path, std::string_view(ours).substr(0, ours.size() - 10));
    EXPECT_EQ(errorOf([&] { readFloatImage(path); }), expected);
}

TEST(ImageIo, ReadsDwabExrEnvironments)
{
    // The assets' EXRs are 512x256 half RGB with lossy DWAB compression (see the assets README).
    const std::pair<const char*, double> files[] = {
        {"bridge", 1.296}, {"city", 0.682}, {"studio", 1.849}, {"venice", 0.595}};
    for (const auto& [name, mean] : files) {
        SCOPED_TRACE(name);
        expectSaneEnvironment(readFloatImage(kAssets / "env" / (std::string(name) + ".exr")), 512, 256, mean);
    }
}

TEST(ImageIo, ReadsRadianceEnvironments)
{
    const std::pair<const char*, double> files[] = {{"bridge", 1.304}, {"city", 0.682}, {"lobby", 0.730},
                                                    {"park", 0.524},   {"sky", 0.674},  {"studio", 1.848},
                                                    {"sunset", 0.408}, {"venice", 0.596}};
    for (const auto& [name, mean] : files) {
        SCOPED_TRACE(name);
        expectSaneEnvironment(readFloatImage(kAssets / "env" / (std::string(name) + "_1k.hdr")), 1024, 512, mean);
    }
}

TEST(ImageIo, ReadsModelTextures)
{
    // Real PNG and JPEG files: the truncation check must not reject complete files.
    for (const char* file : {"BoxTextured/CesiumLogoFlat.png", "BreakfastRoom/marble.jpg", "BreakfastRoom/picture3.jpg"}) {
        SCOPED_TRACE(file);
        const ImageRGBA8 image = readPng(kAssets / "models" / file);
        EXPECT_GT(image.width, 0);
        EXPECT_GT(image.height, 0);
        EXPECT_EQ(image.pixels.size(), size_t(image.width) * size_t(image.height) * 4);
    }
}

// -- hostile headers (issue 16) -----------------------------------------------------------------

namespace {

/// Offset of the 4-byte size of attribute `name` in an OpenEXR file's header.
size_t exrAttributeSize(const std::string& bytes, const std::string& name)
{
    const size_t at = bytes.find(name + std::string(1, '\0'));
    EXPECT_NE(at, std::string::npos) << name;
    const size_t type = at + name.size() + 1;
    return bytes.find('\0', type) + 1;
}

} // namespace

TEST(ImageIo, ExrAttributeSizeBeyondTheFileIsAnError)
{
    // OpenEXR allocates an attribute's declared size before reading it: 2 GiB from a file of
    // a few hundred bytes was an out-of-memory kill (found by an earlier fuzzing attempt on
    // issue 16). Checked first now.
    TempDir dir;
    writeExr(dir / "a.exr", testPatternFloat(4, 3));
    std::string bytes = readFile(dir / "a.exr");
    const int32_t huge = 0x7fffffff;
    bytes.replace(exrAttributeSize(bytes, "channels"), 4, reinterpret_cast<const char*>(&huge), 4);
    const std::string message = errorOf([&] { readFloatImage(dir.write("huge.exr", bytes)); });
    EXPECT_NE(message.find("attribute channels declares 2147483647 bytes, more than the file holds"), std::string::npos) << message;
}

TEST(ImageIo, ExrDataWindowFarFromTheOriginIsRead)
{
    // fuzz_exr's finding (fuzz/seeds/exr/window-far-from-origin.exr): a data window whose corner
    // is at (3.7e8, 3.7e8). OpenEXR's ComputeBasePointer, which the reader used, forms the frame
    // buffer's base as pixels - x - y * width by pointer arithmetic, and that overflowed the
    // address space (undefined behaviour; UBSan stops this test under make test-sanitize
    // without the fix). The same 4 x 3 image moved there must read back as it was written.
    TempDir dir;
    const ImageFloat written = testPatternFloat(4, 3);
    writeExr(dir / "a.exr", written);
    const ImageFloat original = readFloatImage(dir / "a.exr");
    std::string bytes = readFile(dir / "a.exr");
    const int32_t x0 = 369098774, y0 = 370546198;
    const int32_t window[4] = {x0, y0, x0 + 3, y0 + 2};
    bytes.replace(exrAttributeSize(bytes, "dataWindow") + 4, 16, reinterpret_cast<const char*>(window), 16);
    // Each chunk starts with its first scanline's y: the one chunk (3 lines, ZIP's 16 a chunk)
    // is found through the offset table after the header (attributes: name, type, size, value).
    size_t at = 8;
    while (bytes[at] != '\0') {
        at = bytes.find('\0', at) + 1; // name
        at = bytes.find('\0', at) + 1; // type
        int32_t size = 0;
        std::memcpy(&size, bytes.data() + at, 4);
        at += 4 + size_t(size);
    }
    uint64_t chunk = 0;
    std::memcpy(&chunk, bytes.data() + at + 1, 8);
    ASSERT_LT(chunk + 4, bytes.size());
    int32_t firstLine = -1;
    std::memcpy(&firstLine, bytes.data() + chunk, 4);
    ASSERT_EQ(firstLine, 0);
    std::memcpy(bytes.data() + chunk, &y0, 4);
    const ImageFloat moved = readFloatImage(dir.write("far.exr", bytes));
    EXPECT_EQ(moved.width, 4);
    EXPECT_EQ(moved.height, 3);
    EXPECT_EQ(moved.pixels, original.pixels);
    // And the fuzzer's own file is an ordinary one-line answer.
    const fs::path found = fs::path(SPECULA_SOURCE_DIR) / "fuzz/seeds/exr/window-far-from-origin.exr";
    try {
        readFloatImage(found);
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
}

TEST(ImageIo, ExrDataWindowOverTheLimitIsAnError)
{
    // OpenEXR sizes its table of line offsets from the data window before reading pixels.
    TempDir dir;
    writeExr(dir / "a.exr", testPatternFloat(4, 3));
    std::string bytes = readFile(dir / "a.exr");
    const int32_t window[4] = {0, 0, 1 << 30, 1 << 30};
    bytes.replace(exrAttributeSize(bytes, "dataWindow") + 4, 16, reinterpret_cast<const char*>(window), 16);
    const std::string message = errorOf([&] { readFloatImage(dir.write("window.exr", bytes)); });
    EXPECT_NE(message.find("unsupported image size"), std::string::npos) << message;
}

TEST(ImageIo, StbImageIsSpeculasOwnCopy)
{
    // Debian's libdraco.so.7 exports a copy of stb_image of its own. With libstb.so linked, the
    // dynamic linker bound every stbi_* call to whichever library came first in the NEEDED
    // list, and that was draco's: every image Specula decoded, and the fuzzers fuzzed, went
    // through draco's copy. core/StbImage.cpp now compiles Debian's headers into the program
    // under names of its own (core/StbImage.h): the function this executable calls must be in
    // the executable itself. (It decodes Radiance files only now: PNG and JPEG are libpng's
    // and libjpeg-turbo's.)
    Dl_info info{};
    ASSERT_NE(dladdr(reinterpret_cast<void*>(&stbi_loadf_from_callbacks), &info), 0);
    ASSERT_NE(info.dli_fname, nullptr);
    std::error_code error;
    EXPECT_TRUE(fs::equivalent(info.dli_fname, "/proc/self/exe", error)) << "stbi_loadf_from_callbacks is from " << info.dli_fname;
    // And nothing this program links takes a stbi_ function from a shared library (binutils' nm
    // on its own dynamic symbol table: with libstb.so linked, 12 of them).
    FILE* pipe = ::popen("nm -D --undefined-only /proc/self/exe 2>&1", "r");
    ASSERT_NE(pipe, nullptr);
    std::string imports;
    char buffer[4096];
    for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) imports.append(buffer, n);
    ASSERT_EQ(::pclose(pipe), 0) << imports;
    EXPECT_NE(imports.find("memcpy"), std::string::npos) << imports; // nm ran and listed the imports
    EXPECT_EQ(imports.find(" stbi"), std::string::npos) << imports;
}

TEST(ImageIo, EmptyAndTinyInputsAreErrors)
{
    // An empty vector's data() is null: stb_image's read callback passed it to memcpy (UBSan).
    for (const std::string& bytes : {std::string(), std::string("#?RADIANCE\n"), std::string("v/1\x01", 4)})
        errorOf([&] { decodeFloatImage(std::vector<char>(bytes.begin(), bytes.end()), "x.hdr"); });
}
