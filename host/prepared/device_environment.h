#pragma once
// The light from outside the scene on the device (kernels/environment.h): the uniform sky's
// radiance, or an environment map's texels and sampling tables. Uploaded with the scene
// (prepared/device_scene.h) and bound by the kernels that see it: the camera pass and the path
// tracer where rays leave the scene, the environment's direct light (light/environment_light.h).

#include <cstdint>

#include "cl/compute_context.h"
#include "scene/scene.h"
#include "shared_types.h"

namespace rad {

struct DeviceEnvironment {
    EnvironmentInfo info{};            // width 0: uniform (info.sky), a sky or black
    cl::Buffer texels, rows, columns;  // one placeholder entry each when uniform
    std::uint64_t bytes = 0;           // device memory they take
    bool mapped() const { return info.width != 0; }
};

// Host copies of what DeviceEnvironment uploads (so DeviceScene can reserve memory first).
struct EnvironmentTables {
    EnvironmentInfo info{};
    std::vector<cl_float4> texels;
    std::vector<std::uint32_t> rows, columns;
    std::uint64_t bytes() const;
};
EnvironmentTables buildEnvironmentTables(const Scene& scene);
DeviceEnvironment uploadEnvironment(ComputeContext& compute, const EnvironmentTables& tables);

}  // namespace rad
