#pragma once
// The light from outside the scene as the kernels read it (kernels/environment.h): the uniform
// sky's radiance, or an environment map's texels and sampling tables. DeviceScene uploads them
// with the scene; the camera pass and the path tracer see them where rays leave the scene, and
// the environment's direct light samples them.

#include <cstdint>
#include <vector>

#include "cl/kernel_pack.h"
#include "scene/scene.h"
#include "shared_types.h"

namespace rad {

struct EnvironmentTables {
    EnvironmentInfo info{};  // width 0: uniform (info.sky), a sky or black
    std::vector<rad_float4> texels;
    std::vector<std::uint32_t> rows, columns;  // one placeholder entry each when uniform
};

EnvironmentTables buildEnvironmentTables(const Scene& scene);

}  // namespace rad
