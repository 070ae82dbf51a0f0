// PNG and JPEG decoding (core/ImageDecode.cpp, libpng and libjpeg-turbo). The images are encoded
// here, with the libraries' own encoders, from known pixels: the expectation is those pixels
// (exactly for PNG, within the codec's error for JPEG at quality 100 without subsampling).
#include <gtest/gtest.h>

#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <jpeglib.h>
#include <png.h>

#include "TestFiles.h"
#include "core/ImageIO.h"

namespace fs = std::filesystem;
using namespace specula;
using test::errorOf;
using test::readFile;
using test::TempDir;

namespace {

const fs::path kSeeds = fs::path(SPECULA_SOURCE_DIR) / "fuzz/seeds/texture";

/// A PNG of `samples` (channels per pixel from the colour type; big-endian 16-bit when depth is
/// 16, packed for depths under 8), written by libpng. `palette`/`trns` for palette images.
std::string encodePng(int width, int height, int depth, int colour, const std::vector<uint8_t>& rows, bool interlace = false,
                      const std::vector<png_color>& palette = {}, const std::vector<png_byte>& trns = {})
{
    std::string out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        ADD_FAILURE() << "libpng could not encode the test image";
        png_destroy_write_struct(&png, &info);
        return {};
    }
    png_set_write_fn(
        png, &out, [](png_structp p, png_bytep data, size_t n) { static_cast<std::string*>(png_get_io_ptr(p))->append(reinterpret_cast<char*>(data), n); },
        nullptr);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), depth, colour,
                 interlace ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (!palette.empty()) png_set_PLTE(png, info, palette.data(), int(palette.size()));
    if (!trns.empty()) png_set_tRNS(png, info, trns.data(), int(trns.size()), nullptr);
    png_write_info(png, info);
    const size_t rowBytes = rows.size() / size_t(height);
    std::vector<png_bytep> pointers;
    for (int y = 0; y < height; ++y) pointers.push_back(const_cast<png_bytep>(rows.data()) + rowBytes * size_t(y));
    png_write_image(png, pointers.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return out;
}

DecodedImage decode(const std::string& bytes)
{
    return decodePngOrJpeg(bytes.data(), bytes.size());
}

/// A JPEG written by libjpeg-turbo from 8-bit `pixels` of `components` (1 grey, 3 RGB).
std::string encodeJpeg(int width, int height, int components, const std::vector<uint8_t>& pixels, bool progressive)
{
    jpeg_compress_struct info{};
    jpeg_error_mgr errors{};
    info.err = jpeg_std_error(&errors);
    jpeg_create_compress(&info);
    unsigned char* buffer = nullptr;
    unsigned long size = 0;
    jpeg_mem_dest(&info, &buffer, &size);
    info.image_width = JDIMENSION(width);
    info.image_height = JDIMENSION(height);
    info.input_components = components;
    info.in_color_space = components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_set_defaults(&info);
    jpeg_set_quality(&info, 100, TRUE);
    for (int c = 0; c < info.num_components; ++c) info.comp_info[c].h_samp_factor = info.comp_info[c].v_samp_factor = 1;
    if (progressive) jpeg_simple_progression(&info);
    jpeg_start_compress(&info, TRUE);
    while (info.next_scanline < info.image_height) {
        JSAMPROW row = const_cast<JSAMPROW>(pixels.data()) + size_t(info.next_scanline) * size_t(width) * size_t(components);
        jpeg_write_scanlines(&info, &row, 1);
    }
    jpeg_finish_compress(&info);
    jpeg_destroy_compress(&info);
    std::string out(reinterpret_cast<char*>(buffer), size);
    std::free(buffer);
    return out;
}

/// A smooth colour gradient (JPEG's quantisation is least at low frequencies).
std::vector<uint8_t> gradient(int width, int height, int components)
{
    std::vector<uint8_t> pixels;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < components; ++c) pixels.push_back(uint8_t((x * 4 + y * 2 + c * 60) % 256 / 2 + 32));
    return pixels;
}

int largestError(const DecodedImage& decoded, const std::vector<uint8_t>& pixels, int components)
{
    int worst = 0;
    for (size_t i = 0; i < pixels.size() / size_t(components); ++i)
        for (int c = 0; c < 4; ++c) {
            const int expected = c == 3 ? 255 : pixels[i * size_t(components) + size_t(components == 1 ? 0 : c)];
            worst = std::max(worst, std::abs(int(decoded.image.pixels[i * 4 + size_t(c)]) - expected));
        }
    return worst;
}

} // namespace

