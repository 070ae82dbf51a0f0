#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace specula::gl {

struct DeviceInfo {
    std::string vendor;
    std::string renderer;
    std::string version;
    std::string glslVersion;
    /// The implementation limits the renderer relies on, by GL name.
    std::vector<std::pair<std::string, int64_t>> limits;
    /// Extensions the renderer uses, with whether they are present.
    std::vector<std::pair<std::string, bool>> extensions;
};

/// Queries the current context.
DeviceInfo queryDeviceInfo();

/// GL_MAX_COLOR_TEXTURE_SAMPLES and GL_MAX_DEPTH_TEXTURE_SAMPLES of the current context.
/// GL_MAX_TEXTURE_IMAGE_UNITS: texture units of a fragment shader (GL 4.5 promises 16).
int maxTextureUnits();
/// GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS: the units a sampler may name, all stages together.
int maxCombinedTextureUnits();
int maxColorSamples();
int maxDepthSamples();

} // namespace specula::gl
