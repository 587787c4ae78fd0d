#pragma once
// What punctual lights send by way of mirrors and glass: light no shadow ray can find (a point
// light's image in a mirror, the focus of a lens). Rays drawn from the lights by power
// (Emitter::sample) go out from them on the device (light_caustics in kernels/shoot.cl); those
// that meet a mirror or glass first, other than straight through a thin pane (shadow rays cross
// panes), go on as the shots' rays do to the element they land on. Their power joins the
// elements' direct light, kept apart as light that came by way of mirrors and glass (the camera
// pass reads it from the solution). Results depend only on the seed: the rays are drawn on the
// host from it, and the device sums their power in integers.

#include <cstdint>

#include "light/emitter.h"
#include "mesh/elements.h"
#include "prepared/prepared_scene.h"
#include "solver/direct_light.h"

namespace rad {

// Rays drawn from the punctual lights when a scene has mirrors or glass.
inline constexpr std::uint64_t kPunctualCausticRays = std::uint64_t{1} << 20;

// Adds to `light` what `lights` (punctual lights, as PunctualLights samples them) send to the
// elements by way of mirrors and glass, from `rays` rays keyed by `seed`; the power that arrives
// leaves `light.escaped`, which counted it before. Nothing where the scene has no mirror or glass.
void addPunctualCaustics(const PreparedScene& scene, const ElementMesh& elements, const Emitter& lights,
                         std::uint32_t seed, std::uint64_t rays, DirectLight& light);

}  // namespace rad
