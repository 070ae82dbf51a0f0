#pragma once
// Image files: 8-bit PNG (and JPEG, read) for display-ready images, Radiance .hdr and OpenEXR for linear radiance.
// Every function throws specula::Error with one line naming the file.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace specula {

/// 8-bit RGBA, tightly packed, top row first.
struct ImageRGBA8 {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels;
};

/// Linear RGBA floats, tightly packed, top row first.
struct ImageFloat {
    int width = 0, height = 0;
    std::vector<float> pixels;
};

// The writers replace the file atomically: they write a temporary file in the same directory
// and rename it, so a failed or interrupted write never leaves a partial image behind.
// Errors read "cannot write <path>: <reason>". `pixels` must hold width * height * 4 values.

/// PNG, 8-bit RGBA.
void writePng(const std::filesystem::path& path, const ImageRGBA8& image);
/// Radiance RGBE (stb_image_write). Alpha is dropped; negative and NaN values are written as 0,
/// which RGBE cannot represent.
void writeHdr(const std::filesystem::path& path, const ImageFloat& image);
/// OpenEXR, half-float RGBA, ZIP compression. Values beyond the half range are clamped to ±65504.
void writeExr(const std::filesystem::path& path, const ImageFloat& image);

/// A PNG or a JPEG file, expanded to 8-bit RGBA (decodePngOrJpeg).
/// Errors read "cannot read <path>: <reason>" (missing, truncated, not an image, over 2^27 pixels).
ImageRGBA8 readPng(const std::filesystem::path& path);
/// True when `bytes` start with a PNG or a JPEG signature: the encoded images glTF allows
/// (besides EXT_texture_webp's), and the only ones Specula decodes to 8 bits.
bool isPngOrJpeg(const void* bytes, size_t size);
struct EncodedImageSize {
    int width = 0, height = 0;
};
/// The size a PNG (its IHDR chunk) or a JPEG (its frame header, read by libjpeg-turbo) declares,
/// without decoding anything: to check limits before an image's worth of memory is allocated.
/// nullopt for anything else, or a header that does not parse.
std::optional<EncodedImageSize> encodedImageSize(const void* bytes, size_t size);
struct DecodedImage {
    ImageRGBA8 image; ///< empty when error is set
    std::string error; ///< why it could not be decoded, or ""
    std::string warning; ///< what libjpeg got past (corrupt data it skipped), or ""
};
/// Decodes a PNG (libpng) or a JPEG (libjpeg-turbo) to 8-bit RGBA, top row first. Palettes,
/// greys and missing alpha are expanded; 16-bit PNG samples are rounded to 8 bits; no gamma or
/// colour-profile conversion. A truncated file is an error, and so is a progressive JPEG of
/// more than 500 scans (each scan is a pass over the image: thousands take minutes). Never
/// throws; sizes are the caller's to limit first (encodedImageSize).
DecodedImage decodePngOrJpeg(const void* bytes, size_t size);
/// A Radiance .hdr or an OpenEXR file (any compression, DWAA/DWAB included; half or float
/// channels; recognised by content, not extension). Alpha is 1 where the file has none.
/// Negative and NaN values (lossy EXR compression rings below zero around bright sources)
/// become 0 so they cannot poison filtering; infinities become the largest half, 65504.
ImageFloat readFloatImage(const std::filesystem::path& path);
/// The same from the file's bytes; `path` names it in messages (the fuzzers read this way).
ImageFloat decodeFloatImage(const std::vector<char>& data, const std::filesystem::path& path);

/// Checks an output path before long work: known extension (.png .hdr .exr, any case), the
/// directory exists and a file can be created in it. Throws Error otherwise.
void checkOutputPath(const std::filesystem::path& path);

} // namespace specula
