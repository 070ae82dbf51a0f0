#pragma once
// The punctual lights of a frame in one buffer (shaders/shared/LightData.h): a header, then the
// lights, as many as there are, laid out as std430 has them. Shaders read it two ways, the same
// bytes (lights/light_list.glsl): the shading passes through a texel view of it (an RGBA32UI
// buffer texture, four texels a light: on llvmpipe a storage block read per fragment made lit
// frames up to twice as slow), compute passes through the std430 storage block. The buffer
// grows by doubling its capacity, so a new buffer is made only when the count outgrows it;
// editing one light rewrites only that light's 64 bytes. Besides memory, the bounds are how
// much a storage block and a buffer texture can reach (GL_MAX_SHADER_STORAGE_BLOCK_SIZE,
// GL_MAX_TEXTURE_BUFFER_SIZE: two million lights on llvmpipe).
#include <array>
#include <cstdint>
#include <vector>

#include "gl/Buffer.h"
#include "gl/Texture.h"
#include "render/PlacedLight.h"
#include "shaders/shared/LightData.h"

namespace specula::gl {
class State;
}

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
    /// How many of them are directional (every light cluster lists them: FrameData.clusterLists).
    int directionalCount() const { return mKinds[size_t(scene::Light::Type::Directional)]; }
    /// How many are of `type` (the forward programs compile in only the kinds a frame has).
    int countOf(scene::Light::Type type) const { return mKinds[size_t(type)]; }
    /// Goes up whenever a light, the count or the cutoff changes (not a shadow slot): what
    /// the light culling depends on, so that it need not run again while this and the view stay.
    uint64_t revision() const { return mRevision; }
    /// How many lights the current buffer holds before it must be replaced.
    int capacity() const { return mCapacity; }
    /// The most lights the GL lets a shader reach, in a storage block and in a buffer texture.
    int maxCount() const { return mMaxCount; }
    const PlacedLight& light(int index) const { return mLights[size_t(index)]; }
    const std::vector<PlacedLight>& all() const { return mLights; }
    /// Byte offset of light `index` inside the buffer.
    static size_t offsetOf(int index);
    const gl::Buffer& buffer() const { return mBuffer; }
    /// The texel view of buffer() the shading passes read (RGBA32UI, 1 + 4 × capacity() texels).
    const gl::Texture& texels() const { return mTexels; }
    /// Binds the texel view (SPECULA_UNIT_LIGHTS) and the storage block (SPECULA_BINDING_LIGHTS).
    void bind(gl::State& state);

    /// Gives light `index` shadow record `slot` (render/passes/ShadowPass; -1 = none): uploads
    /// its 16-byte spot field, and only when the slot changes. setAll() clears every slot.
    void setShadowSlot(int index, int slot);
    int shadowSlot(int index) const { return mShadowSlots[size_t(index)]; }

    /// The cutoff that gives lights without a range theirs (shading/LightClusters.h,
    /// effectiveRange): a change re-uploads every light.
    void setCutoff(float cutoff);
    float cutoff() const { return mCutoff; }

    /// The light as the GPU holds it: a light without a range gets effectiveRange(0, cutoff).
    static shared::GpuLight pack(const PlacedLight& light, int shadowSlot = -1, float cutoff = kDefaultCutoff);
    /// The default cutoff: 10⁻⁴, an effective range of 100 m.
    static constexpr float kDefaultCutoff = 1e-4f;

private:
    void allocate(size_t capacity);
    void uploadAll();

    gl::Buffer mBuffer;
    gl::Texture mTexels;
    uint32_t mRetiredTexels = 0; ///< the texel view a growth deleted, for gl::State to forget
    int mCapacity = 0;
    int mMaxCount = 0;
    float mCutoff = kDefaultCutoff;
    std::array<int, 3> mKinds{}; ///< lights of each scene::Light::Type
    uint64_t mRevision = 0;
    std::vector<PlacedLight> mLights;
    std::vector<int> mShadowSlots;
};

/// The scene's lights in world space; hidden ones (KHR_node_visibility) only with
/// HiddenNodes::Include, as PlacedLight::visible false.
std::vector<PlacedLight> placeLights(const scene::Scene& scene, scene::HiddenNodes hidden = scene::HiddenNodes::Skip);

} // namespace specula::render
