#include "solver/refinement.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "device/kernel_arguments.h"
#include "mesh/sampling_tables.h"
#include "mesh/vertices.h"
#include "shared_math.h"
#include "util/sample_streams.h"
#include "util/stopwatch.h"

namespace rad {
namespace {
// Departures in the dark are judged against a tenth of the scene's mean, not against their own
// faint light: a shadow's deep interior is not worth elements that the lit floor needs.
constexpr double kDarkFloor = 0.1;

double luminance(const glm::vec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

// Luminance power the scene's direct sources emit (W), as directVariation's irradiance counts it.
double emittedLuminance(const std::vector<DirectSource>& sources) {
    double power = 0.0;
    for (const DirectSource& s : sources) power += kPi * luminance(s.radiance) * s.area;
    return power;
}

// The direct sources, strongest first, thinned evenly to at most `count`.
std::vector<DirectSource> strongestSources(const std::vector<DirectSource>& sources, std::uint32_t count) {
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t k = 0; k < sources.size(); ++k) {
        const double power = luminance(sources[k].radiance) * sources[k].area;
        if (power > 0.0) order.emplace_back(-power, k);
    }
    // Ties go to the earlier source, as they did to the lower patch index.
    std::sort(order.begin(), order.end());
    std::vector<DirectSource> chosen;
    const double step = order.size() > count ? static_cast<double>(order.size()) / count : 1.0;
    for (double k = 0.0; k < order.size() && chosen.size() < count; k += step)
        chosen.push_back(sources[order[static_cast<std::size_t>(k)].second]);
    return chosen;
}

}  // namespace

std::vector<double> solutionDepartures(const Mesh& mesh, const ElementMesh& elements,
                                       const std::vector<glm::vec3>& radiosity, const std::vector<double>& hits,
                                       double threshold) {
    const MeshVertices vertices = weldVertices(mesh, elements);
    const std::vector<glm::vec3> atVertices = vertexValues(elements, vertices, radiosity);
    double mean = 0.0, area = 0.0;
    for (std::size_t e = 0; e < radiosity.size(); ++e) {
        mean += luminance(radiosity[e]) * elements.elements()[e].area;
        area += elements.elements()[e].area;
    }
    const double floor = area > 0.0 ? kDarkFloor * mean / area : 0.0;
    std::vector<double> departures(radiosity.size(), 0.0);
    for (std::size_t e = 0; e < radiosity.size(); ++e) {
        // Linear shading over the element has the mean of its corners' values; its own mean
        // differs from that where the light bends across it.
        const double y = luminance(radiosity[e]);
        double shaded = 0.0, scale = std::max(y, floor);
        for (std::uint32_t v : vertices.corners[e]) {
            const double yv = luminance(atVertices[v]);
            shaded += yv / 3.0;
            scale = std::max(scale, yv);
        }
        // The element's mean and the fits at its corners are both noisy, about equally: four
        // standard deviations of their difference keep false marks rare among many elements.
        const double noise = 4.0 * std::sqrt(2.0) * y / std::sqrt(std::max(hits[e], 1.0));
        const double departure = std::fabs(shaded - y);
        if (departure > std::max(threshold * scale, noise)) departures[e] = departure;
    }
    return departures;
}

std::vector<DirectVariation> directVariation(const PreparedScene& scene, const ElementMesh& elements,
                                             const std::vector<std::uint32_t>& which, const RefinementOptions& options) {
    ComputeContext& compute = scene.compute();
    const Mesh& mesh = scene.mesh();
    const auto& list = elements.elements();
    std::vector<DirectVariation> result(which.size());
    const std::vector<DirectSource> sources = scene.emitters().directSources();
    const std::vector<DirectSource> chosen = strongestSources(sources, options.visibilityShooters);
    // The punctual lights are the device scene's (Emitters::punctualLights).
    const bool lights = scene.emitters().punctualLights().lights.size() > 0;
    if ((chosen.empty() && !lights) || which.empty()) return result;

    std::vector<rad_uint> shooters;
    std::vector<float> exitance;
    double chosenPower = 0.0;
    for (const DirectSource& s : chosen) {
        const double e = kPi * luminance(s.radiance);
        shooters.push_back(s.triangle);
        exitance.push_back(static_cast<float>(e));
        chosenPower += e * s.area;
    }
    // The emitters left out light the scene too, much as those chosen do. With punctual lights
    // the kernel scales the patches' part before adding the lights'; without, the host scales.
    const double scale = chosenPower > 0.0 ? emittedLuminance(sources) / chosenPower : 1.0;
    const double hostScale = lights ? 1.0 : scale;
    const auto shooterCount = static_cast<rad_uint>(shooters.size());
    if (shooters.empty()) {  // a placeholder the kernel does not read
        shooters.push_back(0);
        exitance.push_back(0.0f);
    }
    // Per element its corners, lifted as ray origins are (the patch's lift, kernels/ray_source.h),
    // then its normal.
    std::vector<LiftedElement> points;
    points.reserve(which.size());
    for (std::uint32_t e : which) {
        const Patch& patch = mesh.patches[list[e].patch];
        float largest = 0.0f;
        for (const glm::vec3& v : patch.p) largest = std::max({largest, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
        const glm::vec3 lift = patch.normal * originLift(largest);
        LiftedElement record{};
        for (std::size_t k = 0; k < 3; ++k) {
            const glm::vec3 q = list[e].p[k] + lift;
            for (int c = 0; c < 3; ++c) record.corners[k][c] = q[c];
        }
        for (int c = 0; c < 3; ++c) record.normal[c] = patch.normal[c];
        points.push_back(record);
    }
    const std::string what = "refinement's direct light";
    const auto pointArray = DeviceArray<LiftedElement>::upload(compute, points, what + ": elements");
    const auto shooterArray = DeviceArray<rad_uint>::upload(compute, shooters, what + ": emitters");
    const auto exitanceArray = DeviceArray<float>::upload(compute, exitance, what + ": emitters' exitance");
    const auto outArray = DeviceArray<rad_float4>::allocate(compute, which.size(), what, DeviceAccess::write);
    DeviceKernel<DirectVariationArgs> kernel =
        scene.device().kernel<DirectVariationArgs>("refine.cl", "direct_variation");
    DirectVariationArgs args;
    args.elements = pointArray;
    args.elementCount = static_cast<rad_uint>(which.size());
    args.shooters = shooterArray;
    args.exitance = exitanceArray;
    args.shooterCount = shooterCount;
    args.rays = options.visibilityRays;
    args.seed = rad_hash2(options.seed, kRefinementShadowsStream);
    args.sourceScale = static_cast<float>(scale);
    args.out = outArray;
    // About 900 shadow rays per element: launches of 2^16 elements return within seconds
    // even on a CPU, and never trip a GPU's watchdog.
    constexpr std::size_t kPerLaunch = std::size_t{1} << 16;
    for (std::size_t first = 0; first < which.size(); first += kPerLaunch) {
        args.first = static_cast<rad_uint>(first);
        kernel.launch(args, std::min(kPerLaunch, which.size() - first));
    }
    const std::vector<rad_float4> out = outArray.read();
    for (std::size_t k = 0; k < out.size(); ++k)
        result[k] = {out[k].s[0], hostScale * out[k].s[1], hostScale * out[k].s[2], out[k].s[3]};
    return result;
}

namespace {

// Whether splitting shows a detail of `departure` (absolute) on light of level `level` rather
// than noise: each child's relative noise is about 1 / sqrt(its rays).
bool resolvable(double departure, double level, double childRays, const AdaptiveOptions& options) {
    return departure * std::sqrt(std::max(childRays, 0.0)) >= options.detailOverNoise * level;
}

// The passes by direct light. Elements darker than a tenth of the scene's mean (over the first
// pass's elements) are judged against that.
void refineByDirectLight(const PreparedScene& scene, ElementMesh& elements, const AdaptiveOptions& options,
                         const std::function<bool()>& interrupted, const std::function<void(const RefinementPass&)>& onPass,
                         std::vector<RefinementPass>& passes) {
    const double emitted = emittedLuminance(scene.emitters().directSources());
    std::vector<std::uint32_t> which(elements.elements().size());
    for (std::uint32_t e = 0; e < which.size(); ++e) which[e] = e;
    double floor = -1.0;
    for (int pass = 0; pass < options.passes && !which.empty() && !(interrupted && interrupted()); ++pass) {
        Stopwatch clock;
        const std::vector<DirectVariation> found = directVariation(scene, elements, which, options.marks);
        if (floor < 0.0) {
            double sum = 0.0, area = 0.0;
            for (std::size_t k = 0; k < found.size(); ++k) {
                sum += found[k].level * elements.elements()[which[k]].area;
                area += elements.elements()[which[k]].area;
            }
            floor = area > 0.0 ? kDarkFloor * sum / area : 0.0;
        }
        RefinementPass record;
        record.before = elements.elements().size();
        record.examined = which.size();
        std::vector<std::uint32_t> split;
        for (std::size_t k = 0; k < found.size(); ++k) {
            const DirectVariation& v = found[k];
            if (!(v.departure * v.level > options.marks.threshold * std::max(v.level, floor))) continue;
            ++record.marked;
            // What a child can expect of the final solve's rays: its share of the emitted power.
            // Punctual lights' direct light comes without noise (kernels/direct_light.cl), so
            // where it is most of the light there is no noise to wait for.
            const double fromPatches = v.mean - v.fromLights;
            const double childRays = emitted > 0.0 ? fromPatches * elements.elements()[which[k]].area / 4.0 / emitted *
                                                         static_cast<double>(options.finalRays)
                                                   : 0.0;
            if (v.fromLights >= 0.5 * v.mean || resolvable(v.departure * v.level, v.mean, childRays, options))
                split.push_back(which[k]);
            else ++record.tooFewRays;
        }
        if (elements.split(split, options.minEdge, options.maxElements, &which) == 0) break;
        record.after = elements.elements().size();
        record.seconds = clock.seconds();
        passes.push_back(record);
        if (onPass) onPass(record);
    }
}

void refineBySolution(const PreparedScene& scene, ElementMesh& elements, const ProgressiveOptions& provisional,
                      const AdaptiveOptions& options, const std::function<void(const RefinementPass&)>& onPass,
                      std::vector<RefinementPass>& passes) {
    Stopwatch clock;
    SolveHooks hooks;
    hooks.group = options.group;
    const ProgressiveResult result = ProgressiveSolver(scene, elements).solve(provisional, hooks, nullptr);
    // Every ray carries about the emitted power over the rays of a full shot (times the scale a
    // scene that returns most of its light gives them, solver/amplification.h): that many rays'
    // worth of power arrived at each element.
    const glm::dvec3 emitted = result.energy.emitted;
    const double perRay =
        (emitted.x + emitted.y + emitted.z) / static_cast<double>(provisional.rays) * result.rayPowerScale;
    std::vector<double> hits(result.incident.size());
    for (std::size_t e = 0; e < hits.size(); ++e)
        hits[e] = (result.incident[e].x + result.incident[e].y + result.incident[e].z) / perRay;
    const std::vector<double> departures =
        solutionDepartures(scene.mesh(), elements, result.radiosity, hits, options.marks.threshold);
    const double finalPerProvisional = static_cast<double>(options.finalRays) / static_cast<double>(provisional.rays);
    RefinementPass record;
    record.bySolution = true;
    record.before = elements.elements().size();
    record.examined = record.before;
    std::vector<std::uint32_t> split;
    for (std::uint32_t e = 0; e < departures.size(); ++e) {
        if (!(departures[e] > 0.0)) continue;
        ++record.marked;
        if (resolvable(departures[e], luminance(result.radiosity[e]), hits[e] * finalPerProvisional / 4.0, options))
            split.push_back(e);
        else
            ++record.tooFewRays;
    }
    elements.split(split, options.minEdge, options.maxElements);
    record.after = elements.elements().size();
    record.seconds = clock.seconds();
    passes.push_back(record);
    if (onPass) onPass(record);
}

}  // namespace

std::vector<RefinementPass> refineAdaptively(const PreparedScene& scene, ElementMesh& elements,
                                             const ProgressiveOptions& provisional, const AdaptiveOptions& options,
                                             const std::function<bool()>& interrupted,
                                             const std::function<void(const RefinementPass&)>& onPass) {
    std::vector<RefinementPass> passes;
    refineByDirectLight(scene, elements, options, interrupted, onPass, passes);
    if (options.solutionPass && !(interrupted && interrupted()))
        refineBySolution(scene, elements, provisional, options, onPass, passes);
    return passes;
}

}  // namespace rad
