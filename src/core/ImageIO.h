#pragma once
// Image files: 8-bit PNG for display-ready images, Radiance .hdr and OpenEXR for linear radiance.
// Every function throws specula::Error with one line naming the file.
#include <cstdint>
#include <filesystem>
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

/// Any 8-bit image stb_image decodes (PNG, JPEG, TGA, BMP...), expanded to RGBA.
/// Errors read "cannot read <path>: <reason>" (missing, truncated, not an image).
ImageRGBA8 readPng(const std::filesystem::path& path);
/// True when `bytes` start with a PNG or a JPEG signature: the encoded images glTF allows, and
/// the only ones Specula hands to stb_image's 8-bit decoders (its others have had memory bugs:
/// Debian 12's reads a 16-bit PNM past the end of its own buffer).
bool isPngOrJpeg(const void* bytes, size_t size);
/// Why stb_image must not decode this JPEG, or "" (also for what is not a JPEG): a Huffman table
/// of more than 256 codes. Debian 12's stb_image (2.27) copies each table's code lengths and
/// values into 257- and 256-entry arrays without checking the count (up to 16 × 255), writing
/// past them on the heap; the JPEG standard allows 256 at most, and stb 2.28 refuses more.
/// Every DHT segment is walked, before and between the scans of a progressive JPEG.
std::string jpegDefect(const void* bytes, size_t size);
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
