#pragma once
// Receivers finer than shooters (Cohen, Greenberg, Immel and Brock 1986): every patch is the
// root of a quadtree of elements. A triangle splits into four similar ones at its edges'
// midpoints, children in the order of their corners (a, ab, ca), (ab, b, bc), (ca, bc, c)
// and the centre (bc, ca, ab); kernels/element_lookup.h descends the same tree. Patches shoot;
// elements receive and are what is shaded and reported. A shot costs the same however finely
// its receivers are split. Adaptive refinement splits only the elements that need it.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/mesh.h"
#include "shared_types.h"

namespace rad {

// Where an element lies in its patch, in the patch's own coordinates (s, t) of the point
// p0 + s (p1 - p0) + t (p2 - p0): its corners are origin + scale * (0, 0), (1, 0), (0, 1).
// The scale is 2^-level, negative for elements turned half a turn (centre children).
struct ElementFrame {
    float s = 0.0f, t = 0.0f;
    float scale = 1.0f;
};

struct Element {
    std::array<glm::vec3, 3> p;  // corners, counter-clockwise seen from the patch's side
    float area = 0.0f;
    std::uint32_t patch = 0;     // the shooter it belongs to
    std::uint32_t level = 0;     // splits below its patch
    ElementFrame frame;
};

class ElementMesh {
public:
    // Every patch split until no element edge exceeds `elementSize` (<= 0: one element per patch).
    static ElementMesh uniform(const Mesh& mesh, double elementSize);

    const std::vector<Element>& elements() const { return elements_; }
    const std::vector<ElementNode>& nodes() const { return nodes_; }
    // Patch p's elements are [elementStart()[p], elementStart()[p + 1]).
    const std::vector<std::uint32_t>& elementStart() const { return start_; }
    std::size_t patchCount() const { return patches_; }

    // Splits the given elements in four, except those whose longest edge would fall below
    // `minEdge`, while the total stays within `maxElements`. Element indices change; returns
    // how many were split, and the new elements' indices in `children` if given.
    std::size_t split(const std::vector<std::uint32_t>& elements, double minEdge, std::size_t maxElements,
                      std::vector<std::uint32_t>* children = nullptr);

    // The element of patch `patch` at the point with weights `w` on the patch's corners, and
    // the point's weights on that element's corners: kernels/element_lookup.h's rule in the
    // same float arithmetic, so host and device agree even on ties.
    std::uint32_t locate(std::uint32_t patch, glm::vec3& w) const;

private:
    void addChildren(std::uint32_t node);  // splits a leaf in four
    void renumber();  // leaves in tree order, patch by patch

    std::uint32_t patches_ = 0;
    std::vector<ElementNode> nodes_;
    std::vector<std::array<glm::vec3, 3>> corners_;  // per node
    std::vector<ElementFrame> frames_;               // per node
    std::vector<std::uint32_t> nodePatch_, nodeLevel_;
    std::vector<Element> elements_;
    std::vector<std::uint32_t> start_;
    std::vector<std::uint32_t> leafNode_;  // per element, its node
};

// Per-surface element counts (for reports).
std::vector<std::size_t> elementsPerSurface(const Mesh& mesh, const ElementMesh& elements);

}  // namespace rad
