#pragma once
// How many GL objects the wrappers hold alive, by kind: a leak shows as a count that grows
// frame after frame (tests/gl/test_soak.cpp, scripts/soak.sh).
#include <cstdint>
#include <string>

namespace specula::gl {

struct ObjectCounts {
    int64_t buffers = 0, textures = 0, samplers = 0, framebuffers = 0, programs = 0, vertexArrays = 0, queries = 0;
    int64_t total() const { return buffers + textures + samplers + framebuffers + programs + vertexArrays + queries; }
    bool operator==(const ObjectCounts&) const = default;
    /// "buffers 12, textures 30, ..."
    std::string describe() const;
};

ObjectCounts liveObjects();

} // namespace specula::gl
