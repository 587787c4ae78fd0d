#pragma once
// Which elements to split ("model no more than the scene needs"). An element is too coarse
// where linear shading over it cannot follow the light, seen two ways:
//   direct light: the irradiance from the strongest emitters, closed-form factors times
//               shadow-ray visibility at seven points of the element (kernels/refine.cl),
//               departs from linear across it by more than the threshold: shadow edges,
//               penumbrae, steep fall-off near a light. Deterministic, and needs no solve;
//   solution:   its solved radiosity differs, in luminance, from the mean of the values at its
//               corners (what linear shading over it averages to; mesh/vertices.h) by more than
//               the threshold, and by more than the noise its share of the rays leaves: light,
//               direct or indirect, that bends across it.
// Both are relative to the light's level there, or to a tenth of the scene's mean where it is
// darker. Elements that stay flat are never marked.

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/elements.h"
#include "parallel/process_group.h"
#include "prepared/prepared_scene.h"
#include "solver/progressive_solver.h"

namespace rad {

struct RefinementOptions {
    double threshold = 0.05;             // departure from linear, over the local (or dark-floor) level
    std::uint32_t visibilityShooters = 32;  // emitting patches whose shadows are looked for
    std::uint32_t visibilityRays = 4;    // shadow rays per element point and shooter
    std::uint32_t seed = 1;
};

// Direct light over one element (W/m^2 in luminance).
struct DirectVariation {
    double departure = 0.0;  // largest departure from linear, over `level`
    double level = 0.0;      // the largest irradiance found on the element
    double mean = 0.0;       // the mean of the seven points
    double fromLights = 0.0;  // the punctual lights' part of `mean` (noise-free in the solve)
};

// For the elements `which` (their indices), in that order.
// The irradiance comes from the emitters' direct sources (light/emitter.h).
std::vector<DirectVariation> directVariation(const PreparedScene& scene, const ElementMesh& elements,
                                             const std::vector<std::uint32_t>& which, const RefinementOptions& options);

// Per element, how far (in luminance) its solved radiosity departs from linear shading over it
// where that exceeds the threshold and the noise; 0 elsewhere. `hits`: about how many rays each
// element received.
std::vector<double> solutionDepartures(const Mesh& mesh, const ElementMesh& elements,
                                       const std::vector<glm::vec3>& radiosity, const std::vector<double>& hits,
                                       double threshold);

struct AdaptiveOptions {
    RefinementOptions marks;
    double minEdge = 0.0;                  // never split below this edge (metres)
    std::size_t maxElements = 4'000'000;   // stop splitting at this many elements
    int passes = 4;                        // at most this many passes by direct light
    bool solutionPass = true;              // then one by a provisional solve
    // Rays of the solve that will use the elements. An element is split only where the detail
    // it would resolve stands this many times above the noise its children would carry (a
    // child with n rays has a relative noise of about 1 / sqrt(n)): finer elements than the
    // rays can fill show noise, not light.
    std::uint64_t finalRays = 16'000'000;
    double detailOverNoise = 2.0;
    const ProcessGroup* group = nullptr;  // the processes sharing the provisional solve's shots
};

struct RefinementPass {
    bool bySolution = false;               // false: by direct light
    std::size_t before = 0, after = 0;     // elements
    std::size_t examined = 0, marked = 0;
    std::size_t tooFewRays = 0;            // marked, but their children would be too noisy
    double seconds = 0.0;
};

// First passes by direct light (the first examines every element, later ones the new
// children), until nothing more is split or the passes run out; then one pass by a
// provisional solve (`provisional`'s rays and tolerance) for what direct light does not show.
// Stops early when the elements run out or `interrupted` says so. Returns the passes that ran.
std::vector<RefinementPass> refineAdaptively(const PreparedScene& scene, ElementMesh& elements,
                                             const ProgressiveOptions& provisional, const AdaptiveOptions& options,
                                             const std::function<bool()>& interrupted = {},
                                             const std::function<void(const RefinementPass&)>& onPass = {});

}  // namespace rad
