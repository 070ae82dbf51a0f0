#pragma once
// Camera matrices for a frame.
#include <glm/glm.hpp>

#include "scene/Scene.h"

namespace specula::scene {
struct Pose;
}

namespace specula::render {

struct View {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 position{0.0f};
};

/// The scene's camera `index` (in Scene::cameraInstances() order) for a viewport of `aspect`.
/// The viewport's aspect wins over the camera's aspectRatio so images are never stretched
/// (`specula render` sizes the image to the aspect ratio where it can: setup::fitSizeToCamera).
/// `pose`: an animation's (scene/Pose.h): the camera's node where the pose puts it, and its
/// KHR_animation_pointer properties; none: the rest pose. Throws specula::Error when there is
/// no such camera.
View cameraView(const scene::Scene& scene, int index, float aspect, const scene::Pose* pose = nullptr);

/// A perspective view that frames `bounds` from the front (+Z), slightly above.
View frameBounds(const scene::Bounds& bounds, float aspect, float yfov = glm::radians(45.0f));

/// cameraView(index) if index >= 0; else the first camera; else frameBounds(scene bounds).
View defaultView(const scene::Scene& scene, int index, float aspect, const scene::Pose* pose = nullptr);

View lookAtView(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float yfov, float aspect, float znear, float zfar);

} // namespace specula::render
