// An OpenEXR file through readFloatImage's decoder: the header walk,
// then OpenEXR (every compression). Any exception other than
// specula::Error, any sanitizer report, any hang (-timeout) is a finding.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "FuzzSupport.h"
#include "core/Error.h"
#include "core/ImageIO.h"

#ifndef FUZZ_NAME
#define FUZZ_NAME "fuzz.exr"
#endif

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    specula::fuzz::quietLogs();
    const std::vector<char> bytes(data, data + size);
    try {
        specula::decodeFloatImage(bytes, FUZZ_NAME);
    } catch (const specula::Error&) {
    }
    return 0;
}
