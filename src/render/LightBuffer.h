#pragma once
// The punctual lights of a frame in one std430 storage buffer (shaders/shared/LightData.h): a
// header, then the lights, as many as there are. The buffer grows by doubling its capacity,
// so a new buffer is made only when the count outgrows it; editing one light rewrites only
// that light's 64 bytes. Besides memory, the one bound is how many bytes a shader's storage
// block can reach (GL_MAX_SHADER_STORAGE_BLOCK_SIZE: two million lights on llvmpipe).
#include <vector>

#include "gl/Buffer.h"
#include "render/PlacedLight.h"
#include "shaders/shared/LightData.h"

namespace specula::render {

class LightBuffer {
public:
    LightBuffer();

    /// Replaces all lights: uploads the header and the lights in one range (into a new buffer
    /// only when there are more than capacity()). Throws specula::Error, changing nothing, when
    /// they are more than maxCount().
    void setAll(const std::vector<PlacedLight>& lights);
    /// Changes light `index` (< count()); uploads only its bytes.
    void set(int index, const PlacedLight& light);

    int count() const { return int(mLights.size()); }
    /// How many lights the current buffer holds before it must be replaced.
    int capacity() const { return mCapacity; }
    /// The most lights the GL lets a shader reach in one storage block.
    int maxCount() const { return mMaxCount; }
    const PlacedLight& light(int index) const { return mLights[size_t(index)]; }
    const std::vector<PlacedLight>& all() const { return mLights; }
    /// Byte offset of light `index` inside the buffer.
    static size_t offsetOf(int index);
    const gl::Buffer& buffer() const { return mBuffer; }
    void bind() const;

    static shared::GpuLight pack(const PlacedLight& light);

private:
    gl::Buffer mBuffer;
    int mCapacity = 0;
    int mMaxCount = 0;
    std::vector<PlacedLight> mLights;
};

/// The scene's lights in world space.
std::vector<PlacedLight> placeLights(const scene::Scene& scene);

} // namespace specula::render
