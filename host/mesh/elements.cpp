#include "mesh/elements.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace rad {
namespace {

glm::vec3 midpoint(const glm::vec3& a, const glm::vec3& b) {  // in double: the same bits from either end
    return glm::vec3(0.5 * (glm::dvec3(a) + glm::dvec3(b)));
}

std::array<std::array<glm::vec3, 3>, 4> children(const std::array<glm::vec3, 3>& t) {
    const glm::vec3 ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
    return {{{t[0], ab, ca}, {ab, t[1], bc}, {ca, bc, t[2]}, {bc, ca, ab}}};
}

// The same four in the patch's coordinates (exact: halvings of powers of two).
std::array<ElementFrame, 4> childFrames(const ElementFrame& f) {
    const float h = 0.5f * f.scale;
    return {{{f.s, f.t, h}, {f.s + h, f.t, h}, {f.s, f.t + h, h}, {f.s + h, f.t + h, -h}}};
}

double longestEdge(const std::array<glm::vec3, 3>& t) {
    const glm::dvec3 a(t[0]), b(t[1]), c(t[2]);
    return std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
}

float area(const std::array<glm::vec3, 3>& t) {
    const glm::dvec3 a(t[0]);
    return static_cast<float>(0.5 * glm::length(glm::cross(glm::dvec3(t[1]) - a, glm::dvec3(t[2]) - a)));
}

}  // namespace

ElementMesh ElementMesh::uniform(const Mesh& mesh, double elementSize) {
    ElementMesh m;
    const std::size_t patches = mesh.patches.size();
    m.patches_ = static_cast<std::uint32_t>(patches);
    for (std::size_t p = 0; p < patches; ++p) {
        m.nodes_.push_back({-1, 0});
        m.corners_.push_back(mesh.patches[p].p);
        m.frames_.push_back({});
        m.nodePatch_.push_back(static_cast<std::uint32_t>(p));
        m.nodeLevel_.push_back(0);
    }
    // Split breadth-first until every element is small enough.
    std::vector<std::uint32_t> open(patches);
    for (std::uint32_t p = 0; p < patches; ++p) open[p] = p;
    while (elementSize > 0.0 && !open.empty()) {
        std::vector<std::uint32_t> next;
        for (std::uint32_t node : open) {
            if (longestEdge(m.corners_[node]) <= elementSize || m.nodeLevel_[node] >= 12) continue;
            for (int k = 0; k < 4; ++k) next.push_back(static_cast<std::uint32_t>(m.nodes_.size()) + k);
            m.addChildren(node);
        }
        open = std::move(next);
    }
    m.renumber();
    return m;
}

void ElementMesh::addChildren(std::uint32_t node) {
    nodes_[node].firstChild = static_cast<std::int32_t>(nodes_.size());
    const auto corners = children(corners_[node]);
    const auto frames = childFrames(frames_[node]);
    for (int k = 0; k < 4; ++k) {
        nodes_.push_back({-1, 0});
        corners_.push_back(corners[k]);
        frames_.push_back(frames[k]);
        nodePatch_.push_back(nodePatch_[node]);
        nodeLevel_.push_back(nodeLevel_[node] + 1);
    }
}

void ElementMesh::renumber() {
    elements_.clear();
    leafNode_.clear();
    start_.assign(1, 0);
    std::vector<std::uint32_t> stack;
    for (std::uint32_t root = 0; root < patches_; ++root) {
        stack.assign(1, root);
        while (!stack.empty()) {
            const std::uint32_t node = stack.back();
            stack.pop_back();
            if (nodes_[node].firstChild >= 0) {
                for (int c = 3; c >= 0; --c) stack.push_back(static_cast<std::uint32_t>(nodes_[node].firstChild + c));
                continue;
            }
            nodes_[node].element = static_cast<rad_uint>(elements_.size());
            elements_.push_back({corners_[node], area(corners_[node]), nodePatch_[node], nodeLevel_[node], frames_[node]});
            leafNode_.push_back(node);
        }
        start_.push_back(static_cast<std::uint32_t>(elements_.size()));
    }
}

std::size_t ElementMesh::split(const std::vector<std::uint32_t>& elements, double minEdge, std::size_t maxElements,
                               std::vector<std::uint32_t>* children) {
    const std::size_t nodesBefore = nodes_.size();
    std::size_t count = 0;
    for (std::uint32_t e : elements) {
        if (elements_.size() + 3 * (count + 1) > maxElements) break;
        const std::uint32_t node = leafNode_[e];
        if (nodes_[node].firstChild >= 0 || longestEdge(corners_[node]) * 0.5 < minEdge) continue;
        addChildren(node);
        ++count;
    }
    if (count > 0) renumber();
    if (children) {
        children->clear();
        for (std::uint32_t e = 0; e < elements_.size(); ++e)
            if (leafNode_[e] >= nodesBefore) children->push_back(e);
    }
    return count;
}

std::uint32_t ElementMesh::locate(std::uint32_t patch, glm::vec3& w) const {
    std::uint32_t node = patch;
    while (nodes_[node].firstChild >= 0) {
        int child;
        if (w.x >= 0.5f) child = 0, w = glm::vec3(2.0f * w.x - 1.0f, 2.0f * w.y, 2.0f * w.z);
        else if (w.y >= 0.5f) child = 1, w = glm::vec3(2.0f * w.x, 2.0f * w.y - 1.0f, 2.0f * w.z);
        else if (w.z >= 0.5f) child = 2, w = glm::vec3(2.0f * w.x, 2.0f * w.y, 2.0f * w.z - 1.0f);
        else child = 3, w = glm::vec3(1.0f - 2.0f * w.x, 1.0f - 2.0f * w.y, 1.0f - 2.0f * w.z);
        node = static_cast<std::uint32_t>(nodes_[node].firstChild + child);
    }
    return nodes_[node].element;
}

std::vector<std::size_t> elementsPerSurface(const Mesh& mesh, const ElementMesh& elements) {
    std::vector<std::size_t> count(mesh.surfaces.size(), 0);
    for (const Element& e : elements.elements()) ++count[mesh.patches[e.patch].surface];
    return count;
}

}  // namespace rad