TEST(ImageDecode, PngsOfEveryColourTypeAndDepthBecomeRgba8)
{
    // 3 x 2 pixels each; the expected RGBA written out by hand from the samples.
    struct Case {
        const char* name;
        int depth, colour;
        std::vector<uint8_t> rows;
        std::vector<uint8_t> rgba;
        bool interlace = false;
    };
    const std::vector<Case> cases = {
        {"grey 8", 8, PNG_COLOR_TYPE_GRAY, {0, 100, 255, 7, 8, 9},
         {0, 0, 0, 255, 100, 100, 100, 255, 255, 255, 255, 255, 7, 7, 7, 255, 8, 8, 8, 255, 9, 9, 9, 255}},
        // 1-bit grey: one byte per row (0b101xxxxx, 0b010xxxxx), expanded to 0 or 255.
        {"grey 1", 1, PNG_COLOR_TYPE_GRAY, {0xa0, 0x40},
         {255, 255, 255, 255, 0, 0, 0, 255, 255, 255, 255, 255, 0, 0, 0, 255, 255, 255, 255, 255, 0, 0, 0, 255}},
        // 4-bit grey: 0..15 scaled by 17.
        {"grey 4", 4, PNG_COLOR_TYPE_GRAY, {0x0f, 0x30, 0x12, 0x40},
         {0, 0, 0, 255, 255, 255, 255, 255, 51, 51, 51, 255, 17, 17, 17, 255, 34, 34, 34, 255, 68, 68, 68, 255}},
        {"grey+alpha 8", 8, PNG_COLOR_TYPE_GRAY_ALPHA, {10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120},
         {10, 10, 10, 20, 30, 30, 30, 40, 50, 50, 50, 60, 70, 70, 70, 80, 90, 90, 90, 100, 110, 110, 110, 120}},
        {"rgb 8", 8, PNG_COLOR_TYPE_RGB, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18},
         {1, 2, 3, 255, 4, 5, 6, 255, 7, 8, 9, 255, 10, 11, 12, 255, 13, 14, 15, 255, 16, 17, 18, 255}},
        {"rgba 8 interlaced", 8, PNG_COLOR_TYPE_RGBA,
         {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24},
         {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24}, true},
        // 16-bit: v * 257 must come back as v exactly, and other values rounded (0x8080 → 128,
        // 0x00ff → 1: 255 * 255 / 65535 = 0.99).
        {"rgb 16", 16, PNG_COLOR_TYPE_RGB,
         {0x01, 0x01, 0x80, 0x80, 0xff, 0xff, 0x00, 0xff, 0x00, 0x00, 0x7f, 0x7f, 0, 0, 0, 0, 0, 0,
          0x12, 0x12, 0x34, 0x34, 0x56, 0x56, 0xab, 0xab, 0xcd, 0xcd, 0xef, 0xef, 0xff, 0x00, 0x00, 0x80, 0x01, 0x00},
         {1, 128, 255, 255, 1, 0, 127, 255, 0, 0, 0, 255, 0x12, 0x34, 0x56, 255, 0xab, 0xcd, 0xef, 255, 254, 0, 1, 255}},
        {"grey+alpha 16", 16, PNG_COLOR_TYPE_GRAY_ALPHA,
         {0x10, 0x10, 0xff, 0xff, 0x20, 0x20, 0x00, 0x00, 0x30, 0x30, 0x80, 0x80,
          0x40, 0x40, 0x40, 0x40, 0x50, 0x50, 0x60, 0x60, 0x70, 0x70, 0x90, 0x90},
         {16, 16, 16, 255, 32, 32, 32, 0, 48, 48, 48, 128, 64, 64, 64, 64, 80, 80, 80, 96, 112, 112, 112, 144}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const DecodedImage decoded = decode(encodePng(3, 2, c.depth, c.colour, c.rows, c.interlace));
        ASSERT_EQ(decoded.error, "");
        EXPECT_EQ(decoded.image.width, 3);
        EXPECT_EQ(decoded.image.height, 2);
        EXPECT_EQ(decoded.image.pixels, c.rgba);
    }
    // A palette with transparency (tRNS): indices 0, 1, 2, 1, 0, 2 (8 bits each).
    const std::vector<png_color> palette = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
    const DecodedImage indexed =
        decode(encodePng(3, 2, 8, PNG_COLOR_TYPE_PALETTE, {0, 1, 2, 1, 0, 2}, false, palette, {255, 128}));
    ASSERT_EQ(indexed.error, "");
    EXPECT_EQ(indexed.image.pixels, (std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 255,
                                                          0, 255, 0, 128, 255, 0, 0, 255, 0, 0, 255, 255}));
    // And the size read from the header alone.
    const std::string png = encodePng(3, 2, 8, PNG_COLOR_TYPE_GRAY, {0, 0, 0, 0, 0, 0});
    const auto size = encodedImageSize(png.data(), png.size());
    ASSERT_TRUE(size);
    EXPECT_EQ(size->width, 3);
    EXPECT_EQ(size->height, 2);
}

