#include "render/View.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "core/Error.h"
#include "scene/Pose.h"

namespace specula::render {

View lookAtView(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float yfov, float aspect, float znear, float zfar)
{
    View v;
    v.view = glm::lookAt(eye, target, up);
    v.projection = glm::perspective(yfov, aspect, znear, zfar);
    v.position = eye;
    return v;
}

View cameraView(const scene::Scene& scene, int index, float aspect, const scene::Pose* pose)
{
    const auto cameras = scene.cameraInstances();
    if (index < 0 || size_t(index) >= cameras.size())
        throw Error("camera {} does not exist (the scene has {} camera{})", index, cameras.size(), cameras.size() == 1 ? "" : "s");
    scene::CameraInstance instance = cameras[size_t(index)];
    scene::Camera camera = scene.cameras[size_t(instance.camera)];
    if (pose) {
        // An animated camera: its node where the pose puts it, its properties as the pose sets them.
        const std::vector<glm::mat4> world = scene::worldMatrices(scene, *pose);
        if (size_t(instance.node) < world.size()) instance.world = world[size_t(instance.node)];
        camera = scene::posedCamera(scene, *pose, instance.camera);
    }
    // Remove scale from the node's world matrix: a camera's frame is rigid.
    glm::mat4 rigid(1.0f);
    rigid[0] = glm::vec4(glm::normalize(glm::vec3(instance.world[0])), 0.0f);
    rigid[1] = glm::vec4(glm::normalize(glm::vec3(instance.world[1])), 0.0f);
    rigid[2] = glm::vec4(glm::normalize(glm::vec3(instance.world[2])), 0.0f);
    rigid[3] = instance.world[3];
    View v;
    v.view = glm::inverse(rigid);
    v.position = glm::vec3(instance.world[3]);
    const float znear = std::max(camera.znear, 1e-4f);
    if (camera.type == scene::Camera::Type::Orthographic) {
        // Keep ymag and fit x to the viewport.
        const float ymag = camera.ymag;
        const float xmag = ymag * aspect;
        v.projection = glm::ortho(-xmag, xmag, -ymag, ymag, znear, camera.zfar > znear ? camera.zfar : znear + 1000.0f);
    } else if (camera.zfar <= 0.0f) {
        v.projection = glm::infinitePerspective(camera.yfov, aspect, znear);
    } else {
        v.projection = glm::perspective(camera.yfov, aspect, znear, camera.zfar);
    }
    return v;
}

View frameBounds(const scene::Bounds& bounds, float aspect, float yfov)
{
    glm::vec3 center(0.0f);
    float radius = 1.0f;
    if (!bounds.empty()) {
        center = bounds.center();
        radius = std::max(bounds.radius(), 1e-3f);
    }
    // Fit the bounding sphere in the narrower of the two fields of view.
    const float xfov = 2.0f * std::atan(std::tan(yfov * 0.5f) * aspect);
    const float fov = std::min(yfov, xfov);
    const float distance = radius / std::sin(fov * 0.5f) * 1.05f;
    const glm::vec3 direction = glm::normalize(glm::vec3(0.0f, 0.25f, 1.0f));
    const glm::vec3 eye = center + direction * distance;
    return lookAtView(eye, center, {0.0f, 1.0f, 0.0f}, yfov, aspect, std::max(distance - radius * 1.5f, distance * 0.01f),
                      distance + radius * 2.0f);
}

View defaultView(const scene::Scene& scene, int index, float aspect, const scene::Pose* pose)
{
    if (index >= 0) return cameraView(scene, index, aspect, pose);
    if (!scene.cameraInstances().empty()) return cameraView(scene, 0, aspect, pose);
    return frameBounds(scene.worldBounds(), aspect);
}

} // namespace specula::render
