#include "OrbitCamera.h"

#include <algorithm>
#include <cmath>

namespace specula::viewer {

void OrbitCamera::frame(const scene::Bounds& bounds)
{
    const float radius = bounds.empty() ? 1.0f : std::max(bounds.radius(), 1e-3f);
    mTarget = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
    mSceneRadius = radius;
    // The bounding sphere fits the vertical field of view, with a 10% margin.
    mDistance = 1.1f * radius / std::sin(0.5f * mYfov);
    mYaw = 0.0f;
    mPitch = 15.0f;
}

void OrbitCamera::orbit(float yawDegrees, float pitchDegrees)
{
    mYaw = std::fmod(mYaw + yawDegrees, 360.0f);
    // 89°: at the pole the up vector and the view direction coincide and lookAt degenerates.
    mPitch = std::clamp(mPitch + pitchDegrees, -89.0f, 89.0f);
}

void OrbitCamera::pan(float dx, float dy)
{
    const glm::vec3 forward = -direction();
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, forward);
    const float height = 2.0f * mDistance * std::tan(0.5f * mYfov);
    mTarget += (right * dx + up * dy) * height;
}

void OrbitCamera::zoom(float factor)
{
    if (factor <= 0.0f) return;
    // Never through the target, never out to where the far plane clips everything.
    mDistance = std::clamp(mDistance / factor, 1e-3f * mSceneRadius, 1e3f * mSceneRadius);
}

void OrbitCamera::look(float yawDegrees, float pitchDegrees)
{
    const glm::vec3 eyeBefore = eye();
    orbit(yawDegrees, pitchDegrees);
    mTarget = eyeBefore - direction() * mDistance;
}

void OrbitCamera::move(const glm::vec3& rightUpForward)
{
    const glm::vec3 forward = -direction();
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, forward);
    mTarget += right * rightUpForward.x + up * rightUpForward.y + forward * rightUpForward.z;
}

glm::vec3 OrbitCamera::direction() const
{
    const float yaw = glm::radians(mYaw), pitch = glm::radians(mPitch);
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

glm::vec3 OrbitCamera::eye() const
{
    return mTarget + direction() * mDistance;
}

render::View OrbitCamera::view(float aspect) const
{
    // Near and far follow the distance so depth precision stays where the scene is.
    const float reach = mDistance + 2.0f * mSceneRadius;
    const float znear = std::max(1e-3f, 0.01f * std::min(mDistance, mSceneRadius));
    return render::lookAtView(eye(), mTarget, glm::vec3(0, 1, 0), mYfov, aspect, znear, std::max(reach * 4.0f, 10.0f * znear));
}

} // namespace specula::viewer
