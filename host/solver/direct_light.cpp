#include "solver/direct_light.h"

#include <algorithm>
#include <string>
#include <vector>

#include "device/element_records.h"
#include "device/kernel_arguments.h"
#include "prepared/prepared_scene.h"
#include "shared_math.h"
#include "solver/punctual_caustics.h"
#include "util/sample_streams.h"

namespace rad {

glm::dvec3 DirectLight::total() const {
    glm::dvec3 sum = escaped + absorbedByBacks;
    for (const glm::dvec3& a : arrived) sum += a;
    return sum;
}

namespace {

// Takes a direct-light kernel's result into `light`: per element e, out[stride e] is the mean
// irradiance on its front and out[stride e + 1] on its black back (W / m^2, rgb), each times
// `scale` per channel; with stride 3, out[3e + 2] is the part of the front's that came by way of
// mirrors or glass (environment_direct). Adds the power that arrived at each element, what the
// backs absorbed, and as escaped what of `power` neither received (what glass absorbed on the
// way included). Sums in element order, so they depend on nothing but the elements.
void addFrontsAndBacks(const ElementMesh& elements, const std::vector<rad_float4>& out, std::size_t stride,
                       const glm::dvec3& scale, const glm::dvec3& power, DirectLight& light) {
    glm::dvec3 arrived(0.0), backs(0.0);
    const std::size_t count = elements.elements().size();
    auto rgb = [&](std::size_t i) { return glm::dvec3(out[i].s[0], out[i].s[1], out[i].s[2]); };
    for (std::size_t e = 0; e < count; ++e) {
        const double area = elements.elements()[e].area;
        const glm::dvec3 front = area * rgb(stride * e) * scale;
        const glm::dvec3 back = area * rgb(stride * e + 1) * scale;
        light.arrived[e] += front;
        arrived += front;
        backs += back;
        if (stride < 3) continue;
        const glm::dvec3 bySpecular = area * rgb(stride * e + 2) * scale;
        if (bySpecular == glm::dvec3(0.0)) continue;
        if (light.arrivedBySpecular.empty()) light.arrivedBySpecular.assign(count, glm::dvec3(0.0));
        light.arrivedBySpecular[e] += bySpecular;
    }
    light.absorbedByBacks += backs;
    light.escaped += power - arrived - backs;
}

// The elements as direct_light.cl's kernels read them, uploaded when first needed and once for
// all the lights that need them, and those kernels run over every element.
class ElementLightKernels {
public:
    ElementLightKernels(const PreparedScene& scene, const ElementMesh& elements, SpecularModel model)
        : scene_(scene), elements_(elements), model_(model) {}

    ComputeContext& compute() const { return scene_.compute(); }

