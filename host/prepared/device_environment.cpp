#include "prepared/device_environment.h"

#include "cl/buffers.h"
#include "scene/environment_map.h"

static_assert(sizeof(EnvironmentInfo) == 32, "EnvironmentInfo must match the kernels' layout");

namespace rad {

std::uint64_t EnvironmentTables::bytes() const {
    return bufferBytes<cl_float4>(texels.size()) + bufferBytes<std::uint32_t>(rows.size()) +
           bufferBytes<std::uint32_t>(columns.size());
}

EnvironmentTables buildEnvironmentTables(const Scene& scene) {
    EnvironmentTables tables;
    if (!scene.environment) {
        for (int c = 0; c < 3; ++c) tables.info.sky[c] = scene.sky[c];
        tables.texels.resize(1, cl_float4{});
        tables.rows.assign(1, 0u);
        tables.columns.assign(1, 0u);
        return tables;
    }
    const EnvironmentMap& map = *scene.environment;
    tables.info.width = static_cast<rad_uint>(map.width);
    tables.info.height = static_cast<rad_uint>(map.height);
    tables.texels.reserve(map.radiance.size());
    for (const glm::vec3& texel : map.radiance) tables.texels.push_back(float4Of(texel));
    EnvironmentSampling sampling = environmentSampling(map);
    tables.rows = std::move(sampling.rows);
    tables.columns = std::move(sampling.columns);
    return tables;
}

DeviceEnvironment uploadEnvironment(ComputeContext& compute, const EnvironmentTables& tables) {
    DeviceEnvironment environment;
    environment.info = tables.info;
    environment.texels = uploadBuffer(compute, tables.texels, "environment map");
    environment.rows = uploadBuffer(compute, tables.rows, "environment map's row table");
    environment.columns = uploadBuffer(compute, tables.columns, "environment map's column tables");
    environment.bytes = tables.bytes();
    return environment;
}

}  // namespace rad
