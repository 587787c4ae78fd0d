#include "mesh/sampling_tables.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "util/shares.h"

namespace rad {
namespace {

void store(float (&out)[4], const glm::vec3& v, float w = 0.0f) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
    out[3] = w;
}

SampleTriangle sampleTriangle(const std::array<glm::vec3, 3>& p, const glm::vec3& normal) {
    SampleTriangle out;
    float largest = 0.0f;
    for (const glm::vec3& v : p) largest = std::max({largest, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    // Origins keep originLift from the triangle's plane, and as far from its edges (inset, in
    // barycentric terms: lift / smallest height).
    const float lift = originLift(largest);
    const glm::dvec3 e1 = glm::dvec3(p[1]) - glm::dvec3(p[0]);
    const glm::dvec3 e2 = glm::dvec3(p[2]) - glm::dvec3(p[0]);
    const double area = 0.5 * glm::length(glm::cross(e1, e2));
    const double longest = std::max({glm::length(e1), glm::length(e2), glm::length(e2 - e1)});
    const double inset = std::min(0.1, lift / std::max(2.0 * area / longest, 1e-300));
    store(out.v0, p[0], lift);
    store(out.e1, p[1] - p[0]);
    store(out.e2, p[2] - p[0]);
    store(out.normal, normal, static_cast<float>(area));
    store(out.tangent, glm::vec3(glm::normalize(e1)), static_cast<float>(inset));
    return out;
}

// Appends the area table of triangles[first ..] to cdf.
void appendAreaTable(const std::vector<SampleTriangle>& triangles, std::size_t first, std::vector<std::uint32_t>& cdf) {
    double total = 0.0;
    for (std::size_t k = first; k < triangles.size(); ++k) total += triangles[k].normal[3];
    double running = 0.0;
    std::uint32_t previous = 0;
    for (std::size_t k = first; k < triangles.size(); ++k) {
        running += triangles[k].normal[3];
        const double end = total > 0.0 ? std::floor(4294967296.0 * (running / total) + 0.5) : 4294967295.0;
        previous = std::max(previous, static_cast<std::uint32_t>(std::min(end, 4294967295.0)));
        cdf.push_back(previous);
    }
}

}  // namespace

SamplingTables buildSamplingTables(const Mesh& mesh) {
    SamplingTables tables;
    tables.triangles.reserve(mesh.patches.size() + 2 * mesh.faces.size());
    for (const Patch& patch : mesh.patches) tables.triangles.push_back(sampleTriangle(patch.p, patch.normal));
    tables.cdf.assign(mesh.patches.size(), 0);  // a patch is sampled alone: no table

    // Each face's side, grouped by the surface side its patches belong to.
    std::vector<std::vector<std::array<glm::vec3, 3>>> sides(mesh.surfaces.size());
    for (const Face& face : mesh.faces) {
        sides[mesh.patches[face.frontPatch].surface].push_back(face.p);
        if (face.backPatch != kNoPatch)
            sides[mesh.patches[face.backPatch].surface].push_back({face.p[0], face.p[2], face.p[1]});
    }
    for (const auto& side : sides) {
        TriangleRun run{static_cast<std::uint32_t>(tables.triangles.size()), static_cast<std::uint32_t>(side.size())};
        for (const auto& p : side) {
            const glm::dvec3 n = glm::cross(glm::dvec3(p[1]) - glm::dvec3(p[0]), glm::dvec3(p[2]) - glm::dvec3(p[0]));
            tables.triangles.push_back(sampleTriangle(p, glm::vec3(glm::normalize(n))));
        }
        appendAreaTable(tables.triangles, run.first, tables.cdf);
        tables.surfaceRuns.push_back(run);
    }
    // The guides after every triangle's entry, so that cdf[k] stays triangle k's.
    for (TriangleRun& r : tables.surfaceRuns) {
        if (r.count <= 1) continue;
        const std::vector<std::uint32_t> guide = shareGuide(tables.cdf.data() + r.first, r.count);
        if (tables.cdf.size() > 0xFFFFFFFFu - guide.size())
            throw std::length_error("the area tables' guides pass 2^32 entries");
        r.guide = static_cast<std::uint32_t>(tables.cdf.size());
        tables.cdf.insert(tables.cdf.end(), guide.begin(), guide.end());
    }
    return tables;
}

}  // namespace rad
