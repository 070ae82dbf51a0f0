#pragma once
// The viewer's camera: orbits a target (left drag), pans (right or middle drag), zooms
// (wheel), frames the scene (F); in fly mode it turns about its own position (WASD + mouse).
#include <glm/glm.hpp>

#include "render/View.h"
#include "scene/Scene.h"

namespace specula::viewer {

class OrbitCamera {
public:
    /// Looks at `bounds` from the front (+Z), slightly above, far enough to see all of it.
    void frame(const scene::Bounds& bounds);

    /// Turns about the target by degrees: yaw about world +Y, pitch up (clamped short of the poles).
    void orbit(float yawDegrees, float pitchDegrees);
    /// Moves target and eye in the view plane by fractions of the view's height at the target.
    void pan(float dx, float dy);
    /// Divides the distance to the target by `factor` (> 1 comes closer).
    void zoom(float factor);
    /// Fly mode: turns about the eye.
    void look(float yawDegrees, float pitchDegrees);
    /// Fly mode: moves eye and target by (right, up, forward) metres.
    void move(const glm::vec3& rightUpForward);

    glm::vec3 eye() const;
    glm::vec3 target() const { return mTarget; }
    float distance() const { return mDistance; }
    /// Metres per second a fly step should cover: a fraction of the framed size.
    float flySpeed() const { return mSceneRadius; }
    render::View view(float aspect) const;

private:
    glm::vec3 direction() const; ///< unit vector from the target to the eye
    glm::vec3 mTarget{0.0f};
    float mDistance = 3.0f;
    float mYaw = 0.0f;    ///< degrees about +Y; 0 = eye on +Z
    float mPitch = 15.0f; ///< degrees above the horizon
    float mSceneRadius = 1.0f;
    float mYfov = glm::radians(45.0f);
};

} // namespace specula::viewer
