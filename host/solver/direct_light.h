#pragma once
// The direct-light service: the light of every emitter the solvers do not shoot (point, spot and
// directional lights, the sky, an environment map: light/emitter.h's DirectDelivery), delivered
// to the elements before the first shot, from what the emitters describe and the device scene
// holds. Punctual lights: the closed-form irradiance at n * n points of each element, each
// through a shadow ray (a light cut with many lights), and rays drawn from them for their light by
// way of mirrors and glass (solver/punctual_caustics.h); the light from outside: rays that leave
// the scene (kernels/direct_light.cl). Both strategies take the result in (the progressive solve
// as incident power before the first shot, the matrix strategy as reflected exitance), with the
// energy balance kept.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/elements.h"
#include "mesh/patch_clusters.h"

namespace rad {

class PreparedScene;

// How direct light meets mirrors and glass (scene/material_model.h). `follow`, as the
// progressive solve's shots do: shadow rays cross thin panes, the light goes on through them to
// the elements it reaches, and their own elements count only what they keep. `diffuse`, as the
// matrix solvers model them (a mirror a diffuse reflector, glass opaque): light stops at them,
// and their elements count all of it.
enum class SpecularModel { follow, diffuse };

// Light delivered straight to receivers, before any shot: the power that arrived at each
// element of the receivers (W per channel), the power absorbed by the black backs of
// single-sided faces, and the power that left the scene without arriving anywhere. Empty when
// no emitter delivers direct light.
struct DirectLight {
    std::vector<glm::dvec3> arrived;
    // Of `arrived`, what came by way of mirrors or glass (the sky's and the environment's light
    // through a window or off a mirror, kernels/direct_light.cl; the punctual lights' off a
    // mirror or through glass, solver/punctual_caustics.h); empty when none did.
    std::vector<glm::dvec3> arrivedBySpecular;
    // Per element, the variance of `arrived`'s sum over channels (W^2) where its light was sampled
    // by rays (the light from outside); empty when none was.
    std::vector<double> variance;
    glm::dvec3 absorbedByBacks{0.0};
    glm::dvec3 escaped{0.0};
    bool empty() const { return arrived.empty(); }
    glm::dvec3 total() const;  // arrived, summed, plus absorbed by backs and escaped
};

// Points per element side where punctual lights' irradiance is found: the midpoint rule on
// n * n sub-triangles.
inline constexpr std::uint32_t kPunctualPointsPerSide = 4;
// Rays per element front that look for the light from outside (a black back, whose light is only
// summed over the scene, takes a sixteenth); on the elements of small patches
// that shoot in clusters (mesh/patch_clusters.h), as many per square metre as on an element of
// a quarter of the patch size squared (a patch of a large face), and at least
// kEnvironmentRaysAtLeast: tessellated content costs what its area does, not its triangle count.
// Both at the progressive solve's default --rays, and in proportion to --rays (at least 1), so
// that more rays make the light from outside as much more exact as the shots' light.
inline constexpr std::uint32_t kEnvironmentRaysPerElement = 256;
inline constexpr std::uint32_t kEnvironmentRaysAtLeast = 16;

// The rays per element front that look for the light from outside (above), in element order;
// `scale`: the solve's rays over its default; `pairs`: an even count, at least 2 (a map's rays,
// one of each strategy in turn).
std::vector<std::uint32_t> environmentRays(const Mesh& mesh, const ElementMesh& elements,
                                           const PatchClusters* clusters, double scale = 1.0, bool pairs = false);

// The direct light of every emitter that delivers it, on `elements`, with mirrors and glass as
// `model` says; any sampling keyed by `seed` (the solve's). Empty when no emitter delivers any.
// `clusters`: the small patches the sky's and environment's rays are spread by area on (none:
// every element gets kEnvironmentRaysPerElement); `environmentRayScale`: the rays for it over
// their default (environmentRays).
DirectLight directLight(const PreparedScene& scene, const ElementMesh& elements, std::uint32_t seed,
                        SpecularModel model = SpecularModel::follow, const PatchClusters* clusters = nullptr,
                        double environmentRayScale = 1.0);

}  // namespace rad
