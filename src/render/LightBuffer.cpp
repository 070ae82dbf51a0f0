#include "render/LightBuffer.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstddef>
#include <cstring>
#include <utility>

#include "core/Error.h"
#include "gl/State.h"
#include "shading/LightClusters.h"
#include "shaders/shared/Bindings.h"

namespace specula::render {

namespace {

// A first buffer for a few dozen lights (4 KiB); scenes with more double it as they grow.
constexpr size_t kInitialCapacity = 64;

gl::Buffer makeBuffer(size_t capacity)
{
    // Zero-filled, so that bytes past the count read back the same every time (tests).
    const std::vector<std::byte> zeros(sizeof(shared::LightHeader) + capacity * sizeof(shared::GpuLight));
    return gl::Buffer(zeros.size(), zeros.data(), "lights");
}

} // namespace

// The texels of the view: 16 bytes each, the header one, a light four.
constexpr size_t kTexelBytes = 16;
static_assert(sizeof(shared::LightHeader) == kTexelBytes && sizeof(shared::GpuLight) == 4 * kTexelBytes);

LightBuffer::LightBuffer()
{
    const size_t byStorage = (gl::maxStorageBlockSize() - sizeof(shared::LightHeader)) / sizeof(shared::GpuLight);
    const size_t byTexels = (gl::maxTextureBufferTexels() - 1) / 4;
    mMaxCount = int(std::min<size_t>({byStorage, byTexels, INT32_MAX}));
    allocate(kInitialCapacity);
}

void LightBuffer::allocate(size_t capacity)
{
    if (mTexels) mRetiredTexels = mTexels.id();
    mTexels = {};
    mBuffer = makeBuffer(capacity);
    mTexels = gl::Texture(mBuffer, gl::Format::RGBA32UI, "light texels");
    mCapacity = int(capacity);
}

shared::GpuLight LightBuffer::pack(const PlacedLight& placed, int shadowSlot, float cutoff)
{
    const scene::Light& l = placed.light;
    shared::GpuLight gpu{};
    const bool directional = l.type == scene::Light::Type::Directional;
    gpu.positionRange = glm::vec4(placed.position, directional ? 0.0f : effectiveRange(std::max(l.range, 0.0f), cutoff));
    const glm::vec3 direction = glm::length(placed.direction) > 0.0f ? glm::normalize(placed.direction) : glm::vec3(0, 0, -1);
    gpu.directionType = glm::vec4(direction, float(uint32_t(l.type)));
    gpu.colorIntensity = glm::vec4(l.color, placed.visible ? std::max(l.intensity, 0.0f) : 0.0f);
    // KHR_lights_punctual: 1e-3 keeps inner == outer from dividing by zero (a hard edge).
    const float cosOuter = std::cos(l.outerConeAngle);
    const float scale = 1.0f / std::max(std::cos(l.innerConeAngle) - cosOuter, 1e-3f);
    gpu.spot = glm::vec4(scale, -cosOuter * scale, float(shadowSlot + 1), cosOuter);
    return gpu;
}

void LightBuffer::setAll(const std::vector<PlacedLight>& lights)
{
    if (lights.size() > size_t(mMaxCount))
        throw Error("{} lights: a shader's storage block holds at most {} here (GL_MAX_SHADER_STORAGE_BLOCK_SIZE)", lights.size(), mMaxCount);
    mLights = lights;
    mShadowSlots.assign(mLights.size(), -1);
    mKinds = {};
    for (const PlacedLight& l : mLights) ++mKinds[size_t(l.light.type)];
    ++mRevision;
    size_t capacity = size_t(mCapacity);
    while (capacity < mLights.size()) capacity *= 2;
    capacity = std::min(capacity, std::max(size_t(mMaxCount), size_t(mCapacity))); // doubling never passes the limit
    if (capacity != size_t(mCapacity)) allocate(capacity);
    uploadAll();
}

void LightBuffer::uploadAll()
{
    // Header and lights in one upload; what lies past the count is never read.
    std::vector<std::byte> bytes(offsetOf(count()));
    const shared::LightHeader header{glm::uvec4(uint32_t(mLights.size()), 0u, 0u, 0u)};
    std::memcpy(bytes.data(), &header, sizeof header);
    for (size_t i = 0; i < mLights.size(); ++i) {
        const shared::GpuLight gpu = pack(mLights[i], mShadowSlots[i], mCutoff);
        std::memcpy(bytes.data() + offsetOf(int(i)), &gpu, sizeof gpu);
    }
    mBuffer.update(0, bytes.size(), bytes.data());
}

void LightBuffer::setCutoff(float cutoff)
{
    if (cutoff == mCutoff) return;
    mCutoff = cutoff;
    ++mRevision;
    uploadAll();
}

void LightBuffer::set(int index, const PlacedLight& light)
{
    assert(index >= 0 && index < count());
    --mKinds[size_t(mLights[size_t(index)].light.type)];
    ++mKinds[size_t(light.light.type)];
    mLights[size_t(index)] = light;
    ++mRevision;
    const shared::GpuLight gpu = pack(light, mShadowSlots[size_t(index)], mCutoff);
    mBuffer.update(offsetOf(index), sizeof gpu, &gpu);
}

void LightBuffer::setShadowSlot(int index, int slot)
{
    assert(index >= 0 && index < count());
    if (mShadowSlots[size_t(index)] == slot) return;
    mShadowSlots[size_t(index)] = slot;
    const shared::GpuLight gpu = pack(mLights[size_t(index)], slot, mCutoff);
    mBuffer.update(offsetOf(index) + offsetof(shared::GpuLight, spot), sizeof gpu.spot, &gpu.spot);
}

size_t LightBuffer::offsetOf(int index)
{
    return sizeof(shared::LightHeader) + size_t(index) * sizeof(shared::GpuLight);
}

void LightBuffer::bind(gl::State& state)
{
    // A name GL may hand out again: the binding cache must not take the new view for the old.
    if (mRetiredTexels) state.forgetTexture(std::exchange(mRetiredTexels, 0u));
    state.bindTexture(SPECULA_UNIT_LIGHTS, mTexels);
    state.bindSampler(SPECULA_UNIT_LIGHTS, nullptr);
    gl::bindStorageBuffer(SPECULA_BINDING_LIGHTS, mBuffer);
}

std::vector<PlacedLight> placeLights(const scene::Scene& scene, scene::HiddenNodes hidden)
{
    std::vector<PlacedLight> out;
    for (const auto& instance : scene.lightInstances(hidden))
        out.push_back({scene.lights[size_t(instance.light)], instance.position, instance.direction, instance.visible});
    return out;
}

} // namespace specula::render
