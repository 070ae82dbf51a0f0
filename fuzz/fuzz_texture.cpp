// An encoded image as a glTF texture: wrapped in a .glb as bufferView 0, image 0 of a textured
// material, so it takes the importer's path (the signature check, the size limits read from the
// header, libpng or libjpeg-turbo, the 16-bit rounding). Any exception other than
// specula::Error, any sanitizer report, is a finding. (Debian's libpng and libjpeg-turbo are not
// instrumented: a bad write inside them shows only if it crashes; OSS-Fuzz fuzzes them, built
// with the sanitizers.)
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "FuzzSupport.h"
#include "core/Error.h"
#include "scene/GltfImporter.h"

namespace {

void put32(std::vector<unsigned char>& out, uint32_t v)
{
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
}

std::vector<unsigned char> glbWithImage(const uint8_t* data, size_t size)
{
    std::string json = fmt::format(
        R"({{"asset":{{"version":"2.0"}},"buffers":[{{"byteLength":{0}}}],"bufferViews":[{{"buffer":0,"byteLength":{0}}}],)"
        R"("images":[{{"bufferView":0,"mimeType":"image/png"}}],"textures":[{{"source":0}}],)"
        R"("materials":[{{"pbrMetallicRoughness":{{"baseColorTexture":{{"index":0}}}}}}]}})",
        size);
    while (json.size() % 4) json += ' ';
    const size_t binSize = (size + 3) & ~size_t(3);
    std::vector<unsigned char> glb;
    put32(glb, 0x46546C67);
    put32(glb, 2);
    put32(glb, uint32_t(12 + 8 + json.size() + 8 + binSize));
    put32(glb, uint32_t(json.size()));
    put32(glb, 0x4E4F534A);
    glb.insert(glb.end(), json.begin(), json.end());
    put32(glb, uint32_t(binSize));
    put32(glb, 0x004E4942);
    glb.insert(glb.end(), data, data + size);
    glb.resize(glb.size() + (binSize - size), 0);
    return glb;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    specula::fuzz::quietLogs();
    static const auto options = specula::fuzz::loadOptions();
    try {
        specula::scene::loadGltfFromMemory(glbWithImage(data, size), SPECULA_FUZZ_FILES "/fuzz.glb", options);
    } catch (const specula::Error&) {
    }
    return 0;
}
