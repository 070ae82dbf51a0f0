// A .glb (binary glTF: JSON and BIN chunks, images in bufferViews) through the whole importer: tinygltf, the checks, accessors, images (URIs into
// fuzz/files: buffer.bin, texture.png, texture.jpg; data: URIs), materials, nodes.
// Any exception other than specula::Error, any sanitizer report, is a finding.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "FuzzSupport.h"
#include "core/Error.h"
#include "scene/GltfImporter.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    specula::fuzz::quietLogs();
    static const auto options = specula::fuzz::loadOptions();
    const std::vector<unsigned char> bytes(data, data + size);
    try {
        specula::scene::loadGltfFromMemory(bytes, SPECULA_FUZZ_FILES "/fuzz.glb", options);
    } catch (const specula::Error&) {
    }
    return 0;
}
