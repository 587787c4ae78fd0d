#include "light/light_tree.h"

#include <algorithm>
#include <numeric>

namespace rad {
namespace {

float luminance(const float* rgb) {
    return (0.2126f * rgb[0] + 0.7152f * rgb[1]) + 0.0722f * rgb[2];
}

// Builds the node for lights[order[begin .. end)] (indices relative to the first non-directional
// light) at nodes[at]; returns nothing, fills children after it.
void build(const std::vector<PunctualLight>& local, std::vector<int>& order, std::size_t begin, std::size_t end,
           std::vector<LightNode>& nodes, std::size_t at) {
    LightNode node{};
    for (int c = 0; c < 3; ++c) {
        node.lo[c] = local[static_cast<std::size_t>(order[begin])].position[c];
        node.hi[c] = node.lo[c];
    }
    int brightest = order[begin];
    for (std::size_t k = begin; k < end; ++k) {
        const PunctualLight& light = local[static_cast<std::size_t>(order[k])];
        for (int c = 0; c < 3; ++c) {
            node.lo[c] = std::min(node.lo[c], light.position[c]);
            node.hi[c] = std::max(node.hi[c], light.position[c]);
            node.intensity[c] += light.intensity[c];
        }
        if (light.intensity[3] > local[static_cast<std::size_t>(brightest)].intensity[3]) brightest = order[k];
    }
    node.lo[3] = luminance(node.intensity);
    node.rep = brightest;
    if (end - begin == 1) {
        node.left = -1 - order[begin];
        node.right = -1 - order[begin];
        nodes[at] = node;
        return;
    }
    int axis = 0;
    for (int c = 1; c < 3; ++c)
        if (node.hi[c] - node.lo[c] > node.hi[axis] - node.lo[axis]) axis = c;
    const std::size_t middle = begin + (end - begin) / 2;
    std::sort(order.begin() + static_cast<long>(begin), order.begin() + static_cast<long>(end), [&](int a, int b) {
        const float pa = local[static_cast<std::size_t>(a)].position[axis];
        const float pb = local[static_cast<std::size_t>(b)].position[axis];
        return pa < pb || (pa == pb && a < b);
    });
    node.left = static_cast<rad_int>(nodes.size());
    nodes.emplace_back();
    node.right = static_cast<rad_int>(nodes.size());
    nodes.emplace_back();
    nodes[at] = node;
    build(local, order, begin, middle, nodes, static_cast<std::size_t>(node.left));
    build(local, order, middle, end, nodes, static_cast<std::size_t>(node.right));
}

}  // namespace

PunctualLightSet buildLightSet(const std::vector<PunctualLight>& lights) {
    PunctualLightSet set;
    for (const PunctualLight& l : lights)
        if (l.type == RAD_LIGHT_DIRECTIONAL) set.lights.push_back(l);
    set.directional = static_cast<std::uint32_t>(set.lights.size());
    std::vector<PunctualLight> local;
    for (const PunctualLight& l : lights)
        if (l.type != RAD_LIGHT_DIRECTIONAL) local.push_back(l);
    set.lights.insert(set.lights.end(), local.begin(), local.end());
    if (local.empty()) return set;
    std::vector<int> order(local.size());
    std::iota(order.begin(), order.end(), 0);
    set.tree.reserve(2 * local.size());
    set.tree.emplace_back();
    build(local, order, 0, local.size(), set.tree, 0);
    return set;
}

}  // namespace rad
