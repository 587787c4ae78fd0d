#pragma once
// The camera an image is rendered from: the scene's camera by name, its first camera, or a
// default view that frames the whole scene.

#include <string>

#include <glm/vec3.hpp>

#include "scene/scene.h"
#include "shared_types.h"

namespace rad {

struct View {
    std::string name;          // the camera's name, or "default"
    glm::vec3 position{0.0f};
    glm::vec3 right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, -1};  // unit, right-handed
    bool orthographic = false;
    float yfov = 0.785398f;    // perspective: vertical field of view, radians
    float halfHeight = 1.0f;   // orthographic: half the visible height, metres
};

// `cameraName` empty: the scene's first camera, or a default view. Throws InputError when
// the named camera does not exist (the message lists those that do).
View chooseView(const Scene& scene, const std::string& cameraName);

// The kernel's form of the view for an image of width x height (the vertical extent is fixed;
// the horizontal one follows the image's aspect ratio).
CameraRays cameraRays(const View& view, int width, int height);

}  // namespace rad
