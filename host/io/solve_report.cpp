#include "io/solve_report.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "io/atomic_file.h"

namespace rad {
namespace {

// Keys in the order written, so the report reads top-down.
using Json = nlohmann::ordered_json;

Json rgb(const glm::dvec3& v) { return Json::array({v.x, v.y, v.z}); }

}  // namespace

std::string reportJson(const SolveReport& r) {
    Json j;
    j["scene"] = r.scene;
    j["method"] = r.method;
    j["solver"] = r.solver;
    Json methodParameters = Json::object();
    for (const auto& [name, value] : r.methodParameters) methodParameters[name] = value;
    j["method_parameters"] = methodParameters;
    j["parameters"] = {{"rays", r.rays},
                       {"min_rays", r.minRays},
                       {"tolerance", r.tolerance},
                       {"max_shots", r.maxShots},
                       {"time_limit", r.timeLimit},
                       {"seed", r.seed},
                       {"patch_size", r.patchSize},
                       {"camera", r.camera},
                       {"width", r.width},
                       {"height", r.height},
                       {"samples_per_pixel", r.samplesPerPixel},
                       {"render", r.renderMode}};
    if (r.noiseTarget > 0.0) j["parameters"]["noise"] = r.noiseTarget;  // only where given: older reports' bytes kept
    j["device"] = {{"platform", r.platform}, {"name", r.device}, {"type", r.deviceType},
                   {"version", r.deviceVersion}, {"driver", r.driver}};
    // The processes that shared the solve: one, or the ranks of mpirun with their devices.
    j["processes"] = {{"count", std::max<std::size_t>(1, r.rankDevices.size())}, {"devices", r.rankDevices}};
    j["mesh"] = {{"surfaces", r.surfaces.size()}, {"faces", r.faces},           {"patches", r.patches},
                 {"elements", r.elements},         {"vertices", r.vertices},     {"adaptive", r.adaptive},
                 {"refinement_passes", r.refinementPasses}};
    // Only where small patches shot in clusters (mesh/patch_clusters.h), so other reports keep their form.
    if (r.clusters > 0 && r.clusters < r.patches) {
        j["mesh"]["clusters"] = r.clusters;
        j["mesh"]["pooled_elements"] = r.pooled;
    }
    const double total = r.seconds.load + r.seconds.mesh + r.seconds.bvh + r.seconds.solve + r.seconds.render +
                         r.seconds.lightmapLayout + r.seconds.lightmap + r.seconds.write;
    j["solve"] = {{"shots", r.tallies.shots},
                  {"batches", r.tallies.batches},
                  {"rays", r.tallies.rays},
                  {"stopped", r.stopped},
                  {"unshot_fraction", r.unshotFraction},
                  {"rays_per_second", r.seconds.solve > 0 ? r.tallies.rays / r.seconds.solve : 0.0}};
    // Only where rays carried more power than emitted / --rays (a scene returning most of its
    // light: solver/amplification.h), so other reports keep their form.
    if (r.rayPowerScale > 1.0) j["solve"]["ray_power_scale"] = r.rayPowerScale;
    if (r.expectedNoise >= 0.0) j["solve"]["expected_noise"] = r.expectedNoise;
    if (r.residual >= 0.0) {
        j["solve"]["iterations"] = r.iterations;
        j["solve"]["residual"] = r.residual;
    }
    j["seconds"] = {{"load", r.seconds.load},     {"mesh", r.seconds.mesh},   {"bvh", r.seconds.bvh},
                    {"solve", r.seconds.solve},   {"render", r.seconds.render}, {"write", r.seconds.write},
                    {"total", total}};
    if (r.renderRays > 0)
        j["render"] = {{"mode", r.renderMode},
                       {"rays", r.renderRays},
                       {"samples_per_pixel", r.samplesTaken},
                       {"noise", r.imageNoise}};
    if (r.lightmap.baked) {
        const LightmapSummary& l = r.lightmap;
        j["seconds"]["lightmap_layout"] = r.seconds.lightmapLayout;
        j["seconds"]["lightmap"] = r.seconds.lightmap;
        j["lightmap"] = {{"uv", l.fromScene ? "TEXCOORD_1 of the scene" : "atlas"},
                         {"pages", l.pages},
                         {"page_size", l.pageSize},
                         {"charts", l.charts},
                         {"texel_size", l.texelSize},
                         {"area_use", l.areaUse},
                         {"largest_stretch", l.largestStretch},
                         {"mean_stretch", l.meanStretch},
                         {"mode", l.mode},
                         {"samples_per_texel", l.samples},
                         {"texels", l.texels},
                         {"faces_baked_on_their_back", l.backSides},
                         {"rays", l.rays},
                         {"seam_edges", l.seamEdges},
                         {"seam_mismatch_before", l.seamMismatchBefore},
                         {"seam_mismatch_after", l.seamMismatchAfter},
                         {"emissive_strength", l.emissiveStrength}};
        if (!l.note.empty()) j["lightmap"]["note"] = l.note;
    }
    if (r.rankDevices.size() > 1) j["seconds"]["sum_over_ranks"] = r.seconds.sumOverRanks;
    j["energy"] = {{"units", "W per channel (r, g, b)"},
                   {"emitted", rgb(r.energy.emitted)},
                   {"absorbed", rgb(r.energy.absorbed)},
                   {"absorbed_by_black_backs", rgb(r.energy.absorbedByBacks)},
                   {"escaped", rgb(r.energy.escaped)},
                   {"unshot", rgb(r.energy.unshot)},
                   {"relative_residual", r.energy.relativeResidual()}};
    // Only when given, so the reports of scenes lit from within keep their form.
    if (r.sky != glm::vec3(0.0f)) j["outside"] = {{"sky", rgb(glm::dvec3(r.sky))}};
    if (!r.environment.empty())
        j["outside"] = {{"environment",
                         {{"file", r.environment},
                          {"strength", r.environmentStrength},
                          {"width", r.environmentWidth},
                          {"height", r.environmentHeight}}}};
    Json surfaces = Json::array();
    for (const SurfaceSummary& s : r.surfaces)
        surfaces.push_back({{"name", s.name},
                            {"area", s.area},
                            {"patches", s.patches},
                            {"elements", s.elements},
                            {"radiosity", rgb(s.radiosity)}});
    j["surfaces"] = surfaces;
    j["outputs"] = r.outputs;
    j["warnings"] = r.warnings;
    return j.dump(2) + "\n";
}

void writeSolveReport(const std::string& path, const SolveReport& report) {
    const std::string text = reportJson(report);
    writeFileAtomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace rad
