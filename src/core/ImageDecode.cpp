// PNG and JPEG decoding with Debian's libpng and libjpeg-turbo (core/ImageIO.h).
//
// These replaced stb_image for the 8-bit images (glTF textures, billboard images): instrumented,
// Debian 12's stb_image 2.27 had a heap overflow in its JPEG Huffman tables and undefined
// shifts in its JPEG bit reader within minutes of fuzzing (docs/testing.md#fuzzers). libpng
// and libjpeg-turbo are the reference decoders and are fuzzed continuously by OSS-Fuzz.
//
// Both libraries report errors by longjmp out of their own C frames, back to the setjmp in the
// function that called them. Nothing with a destructor lives in the frames that are skipped
// (theirs), and what the decoding functions own is held in objects whose address libjpeg or
// libpng has, so it is in memory, not in registers, when the jump lands.
#include "core/ImageIO.h"

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <string>

#include <jpeglib.h>
#include <jerror.h>
#include <png.h>

namespace specula {

namespace {

constexpr unsigned char kPngSignature[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

bool isPng(const unsigned char* bytes, size_t size)
{
    return size >= sizeof kPngSignature && std::memcmp(bytes, kPngSignature, sizeof kPngSignature) == 0;
}

bool isJpeg(const unsigned char* bytes, size_t size)
{
    return size >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff;
}

uint32_t bigEndian32(const unsigned char* p)
{
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

// -- JPEG -------------------------------------------------------------------------------------

/// A progressive JPEG may have any number of scans, and each costs a pass over the whole
/// coefficient buffer: a few kilobytes of tiny scans keep libjpeg busy for minutes (libjpeg-turbo
/// documents this and suggests a progress monitor that stops at a limit; its TurboJPEG 3 has a
/// scan limit too). Real encoders write about ten.
constexpr int kMaxJpegScans = 500;

struct JpegDecoder {
    jpeg_decompress_struct info{};
    jpeg_error_mgr errors{};
    jpeg_progress_mgr progress{};
    std::jmp_buf jump{};
    char message[JMSG_LENGTH_MAX] = {};
    bool truncated = false;
    std::string warning;
};

JpegDecoder& decoderOf(j_common_ptr info)
{
    return *static_cast<JpegDecoder*>(info->client_data);
}

[[noreturn]] void jpegFail(j_common_ptr info)
{
    JpegDecoder& decoder = decoderOf(info);
    info->err->format_message(info, decoder.message);
    std::longjmp(decoder.jump, 1);
}

/// Warnings (level -1) are corrupt or missing data that libjpeg got past; the rest is tracing.
void jpegMessage(j_common_ptr info, int level)
{
    if (level >= 0) return;
    JpegDecoder& decoder = decoderOf(info);
    if (info->err->msg_code == JWRN_JPEG_EOF) decoder.truncated = true;
    if (decoder.warning.empty()) {
        char text[JMSG_LENGTH_MAX];
        info->err->format_message(info, text);
        decoder.warning = text;
    }
}

void jpegProgress(j_common_ptr info)
{
    const auto* decompress = reinterpret_cast<j_decompress_ptr>(info);
    if (decompress->input_scan_number > kMaxJpegScans) {
        JpegDecoder& decoder = decoderOf(info);
        std::snprintf(decoder.message, sizeof decoder.message, "more than %d scans", kMaxJpegScans);
        std::longjmp(decoder.jump, 1);
    }
}

/// Sets `decoder` up on `bytes` and reads the header. Failures jump to decoder.jump with
/// decoder.message set: the caller must have called setjmp on it, and calls
/// jpeg_destroy_decompress either way.
void startJpeg(JpegDecoder& decoder, const unsigned char* bytes, size_t size)
{
    decoder.info.err = jpeg_std_error(&decoder.errors);
    decoder.errors.error_exit = jpegFail;
    decoder.errors.emit_message = jpegMessage;
    jpeg_create_decompress(&decoder.info);
    decoder.info.client_data = &decoder;
    decoder.progress.progress_monitor = jpegProgress;
    decoder.info.progress = &decoder.progress;
    jpeg_mem_src(&decoder.info, bytes, static_cast<unsigned long>(size));
    if (jpeg_read_header(&decoder.info, TRUE) != JPEG_HEADER_OK) {
        std::snprintf(decoder.message, sizeof decoder.message, "no image in the data, only tables");
        std::longjmp(decoder.jump, 1);
    }
}

std::string decodeJpeg(const unsigned char* bytes, size_t size, DecodedImage& out)
{
    JpegDecoder decoder;
    if (setjmp(decoder.jump)) {
        jpeg_destroy_decompress(&decoder.info);
        out.image = {};
        return decoder.message;
    }
    startJpeg(decoder, bytes, size);
    // libjpeg-turbo converts YCbCr, RGB and greyscale to RGBA itself; CMYK it cannot, and says so.
    decoder.info.out_color_space = JCS_EXT_RGBA;
    jpeg_start_decompress(&decoder.info);
    if (decoder.info.output_components != 4) {
        std::snprintf(decoder.message, sizeof decoder.message, "%d output components", decoder.info.output_components);
        std::longjmp(decoder.jump, 1);
    }
    out.image.width = int(decoder.info.output_width);
    out.image.height = int(decoder.info.output_height);
    out.image.pixels.resize(size_t(decoder.info.output_width) * decoder.info.output_height * 4);
    while (decoder.info.output_scanline < decoder.info.output_height) {
        JSAMPROW row = out.image.pixels.data() + size_t(decoder.info.output_scanline) * decoder.info.output_width * 4;
        jpeg_read_scanlines(&decoder.info, &row, 1);
    }
    jpeg_finish_decompress(&decoder.info);
    jpeg_destroy_decompress(&decoder.info);
    // A truncated file decodes, grey where the data stopped: a picture that is not the file's.
    if (decoder.truncated) {
        out.image = {};
        return "the file is truncated";
    }
    out.warning = decoder.warning;
    return "";
}

// -- PNG --------------------------------------------------------------------------------------

struct PngDecoder {
    const unsigned char* bytes = nullptr;
    size_t size = 0, position = 0;
    std::jmp_buf jump{};
    std::string message;
};

[[noreturn]] void pngFail(png_structp png, png_const_charp message)
{
    auto& decoder = *static_cast<PngDecoder*>(png_get_error_ptr(png));
    decoder.message = message;
    std::longjmp(decoder.jump, 1);
}

/// Warnings are ancillary chunks libpng skipped (a bad ICC profile, a wrong CRC on text): the
/// pixels are the file's, as with stb_image, which reads no ancillary chunk at all.
void pngWarning(png_structp, png_const_charp) {}

void pngRead(png_structp png, png_bytep out, size_t count)
{
    auto& decoder = *static_cast<PngDecoder*>(png_get_io_ptr(png));
    if (count > decoder.size - decoder.position) png_error(png, "the file is truncated");
    std::memcpy(out, decoder.bytes + decoder.position, count);
    decoder.position += count;
}

std::string decodePng(const unsigned char* bytes, size_t size, DecodedImage& out)
{
    PngDecoder decoder{bytes, size};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &decoder, pngFail, pngWarning);
    if (!png) return "out of memory";
    png_infop info = png_create_info_struct(png);
    std::vector<png_bytep> rows;
    std::vector<uint8_t> samples; // 16-bit images only
    if (setjmp(decoder.jump)) {
        png_destroy_read_struct(&png, &info, nullptr);
        out.image = {};
        return decoder.message;
    }
    if (!info) png_error(png, "out of memory");
    // Image sizes are the callers' to limit (from the header, before anything is decoded).
    png_set_read_fn(png, &decoder, pngRead);
    png_read_info(png, info);
    const png_uint_32 width = png_get_image_width(png, info), height = png_get_image_height(png, info);
    const bool sixteen = png_get_bit_depth(png, info) == 16;
    const int colour = png_get_color_type(png, info);
    // To RGBA at the file's depth: palettes and low-bit greys expanded, tRNS made alpha, grey
    // made RGB, an opaque alpha added where there is none. No gamma or colour-profile change.
    png_set_expand(png);
    if (colour == PNG_COLOR_TYPE_GRAY || colour == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
    png_set_add_alpha(png, sixteen ? 0xffff : 0xff, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    const size_t rowBytes = size_t(width) * 4 * (sixteen ? 2 : 1);
    if (png_get_rowbytes(png, info) != rowBytes) png_error(png, "unexpected row size after conversion to RGBA");
    out.image.width = int(width);
    out.image.height = int(height);
    out.image.pixels.resize(size_t(width) * height * 4);
    uint8_t* target = out.image.pixels.data();
    if (sixteen) {
        samples.resize(rowBytes * height);
        target = samples.data();
    }
    rows.resize(height);
    for (png_uint_32 y = 0; y < height; ++y) rows[y] = target + rowBytes * y;
    png_read_image(png, rows.data());
    png_read_end(png, nullptr); // to IEND: a file cut after its pixels is still truncated
    png_destroy_read_struct(&png, &info, nullptr);
    // 16-bit samples (big-endian) rounded to 8 bits, so 8-bit values stored as 16-bit ones
    // (v * 257) come back exactly.
    if (sixteen)
        for (size_t i = 0; i < out.image.pixels.size(); ++i) {
            const uint32_t v = uint32_t(samples[2 * i]) << 8 | samples[2 * i + 1];
            out.image.pixels[i] = uint8_t((v * 255u + 32767u) / 65535u);
        }
    return "";
}

} // namespace

bool isPngOrJpeg(const void* data, size_t size)
{
    const auto* bytes = static_cast<const unsigned char*>(data);
    return isPng(bytes, size) || isJpeg(bytes, size);
}

std::optional<EncodedImageSize> encodedImageSize(const void* data, size_t size)
{
    const auto* bytes = static_cast<const unsigned char*>(data);
    if (isPng(bytes, size)) {
        // The signature, then IHDR: length 13, "IHDR", width, height (libpng requires it first).
        if (size < 8 + 8 + 8 || std::memcmp(bytes + 12, "IHDR", 4) != 0) return std::nullopt;
        const uint32_t width = bigEndian32(bytes + 16), height = bigEndian32(bytes + 20);
        if (width == 0 || height == 0 || width > PNG_UINT_31_MAX || height > PNG_UINT_31_MAX) return std::nullopt;
        return EncodedImageSize{int(width), int(height)};
    }
    if (!isJpeg(bytes, size)) return std::nullopt;
    JpegDecoder decoder;
    if (setjmp(decoder.jump)) {
        jpeg_destroy_decompress(&decoder.info);
        return std::nullopt;
    }
    startJpeg(decoder, bytes, size);
    const EncodedImageSize result{int(decoder.info.image_width), int(decoder.info.image_height)};
    jpeg_destroy_decompress(&decoder.info);
    return result;
}

DecodedImage decodePngOrJpeg(const void* data, size_t size)
{
    const auto* bytes = static_cast<const unsigned char*>(data);
    DecodedImage out;
    if (size == 0) out.error = "the image data is empty";
    else if (isPng(bytes, size)) out.error = decodePng(bytes, size, out);
    else if (isJpeg(bytes, size)) out.error = decodeJpeg(bytes, size, out);
    else out.error = "not a PNG or JPEG image";
    return out;
}

} // namespace specula
