#pragma once
// The punctual lights as the device reads them (kernels/light_tree.h): directional lights first,
// then the point and spot lights with a binary tree over them, so that many lights cost a light
// cut per point rather than a shadow ray per light. The tree splits the lights' positions at the
// median of the box's longest axis (ties by index), down to single lights; each node holds its
// box, summed intensity and brightest light. Deterministic: the same lights, the same tree.

#include <cstdint>
#include <vector>

#include "shared_types.h"

namespace rad {

struct PunctualLightSet {
    std::vector<PunctualLight> lights;  // directional ones first
    std::uint32_t directional = 0;      // how many
    std::vector<LightNode> tree;        // over lights[directional ..]; root at 0; empty when none
};

PunctualLightSet buildLightSet(const std::vector<PunctualLight>& lights);

}  // namespace rad
