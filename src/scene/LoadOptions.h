#pragma once
// What a loader may do with a file from anywhere (a downloaded model, a batch job's input):
// which other files it may open, and how much it may allocate. The defaults are generous for
// real scenes and refuse what only a forged or corrupt file asks for; the command line changes
// them (--allow-external-files, --max-buffer-bytes, --max-accessor-count, --max-image-size,
// --max-texture-memory, --max-instances).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace specula::scene {

struct LoadLimits {
    /// Bytes of one glTF buffer (its byteLength, or the size of the file a URI names).
    uint64_t maxBufferBytes = uint64_t(2) << 30;
    /// Elements of one accessor.
    uint64_t maxAccessorCount = uint64_t(1) << 28;
    /// Pixels along either side of one image. Above GL's own limit (16384 on llvmpipe and most
    /// GPUs) the renderer downscales with a warning, so this is about memory, not the GPU.
    int maxImageSize = 32768;
    /// Decoded texture memory of one model, RGBA8 bytes over all its images.
    uint64_t maxTextureBytes = uint64_t(2) << 30;
    /// EXT_mesh_gpu_instancing's instances of one model, all nodes together: each is a node and
    /// a draw, so a few bytes of a forged file could otherwise ask for gigabytes of them.
    uint64_t maxInstances = uint64_t(1) << 20;
};

struct LoadOptions {
    /// Let a file name files outside its own folder (absolute paths, `..` above it). Off: a
    /// glTF's URIs and a scene file's paths must resolve inside the directory tree of the file
    /// that names them.
    bool allowExternalFiles = false;
    LoadLimits limits;
};

/// Why `reference` (a URI or path written in a file whose directory is `root`) may not be
/// opened, or nothing when it may: URI schemes (file:, http:, ...) are always refused; absolute
/// paths and paths leaving `root` (through `..` or a symbolic link) unless `allowExternal`.
/// The reason reads as the end of a sentence naming the reference: "leaves the folder of ...".
std::optional<std::string> refuseReference(const std::filesystem::path& root, std::string_view reference,
                                           bool allowExternal);

} // namespace specula::scene
