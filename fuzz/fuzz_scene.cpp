// A JSON scene file (docs/scene-format.md): every section, and the files it names in
// fuzz/files (model.gltf, texture.png, env.hdr). Any exception other than specula::Error, any
// sanitizer report, is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "FuzzSupport.h"
#include "core/Error.h"
#include "scene/SceneFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    specula::fuzz::quietLogs();
    static const auto options = specula::fuzz::loadOptions();
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        specula::scene::loadSceneText(text, SPECULA_FUZZ_FILES "/fuzz.json", options);
    } catch (const specula::Error&) {
    }
    return 0;
}
