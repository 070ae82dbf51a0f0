#include "render/LightBuffer.h"

#include <algorithm>
#include <cmath>

#include "core/Log.h"
#include "shaders/shared/Bindings.h"

namespace specula::render {

LightBuffer::LightBuffer() : mUbo("lights") {}

shared::GpuLight LightBuffer::pack(const PlacedLight& placed)
{
    const scene::Light& l = placed.light;
    shared::GpuLight gpu{};
    gpu.positionRange = glm::vec4(placed.position, std::max(l.range, 0.0f));
    const glm::vec3 direction = glm::length(placed.direction) > 0.0f ? glm::normalize(placed.direction) : glm::vec3(0, 0, -1);
    gpu.directionType = glm::vec4(direction, float(uint32_t(l.type)));
    gpu.colorIntensity = glm::vec4(l.color, std::max(l.intensity, 0.0f));
    // KHR_lights_punctual: 1e-3 keeps inner == outer from dividing by zero (a hard edge).
    const float cosOuter = std::cos(l.outerConeAngle);
    const float scale = 1.0f / std::max(std::cos(l.innerConeAngle) - cosOuter, 1e-3f);
    gpu.spot = glm::vec4(scale, -cosOuter * scale, 0.0f, 0.0f);
    return gpu;
}

void LightBuffer::setAll(const std::vector<PlacedLight>& lights)
{
    mLights = lights;
    if (mLights.size() > SPECULA_MAX_LIGHTS) {
        log::warn("{} lights, only the first {} are used", mLights.size(), SPECULA_MAX_LIGHTS);
        mLights.resize(SPECULA_MAX_LIGHTS);
    }
    auto& block = mUbo.data();
    block = {};
    block.count = glm::uvec4(uint32_t(mLights.size()), 0, 0, 0);
    for (size_t i = 0; i < mLights.size(); ++i) block.lights[i] = pack(mLights[i]);
    mUbo.upload();
}

void LightBuffer::set(int index, const PlacedLight& light)
{
    mLights[size_t(index)] = light;
    mUbo.data().lights[index] = pack(light);
    mUbo.upload(&shared::LightBlock::lights, size_t(index));
}

size_t LightBuffer::offsetOf(int index) const
{
    return mUbo.offsetOf(&shared::LightBlock::lights, size_t(index));
}

void LightBuffer::bind() const
{
    mUbo.bind(SPECULA_BINDING_LIGHTS);
}

std::vector<PlacedLight> placeLights(const scene::Scene& scene)
{
    std::vector<PlacedLight> out;
    for (const auto& instance : scene.lightInstances())
        out.push_back({scene.lights[size_t(instance.light)], instance.position, instance.direction});
    return out;
}

} // namespace specula::render
