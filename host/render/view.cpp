#include "render/view.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "util/error.h"

namespace rad {
namespace {

View fromCamera(const Camera& camera) {
    View v;
    v.name = camera.name;
    v.position = camera.position;
    v.right = glm::normalize(camera.orientation[0]);
    v.up = glm::normalize(camera.orientation[1]);
    v.forward = -glm::normalize(camera.orientation[2]);
    v.orthographic = camera.projection == Camera::Projection::Orthographic;
    v.yfov = camera.yfov;
    v.halfHeight = camera.ymag;
    return v;
}

// Looks at the scene's bounding sphere from its +Z side, slightly above, with a 45 degree
// vertical field of view, far enough that the sphere fits.
View defaultView(const Scene& scene) {
    const Bounds b = scene.bounds();
    const glm::vec3 centre = 0.5f * (b.lo + b.hi);
    const float radius = static_cast<float>(std::clamp(0.5 * b.diagonal(), 1e-6, 1e30));
    View v;
    v.name = "default";
    v.yfov = 0.785398f;
    const glm::vec3 back = glm::normalize(glm::vec3(0.0f, 0.25f, 1.0f));
    v.position = centre + back * (radius / std::sin(0.5f * v.yfov));
    v.forward = -back;
    v.right = glm::normalize(glm::cross(v.forward, glm::vec3(0, 1, 0)));
    v.up = glm::cross(v.right, v.forward);
    return v;
}

void store(float (&out)[4], const glm::vec3& v, float w) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
    out[3] = w;
}

}  // namespace

View chooseView(const Scene& scene, const std::string& cameraName) {
    if (cameraName.empty()) return scene.cameras.empty() ? defaultView(scene) : fromCamera(scene.cameras.front());
    std::string names;
    for (const Camera& c : scene.cameras) {
        if (c.name == cameraName) return fromCamera(c);
        names += (names.empty() ? "" : ", ") + c.name;
    }
    throw InputError(scene.path + ": no camera named '" + cameraName + "' (" +
                     (names.empty() ? "the scene has no cameras" : "it has: " + names) + ")");
}

CameraRays cameraRays(const View& view, int width, int height) {
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const float halfHeight = view.orthographic ? view.halfHeight : std::tan(0.5f * view.yfov);
    CameraRays c{};
    store(c.position, view.position, 0.0f);
    store(c.right, view.right, halfHeight * aspect);
    store(c.up, view.up, halfHeight);
    store(c.forward, view.forward, view.orthographic ? 1.0f : 0.0f);
    return c;
}

}  // namespace rad
