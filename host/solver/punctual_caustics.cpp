#include "solver/punctual_caustics.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "device/device_elements.h"
#include "device/kernel_arguments.h"
#include "shared_math.h"
#include "util/error.h"
#include "util/sample_streams.h"

namespace rad {

namespace {

// Ray `index` of `rays` from the lights (four numbers in [0, 1) from the hash of (key, index)),
// carrying its share of the power: the sample's estimate of the whole over the number of rays.
EmissionSample drawRay(const Emitter& lights, std::uint32_t key, std::uint64_t index, std::uint64_t rays) {
    const std::uint32_t ray = rad_hash2(key, static_cast<std::uint32_t>(index));
    glm::dvec4 u;
    for (int k = 0; k < 4; ++k) u[k] = rad_hash2(ray, static_cast<std::uint32_t>(k)) * 0x1p-32;
    EmissionSample s = lights.sample(u);
    s.power /= static_cast<double>(rays);
    return s;
}

// A 64-bit two's complement sum of the kernel's counters (low word first), as a double.
double counterValue(const std::vector<rad_uint>& words, std::size_t at) {
    const std::uint64_t bits = (static_cast<std::uint64_t>(words[at + 1]) << 32) | words[at];
    std::int64_t value;
    std::memcpy(&value, &bits, sizeof value);
    return static_cast<double>(value);
}

}  // namespace

void addPunctualCaustics(const PreparedScene& scene, const ElementMesh& elements, const Emitter& lights,
                         std::uint32_t seed, std::uint64_t rays, DirectLight& light) {
    const std::size_t count = elements.elements().size();
    if (!scene.device().specularFaces() || count == 0 || rays == 0) return;
    // Ray indices are hashed as 32-bit numbers, and 2^31 rays of below 2^32 quanta each sum below 2^63.
    if (rays > (std::uint64_t{1} << 31)) throw InputError("more than 2^31 rays from the punctual lights");
    const std::uint32_t key = rad_hash2(seed, kPunctualCausticsStream);
    // The quantum: the largest power a ray carries over 2^32, so that every ray's power is an
    // integer below 2^32 and a million of them sum far below 2^63.
    double largest = 0.0;
    for (std::uint64_t r = 0; r < rays; ++r) {
        const glm::dvec3 power = drawRay(lights, key, r, rays).power;
        largest = std::max({largest, power.x, power.y, power.z});
    }
    const double quantum = largest * 0x1p-32;
    if (!(quantum >= std::numeric_limits<double>::min()) || !std::isfinite(largest))
        return;  // no light, or none to count
    ComputeContext& compute = scene.compute();
    const std::size_t columns = 2 * count + 2;  // the shots' columns: elements, escaped, backs, caustic
    constexpr std::size_t kPerLaunch = std::size_t{1} << 18;
    const std::string what = "punctual lights' light through mirrors and glass";
    const std::shared_ptr<const DeviceElements> device = scene.device().elements(elements);
    const DeviceArray<rad_uint> power = DeviceArray<rad_uint>::upload(
        compute, std::vector<rad_uint>(columns * 6, 0u), what + ": sums", DeviceAccess::readWrite);
    DeviceKernel<LightCausticsArgs> kernel = scene.device().kernel<LightCausticsArgs>("shoot.cl", "light_caustics");
    LightCausticsArgs args;
    args.elements = device->nodes;
    args.elementCount = static_cast<rad_uint>(count);
    args.power = power;
    std::vector<rad_float4> batch;
    for (std::uint64_t first = 0; first < rays; first += kPerLaunch) {
        const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(kPerLaunch, rays - first));
        batch.clear();
        for (std::size_t i = 0; i < n; ++i) {
            const EmissionSample s = drawRay(lights, key, first + i, rays);
            const glm::vec3 position(s.position), direction(s.direction), carried(s.power / quantum);
            batch.push_back({{position.x, position.y, position.z, 0.0f}});
            batch.push_back({{direction.x, direction.y, direction.z, 0.0f}});
            batch.push_back({{carried.x, carried.y, carried.z, 0.0f}});
        }
        const DeviceArray<rad_float4> rayArray = DeviceArray<rad_float4>::upload(compute, batch, what + ": rays");
        args.rays = rayArray;
        args.rayCount = static_cast<rad_uint>(n);
        args.key = rad_hash2(key, static_cast<std::uint32_t>(first));
        kernel.launch(args, n);
    }
    const std::vector<rad_uint> sums = power.read();
    auto column = [&](std::size_t c) {
        const std::size_t at = c * 6;
        return quantum * glm::dvec3(counterValue(sums, at), counterValue(sums, at + 2), counterValue(sums, at + 4));
    };
    glm::dvec3 arrived(0.0);
    for (std::size_t e = 0; e < count; ++e) {
        const glm::dvec3 received = column(e), bySpecular = column(count + 2 + e);
        light.arrived[e] += received;
        arrived += received;
        if (bySpecular == glm::dvec3(0.0)) continue;
        if (light.arrivedBySpecular.empty()) light.arrivedBySpecular.assign(count, glm::dvec3(0.0));
        light.arrivedBySpecular[e] += bySpecular;
    }
    const glm::dvec3 backs = column(count + 1);
    light.absorbedByBacks += backs;
    light.escaped -= arrived + backs;
}

}  // namespace rad
