#pragma once
// The streams that, with the user's seed, key every sample sequence (rad_hash2(seed, stream)):
// one list, so that two estimators never draw the same numbers. A new estimator takes a new
// value here.

#include <cstdint>

namespace rad {

enum SampleStream : std::uint32_t {
    kSurfaceRaysStream = 0x5f5e0001u,        // viewfactors: rays from whole surfaces
    kShooterRaysStream = 0x5f5e0002u,        // progressive refinement's shots
    kMatrixRowsStream = 0x5f5e0003u,         // patch-matrix rows: shoot, hemicube jitter, gather
    kRefinementShadowsStream = 0x5f5e0004u,  // adaptive refinement's shadow rays
    kSkyRaysStream = 0x5f5e0005u,            // the sky's direct light (light/environment_light.h)
    kEnvironmentRaysStream = 0x5f5e0006u,    // an environment map's direct light (light/environment_light.h)
    kViewIndirectStream = 0x5f5e0007u,       // the camera pass's indirect light per element (render/view_pass.h)
    kPunctualCausticsStream =
        0x5f5e0008u,  // punctual lights' rays through mirrors and glass (solver/punctual_caustics.h)
    kLightmapTexelsStream = 0x5f5e0009u,  // a lightmap's texels (lightmap/texel_bake.h)
};

}  // namespace rad
