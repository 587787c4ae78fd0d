#include "device/device_environment.h"

#include "scene/environment_map.h"

namespace rad {

EnvironmentTables buildEnvironmentTables(const Scene& scene) {
    EnvironmentTables tables;
    if (!scene.environment) {
        for (int c = 0; c < 3; ++c) tables.info.sky[c] = scene.sky[c];
        tables.texels.resize(1, rad_float4{});
        tables.rows.assign(1, 0u);
        tables.columns.assign(1, 0u);
        return tables;
    }
    const EnvironmentMap& map = *scene.environment;
    tables.info.width = static_cast<rad_uint>(map.width);
    tables.info.height = static_cast<rad_uint>(map.height);
    tables.texels.reserve(map.radiance.size());
    for (const glm::vec3& texel : map.radiance) tables.texels.push_back({{texel.x, texel.y, texel.z, 0.0f}});
    EnvironmentSampling sampling = environmentSampling(map);
    tables.rows = std::move(sampling.rows);
    tables.columns = std::move(sampling.columns);
    return tables;
}

}  // namespace rad
