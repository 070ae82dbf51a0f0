#pragma once
// The punctual lights of a frame in one std140 uniform buffer. Editing one light
// rewrites only that light's 64 bytes.
#include <vector>

#include "gl/UniformBuffer.h"
#include "scene/Scene.h"
#include "shaders/shared/LightData.h"

namespace specula::render {

/// A light placed in the world.
struct PlacedLight {
    scene::Light light;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; ///< where it points
};

class LightBuffer {
public:
    LightBuffer();

    /// Replaces all lights (uploads the whole block). Lights beyond SPECULA_MAX_LIGHTS are
    /// dropped with a warning.
    void setAll(const std::vector<PlacedLight>& lights);
    /// Changes light `index` (< count()); uploads only its bytes.
    void set(int index, const PlacedLight& light);

    int count() const { return int(mLights.size()); }
    const PlacedLight& light(int index) const { return mLights[size_t(index)]; }
    /// Byte range of light `index` inside the buffer.
    size_t offsetOf(int index) const;
    const gl::Buffer& buffer() const { return mUbo.buffer(); }
    void bind() const;

    static shared::GpuLight pack(const PlacedLight& light);

private:
    gl::UniformBuffer<shared::LightBlock> mUbo;
    std::vector<PlacedLight> mLights;
};

/// The scene's lights in world space.
std::vector<PlacedLight> placeLights(const scene::Scene& scene);

} // namespace specula::render
