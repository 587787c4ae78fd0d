#pragma once
// report.json: what was solved, on what, how long each stage took, why it stopped, where the
// energy went, and every surface's area-weighted mean radiosity.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "solver/energy_balance.h"
#include "solver/solver_state.h"

namespace rad {

struct SurfaceSummary {
    std::string name;
    double area = 0.0;          // m^2
    glm::dvec3 radiosity{0.0};  // area-weighted mean B, W/m^2
    std::uint32_t patches = 0;
    std::size_t elements = 0;
};

struct StageSeconds {
    double load = 0, mesh = 0, bvh = 0, solve = 0, render = 0, lightmapLayout = 0, lightmap = 0, write = 0;
    double sumOverRanks = 0;  // part of solve: under mpirun, the ranks summing each batch's counts
};

// solve --lightmap: the atlas and the bake (lightmap/).
struct LightmapSummary {
    bool baked = false;
    bool fromScene = false;  // the scene's TEXCOORD_1, or a made atlas
    std::string note;        // why a made atlas where the scene had a TEXCOORD_1
    std::string mode;        // the texels' indirect light: direct or final-gather
    std::uint32_t pages = 0, pageSize = 0, charts = 0, samples = 0;
    double texelSize = 0.0, areaUse = 0.0, largestStretch = 1.0, meanStretch = 1.0;
    std::uint64_t texels = 0, rays = 0;  // texels holding surface (baked or, none counted, filled); rays
    std::uint64_t backSides = 0;         // double-sided faces baked on their back
    std::uint64_t seamEdges = 0;
    double seamMismatchBefore = 0.0, seamMismatchAfter = 0.0;  // W / m^2, RMS of luminance
    double emissiveStrength = 0.0;  // lightmapped.glb's S: its emissive factor (<= 1) or emissive strength
};

struct SolveReport {
    std::string scene;
    std::string method = "shoot";                                  // the form-factor estimator
    std::string solver = "progressive";                            // how the system is solved
    std::vector<std::pair<std::string, double>> methodParameters;  // the estimator's and solver's own
    // Parameters as used.
    std::uint64_t rays = 0;
    std::uint32_t minRays = 0;
    double tolerance = 0.0;
    std::uint64_t maxShots = 0;
    double timeLimit = 0.0;
    std::uint32_t seed = 0;
    double patchSize = 0.0;
    std::string camera;
    int width = 0, height = 0, samplesPerPixel = 0;
    std::string renderMode = "radiosity";  // the camera pass (render/view_pass.h)
    std::uint64_t renderRays = 0;          // rays the camera pass traced (counted in direct and final-gather)
    double noiseTarget = 0.0;              // --noise (0: none)
    std::uint32_t samplesTaken = 0;        // direct and final-gather: samples per pixel taken (--noise may stop sooner)
    double imageNoise = 0.0;               // and the image's noise (render/pixel_estimate.h: imageNoise)
    // Device.
    std::string platform, device, deviceType, deviceVersion, driver;
    std::vector<std::string> rankDevices;  // under mpirun: each rank's "platform: device", in rank order
    // Mesh.
    std::size_t faces = 0, patches = 0, vertices = 0, elements = 0;
    bool adaptive = false;
    int refinementPasses = 0;
    std::size_t clusters = 0;  // progressive: clusters of patches that shot; reported where fewer than the patches
    std::size_t pooled = 0;    // progressive: elements whose shot light is more their cluster's than their own (with clusters)
    // Solve.
    SolveTallies tallies;
    double rayPowerScale = 1.0;    // above 1: the scene returned most of its light (amplification.h)
    double expectedNoise = -1.0;   // progressive: the elements' expected relative noise (ray_hit_checks.h); < 0: none
    std::uint64_t iterations = 0;  // matrix solvers: sweeps (progressive on a matrix: shots)
    double residual = -1.0;        // matrix solvers: max |E + rho F B - B| / max B; < 0: none
    std::string stopped;
    double unshotFraction = 0.0;
    EnergyBalance energy;
    StageSeconds seconds;
    std::vector<SurfaceSummary> surfaces;
    // The light from outside the scene, when the command line gave it: a uniform sky's radiance,
    // or an environment map (its file, strength and size).
    glm::vec3 sky{0.0f};
    std::string environment;
    double environmentStrength = 1.0;
    int environmentWidth = 0, environmentHeight = 0;
    LightmapSummary lightmap;
    std::vector<std::string> outputs;
    std::vector<std::string> warnings;
};

std::string reportJson(const SolveReport& report);
void writeSolveReport(const std::string& path, const SolveReport& report);

}  // namespace rad