    // The kernel `name`, its args' `elements` and `out` filled here, with `perElement` results
    // per element and about `raysPerElement` rays each (launchOverElements); its results.
    template <typename Args>
    std::vector<rad_float4> run(const char* name, Args args, std::size_t perElement, double raysPerElement,
                                const std::string& what) {
        ComputeContext& compute = scene_.compute();
        const std::size_t count = elements_.elements().size();
        if (!uploaded_) {
            records_ = DeviceArray<DirectLightElement>::upload(
                compute, directLightElements(scene_.mesh(), elements_), "direct light: elements");
            uploaded_ = true;
        }
        const DeviceArray<rad_float4> out =
            DeviceArray<rad_float4>::allocate(compute, perElement * count, what, DeviceAccess::write);
        DeviceKernel<Args> kernel =
            scene_.device().kernel<Args>({"direct_light.cl", model_ == SpecularModel::follow}, name);
        args.elements = records_;
        args.out = out;
        launchOverElements(kernel, args, count, raysPerElement);
        return out.read();
    }

private:
    const PreparedScene& scene_;
    const ElementMesh& elements_;
    SpecularModel model_;
    DeviceArray<DirectLightElement> records_;
    bool uploaded_ = false;
};

}  // namespace

std::vector<std::uint32_t> environmentRays(const Mesh& mesh, const ElementMesh& elements,
                                           const PatchClusters* clusters, double scale, bool pairs) {
    // At most 2^20 per element front, far past where any solve's shots would be as exact; with
    // a map an even count, at least 2, since its rays take the two strategies in turn and their
    // weights (kernels/direct_light.cl) hold only for as many of each.
    auto scaled = [scale, pairs](double rays) {
        const double n = std::clamp(std::ceil(rays * scale), pairs ? 2.0 : 1.0, 1048576.0);
        return static_cast<std::uint32_t>(pairs ? 2.0 * std::ceil(n / 2.0) : n);
    };
    std::vector<std::uint32_t> rays(elements.elements().size(), scaled(kEnvironmentRaysPerElement));
    if (!clusters || clusters->isIdentity()) return rays;
    std::vector<bool> small(mesh.patches.size(), false);
    for (std::size_t c = 0; c < clusters->count(); ++c)
        if (clusters->size(c) > 1)
            for (std::uint32_t m = clusters->start()[c]; m < clusters->start()[c + 1]; ++m)
                small[clusters->members()[m]] = true;
    const double perArea = kEnvironmentRaysPerElement / (0.25 * mesh.patchSize * mesh.patchSize);
    for (std::size_t e = 0; e < rays.size(); ++e) {
        const Element& element = elements.elements()[e];
        if (small[element.patch])
            rays[e] = scaled(std::clamp(std::ceil(perArea * element.area), static_cast<double>(kEnvironmentRaysAtLeast),
                                        static_cast<double>(kEnvironmentRaysPerElement)));
    }
    return rays;
}

namespace {

// The light from outside (the uniform sky or the environment map, the device scene's) by
// kernels/direct_light.cl's environment_direct, its result times `scale` (pi L for a uniform sky,
// whose kernel gives the fraction of it each element sees; 1 for a map).
void addEnvironmentLight(ElementLightKernels& kernels, const Mesh& mesh, const ElementMesh& elements,
                         const PatchClusters* clusters, double rayScale, bool mapped, std::uint32_t key,
                         const glm::dvec3& scale, const glm::dvec3& power, DirectLight& light) {
    if (elements.elements().empty()) return;
    const std::vector<std::uint32_t> rays = environmentRays(mesh, elements, clusters, rayScale, mapped);
    double total = 0.0;
    for (const std::uint32_t r : rays) total += r;
    const DeviceArray<rad_uint> raysOf =
        DeviceArray<rad_uint>::upload(kernels.compute(), rays, "light from outside: rays per element");
    EnvironmentDirectArgs args;
    args.raysOf = raysOf;
    args.key = key;
    const std::vector<rad_float4> out =
        kernels.run("environment_direct", args, 3, 1.0625 * total / static_cast<double>(rays.size()), "light from outside");
    addFrontsAndBacks(elements, out, 3, scale, power, light);
    // The variance of each front's mean, taken as the same relative variance in every channel,
    // from how far the means of the first half of its rays (h of n; with a map, h even, as many
    // of each strategy) and the rest differ by, d:
    // d^2 h (n - h) / n^2, which for independent rays has the mean's variance for its
    // expectation. The rays are stratified, each half a stratified set of its own; the halves
    // then differ by more than the whole errs, so this bounds it from above, and closely: an
    // open box's floor under the sky spread over seeds by 0.77 of it (tests/test_lights.cpp),
    // where the independent rays' (mean square - mean^2) / n was 11 times the spread. One ray:
    // its own value, 100 %. Where no ray brought light it counts as exact: most such elements
    // see no sky at all (the insides of an assembly), and one ray's light as their error would
    // make the engine model's expected noise 11.7 % where it measures 7.1 %; at very few rays
    // per element this understates the noise of dim ones.
    if (light.variance.empty()) light.variance.assign(rays.size(), 0.0);
    for (std::size_t e = 0; e < rays.size(); ++e) {
        const rad_float4& front = out[3 * e];
        const double mean = static_cast<double>(front.s[0]) + front.s[1] + front.s[2];
        const double n = rays[e], h = mapped ? 2.0 * std::floor(n / 4.0) : std::floor(n / 2.0), d = front.s[3];
        if (!(mean > 0.0)) continue;
        const double relative = h > 0.0 ? d * d * h * (n - h) / (n * n) / (mean * mean) : 1.0;
        const glm::dvec3 arrived = static_cast<double>(elements.elements()[e].area) * glm::dvec3(front.s[0], front.s[1], front.s[2]) * scale;
        const double sum = arrived.x + arrived.y + arrived.z;
        light.variance[e] += relative * sum * sum;
    }
}

// The punctual lights' (all the scene's, on the device) irradiance at n * n points of each
// element, each through a shadow ray, with `power` the lights' power; no sampling: the same
// points and shadow rays whatever the seed.
void addPunctualLight(const PreparedScene& scene, ElementLightKernels& kernels, const ElementMesh& elements,
                      const glm::dvec3& power, DirectLight& light) {
    if (elements.elements().empty()) return;
    PunctualDirectArgs args;
    args.n = kPunctualPointsPerSide;
    // Shadow rays per element: every light's up to RAD_EXACT_LIGHTS, else about a cut's.
    const double perPoint = std::min<double>(static_cast<double>(scene.emitters().punctualLights().lights.size()), 64.0);
    const std::vector<rad_float4> out =
        kernels.run("punctual_direct", args, 2, 2.0 * kPunctualPointsPerSide * kPunctualPointsPerSide * perPoint,
                    "punctual lights' direct light");
    // What neither side of any element received left the scene (this includes the midpoint
    // rule's quadrature error, small where elements are small against their distance to a light).
    addFrontsAndBacks(elements, out, 2, glm::dvec3(1.0), power, light);
}

// irradiance() at each element's centroid, nothing in the way.
void addUnoccludedLight(const PreparedScene& scene, const ElementMesh& elements, const Emitter& emitter,
                        DirectLight& light) {
    for (std::size_t e = 0; e < elements.elements().size(); ++e) {
        const Element& element = elements.elements()[e];
        const glm::dvec3 centre = (glm::dvec3(element.p[0]) + glm::dvec3(element.p[1]) + glm::dvec3(element.p[2])) / 3.0;
        const glm::dvec3 normal(scene.mesh().patches[element.patch].normal);
        light.arrived[e] += emitter.irradiance(centre, normal) * static_cast<double>(element.area);
    }
}

}  // namespace

DirectLight directLight(const PreparedScene& scene, const ElementMesh& elements, std::uint32_t seed,
                        SpecularModel model, const PatchClusters* clusters, double environmentRayScale) {
    DirectLight light;
    const std::vector<std::unique_ptr<Emitter>>& emitters = scene.emitters().list();
    glm::dvec3 punctualPower(0.0);
    for (const auto& e : emitters)
        if (e->delivery() == DirectDelivery::punctual) punctualPower += e->power();
    bool punctualDone = false;
    ElementLightKernels kernels(scene, elements, model);
    for (const auto& e : emitters) {
        const DirectDelivery delivery = e->delivery();
        if (delivery == DirectDelivery::none) continue;
        if (light.empty()) light.arrived.assign(elements.elements().size(), glm::dvec3(0.0));
        switch (delivery) {
            case DirectDelivery::punctual:
                // The device holds every emitter's punctual lights: delivered once, for all.
                if (!punctualDone) addPunctualLight(scene, kernels, elements, punctualPower, light);
                punctualDone = true;
                if (model == SpecularModel::follow)
                    addPunctualCaustics(scene, elements, *e, seed, kPunctualCausticRays, light);
                break;
            case DirectDelivery::environment: {
                const Scene& described = scene.scene();
                const bool uniform = !described.environment;
                addEnvironmentLight(kernels, scene.mesh(), elements, clusters, environmentRayScale, !uniform,
                                    rad_hash2(seed, uniform ? kSkyRaysStream : kEnvironmentRaysStream),
                                    uniform ? kPi * glm::dvec3(described.sky) : glm::dvec3(1.0), e->power(), light);
                break;
            }
            case DirectDelivery::unoccluded:
                addUnoccludedLight(scene, elements, *e, light);
                break;
            case DirectDelivery::none:
                break;
        }
    }
    return light;
}

}  // namespace rad