TEST(ImageDecode, JpegsDecodeWithinTheCodecsError)
{
    // Quality 100, no chroma subsampling: libjpeg-turbo's encoder and decoder together stay
    // within 3 of the pixels encoded on a smooth gradient (measured: 1 to 2). Baseline and
    // progressive, RGB and greyscale (expanded to RGB).
    for (const int components : {3, 1})
        for (const bool progressive : {false, true}) {
            SCOPED_TRACE(testing::Message() << components << " components" << (progressive ? ", progressive" : ""));
            const std::vector<uint8_t> pixels = gradient(40, 24, components);
            const std::string jpeg = encodeJpeg(40, 24, components, pixels, progressive);
            const auto size = encodedImageSize(jpeg.data(), jpeg.size());
            ASSERT_TRUE(size);
            EXPECT_EQ(size->width, 40);
            EXPECT_EQ(size->height, 24);
            const DecodedImage decoded = decode(jpeg);
            ASSERT_EQ(decoded.error, "");
            EXPECT_EQ(decoded.warning, "");
            ASSERT_EQ(decoded.image.width, 40);
            ASSERT_EQ(decoded.image.height, 24);
            EXPECT_LE(largestError(decoded, pixels, components), 3);
        }
}

TEST(ImageDecode, TruncatedJpegsAreErrorsNotGreyPictures)
{
    // libjpeg decodes a cut file with a warning, grey where the data stopped; that is refused.
    const std::string jpeg = encodeJpeg(40, 24, 3, gradient(40, 24, 3), false);
    for (const size_t size : {jpeg.size() - 2, jpeg.size() * 3 / 4, jpeg.size() / 2}) {
        SCOPED_TRACE(size);
        const DecodedImage decoded = decode(jpeg.substr(0, size));
        EXPECT_EQ(decoded.error, "the file is truncated");
        EXPECT_TRUE(decoded.image.pixels.empty());
    }
    TempDir dir;
    const fs::path cut = dir.write("cut.jpg", jpeg.substr(0, jpeg.size() / 2));
    EXPECT_EQ(errorOf([&] { readPng(cut); }), "cannot read " + cut.string() + ": the file is truncated");
    // A header cut short has no size, and is an error too.
    EXPECT_FALSE(encodedImageSize(jpeg.data(), 40));
    EXPECT_NE(decode(jpeg.substr(0, 40)).error, "");
}

TEST(ImageDecode, ProgressiveJpegsOfThousandsOfScansAreRefused)
{
    // Each scan is a pass over the image: a few kilobytes of repeated scans kept libjpeg busy
    // for minutes. The progressive file's last scan (an AC refinement) repeated: 400 scans in
    // all decode (libjpeg warns of the bogus progression; the refinements repeated change the
    // picture a little, so only its size is checked), 600 are refused.
    const std::vector<uint8_t> pixels = gradient(16, 16, 3);
    const std::string jpeg = encodeJpeg(16, 16, 3, pixels, true);
    const size_t lastScan = jpeg.rfind("\xff\xda"), end = jpeg.rfind("\xff\xd9");
    ASSERT_NE(lastScan, std::string::npos);
    ASSERT_EQ(end, jpeg.size() - 2);
    size_t scans = 0;
    for (size_t at = jpeg.find("\xff\xda"); at != std::string::npos; at = jpeg.find("\xff\xda", at + 2)) ++scans;
    const auto withScans = [&](size_t total) {
        std::string out = jpeg.substr(0, end);
        for (size_t i = scans; i < total; ++i) out += jpeg.substr(lastScan, end - lastScan);
        return out + "\xff\xd9";
    };
    const DecodedImage many = decode(withScans(400));
    ASSERT_EQ(many.error, "");
    EXPECT_NE(many.warning, "");
    EXPECT_EQ(many.image.width, 16);
    EXPECT_EQ(many.image.pixels.size(), size_t(16 * 16 * 4));
    EXPECT_EQ(decode(withScans(600)).error, "more than 500 scans");
}

TEST(ImageDecode, StbImagesFuzzFindingsAreOrdinaryErrorsNow)
{
    // The inputs on which fuzz_texture found Debian 12's stb_image 2.27 writing past its
    // Huffman tables (a table of 257 codes; one running past the end of the file) and shifting
    // a 32-bit value by 32 in its bit reader (UBSan). libjpeg-turbo refuses the first two and
    // decodes the third with a warning; under the sanitizers (make test-sanitize) any report
    // from these calls fails the test.
    for (const char* name : {"huffman-257.jpg", "huffman-truncated.jpg"}) {
        SCOPED_TRACE(name);
        const DecodedImage decoded = decode(readFile(kSeeds / name));
        EXPECT_NE(decoded.error, "");
        EXPECT_EQ(decoded.error.find('\n'), std::string::npos);
    }
    EXPECT_EQ(decode(readFile(kSeeds / "huffman-257.jpg")).error, "Bogus Huffman table definition");
    const DecodedImage shift = decode(readFile(kSeeds / "stb-jpeg-shift32.jpg"));
    EXPECT_EQ(shift.error.find('\n'), std::string::npos);
    TempDir dir;
    const fs::path bad = dir.write("huffman.jpg", readFile(kSeeds / "huffman-257.jpg"));
    EXPECT_EQ(errorOf([&] { readPng(bad); }), "cannot read " + bad.string() + ": not a readable image (Bogus Huffman table definition)");
}
