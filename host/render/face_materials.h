#pragma once
// What the path tracer and the camera pass read per face (kernels/face_material.h): the face's
// diffuse reflectance and emitted radiance (its front patch's), its ideal specular reflection
// or transmission where its material has one (kernels/specular.h), and how far new rays leave a
// surface.

#include <vector>

#include "cl/opencl.h"
#include "prepared/prepared_scene.h"
#include "shared_types.h"

namespace rad {

struct FaceMaterialArrays {
    std::vector<cl_float4> reflectance, emission;  // per face (one entry when there is none)
    std::vector<SpecularFace> specular;            // per face where any face is specular, else one entry
    bool anySpecular = false;
    float lift = 0.0f;                             // 32 ulps of the scene's largest coordinate, metres
};

FaceMaterialArrays faceMaterialArrays(const PreparedScene& scene);

}  // namespace rad
