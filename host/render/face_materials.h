#pragma once
// What the path tracer and the camera pass read per face (kernels/face_material.h): the face's
// diffuse reflectance and emitted radiance (its front patch's). Mirrors and glass, and how far
// new rays leave a surface, are the device scene's (DeviceScene::specular and lift).

#include <vector>

#include "cl/opencl.h"
#include "prepared/prepared_scene.h"
#include "shared_types.h"

namespace rad {

struct FaceMaterialArrays {
    std::vector<cl_float4> reflectance, emission;  // per face (one entry when there is none)
};

FaceMaterialArrays faceMaterialArrays(const PreparedScene& scene);

}  // namespace rad
