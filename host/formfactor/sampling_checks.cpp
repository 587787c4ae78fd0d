#include "formfactor/sampling_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "shared_math.h"
#include "util/format.h"

namespace rad {
namespace {

double sceneDiagonal(const Mesh& mesh) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const Face& f : mesh.faces)
        for (const glm::vec3& p : f.p) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    return mesh.faces.empty() ? 0.0 : glm::length(glm::dvec3(hi) - glm::dvec3(lo));
}

glm::vec3 centroid(const Patch& p) {
    return (p.p[0] + p.p[1] + p.p[2]) / 3.0f;
}

float longestEdge(const Patch& p) {
    return std::max({glm::length(p.p[1] - p.p[0]), glm::length(p.p[2] - p.p[1]), glm::length(p.p[0] - p.p[2])});
}

}  // namespace

std::vector<std::string> smallReceivers(const Mesh& mesh, const std::string& method, std::uint32_t hemicubeResolution,
                                        std::uint64_t raysPerSource, bool surfaceSources) {
    const double diagonal = sceneDiagonal(mesh);
    if (!(diagonal > 0.0)) return {};
    std::vector<double> areas;
    if (surfaceSources)
        for (const MeshSurface& s : mesh.surfaces) areas.push_back(s.area);
    else
        for (const Patch& p : mesh.patches) areas.push_back(p.area);
    if (areas.empty()) return {};
    // Receivers of at least this area get one sample or more from across the scene.
    const bool hemicube = method == "hemicube";
    const double R = hemicubeResolution;
    const double resolvable =
        hemicube ? 4.0 * diagonal * diagonal / (R * R)
                 : kPi * diagonal * diagonal / static_cast<double>(std::max<std::uint64_t>(raysPerSource, 1));
    const double smallest = *std::min_element(areas.begin(), areas.end());
    // Surface view factors are a result in their own right, so there the check asks for 100
    // rays (10 % noise), not one: a surface view factor from 7 rays is 40 % off, and users read
    // such a table entry by entry. Rows of a patch matrix only feed a solve, where the noise
    // of many patches averages out; there a receiver that no ray can reach is the failure.
    const bool surfaceRows = surfaceSources && !hemicube;
    const double wanted = surfaceRows ? 100.0 : 1.0;
    if (smallest >= wanted * resolvable) return {};
    const auto below = std::count_if(areas.begin(), areas.end(), [&](double a) { return a < wanted * resolvable; });
    const double sample =
        hemicube ? 4.0 / (kPi * R * R) : 1.0 / static_cast<double>(std::max<std::uint64_t>(raysPerSource, 1));
    const double smallestF = smallest / (kPi * diagonal * diagonal);
    const char* what = surfaceSources ? "surfaces" : "patches";
    if (surfaceRows && smallest >= resolvable) {
        const double k = smallestF / sample;
        return {
            format("%s: %lld of %zu surfaces (the smallest %.3g m^2, a form factor of %.3g from %.3g m away) get "
                   "fewer than 100 rays from a source across the scene (the smallest about %.0f of %llu): their "
                   "view factors carry about %.0f %% noise; use --rays %.3g or more for 100",
                   method.c_str(), static_cast<long long>(below), areas.size(), smallest, smallestF, diagonal, k,
                   static_cast<unsigned long long>(raysPerSource), 100.0 / std::sqrt(k),
                   std::ceil(100.0 * kPi * diagonal * diagonal / smallest))};
    }
    std::string unit, remedy;
    if (hemicube) {
        unit = format("hemicube pixel (at --hemicube-res %.0f, a form factor of %.3g)", R, sample);
        remedy = format("use --hemicube-res %.0f or more, or --method shoot or gather",
                        2.0 * std::ceil(diagonal / std::sqrt(smallest)));  // even
    } else {
        unit =
            format("ray (one of %llu, a form factor of %.3g)", static_cast<unsigned long long>(raysPerSource), sample);
        remedy =
            format("use %s %.3g or more (now %llu)%s", surfaceSources ? "--rays" : "--rays-per-patch",
                   std::ceil(wanted * kPi * diagonal * diagonal / smallest),
                   static_cast<unsigned long long>(raysPerSource), surfaceSources ? "" : ", or a larger --patch-size");
    }
    return {
        format("%s: %lld of %zu %s (the smallest %.3g m^2, a form factor of %.3g from %.3g m away) get less than one "
               "%s from a source across the scene: such receivers are missed or counted whole; %s",
               method.c_str(), static_cast<long long>(below), areas.size(), what, smallest, smallestF, diagonal,
               unit.c_str(), remedy.c_str())};
}

// A uniform grid of cells as large as the largest patch finds every such pair among
// neighbouring cells.
std::vector<std::string> nearField(const Mesh& mesh, const std::string& method) {
    const std::size_t n = mesh.patches.size();
    if (n < 2) return {};
    std::vector<glm::vec3> centre(n);
    std::vector<float> size(n);
    float cell = 0.0f;
    for (std::size_t i = 0; i < n; ++i) {
        centre[i] = centroid(mesh.patches[i]);
        size[i] = longestEdge(mesh.patches[i]);
        cell = std::max(cell, size[i]);
    }
    if (!(cell > 0.0f)) return {};
    auto key = [](long long x, long long y, long long z) {
        return static_cast<std::uint64_t>((x & 0x1FFFFF) | ((y & 0x1FFFFF) << 21) | ((z & 0x1FFFFF) << 42));
    };
    auto cellOf = [&](const glm::vec3& c, long long out[3]) {
        for (int k = 0; k < 3; ++k) out[k] = static_cast<long long>(std::floor(c[k] / cell));
    };
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
    for (std::size_t i = 0; i < n; ++i) {
        long long c[3];
        cellOf(centre[i], c);
        grid[key(c[0], c[1], c[2])].push_back(static_cast<std::uint32_t>(i));
    }
    std::vector<char> near(n, 0);
    std::uint64_t tests = 0;
    const std::uint64_t budget = 400'000'000;  // bounds the time on pathological meshes
    std::size_t example = n;
    for (std::size_t i = 0; i < n && tests < budget; ++i) {
        long long c[3];
        cellOf(centre[i], c);
        const Patch& a = mesh.patches[i];
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy)
                for (long long dz = -1; dz <= 1; ++dz) {
                    const auto found = grid.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
                    if (found == grid.end()) continue;
                    for (std::uint32_t j : found->second) {
                        if (j <= i) continue;
                        ++tests;
                        const glm::vec3 d = centre[j] - centre[i];
                        const float reach = std::max(size[i], size[j]);
                        if (glm::dot(d, d) >= reach * reach) continue;
                        // Facing each other: each lies in front of the other (coplanar
                        // neighbours and back-to-back patches do not exchange light).
                        const Patch& b = mesh.patches[j];
                        const float eps = 1e-4f * reach;
                        if (glm::dot(d, a.normal) > eps && glm::dot(-d, b.normal) > eps) {
                            if (!near[i] && example == n) example = i;
                            near[i] = near[j] = 1;
                        }
                    }
                }
    }
    const auto count = std::count(near.begin(), near.end(), 1);
    if (count == 0) return {};
    const std::string how = method == "hemicube" ? "the hemicube sees from each patch's centre only"
                                                 : "gather evaluates each receiver at three points only";
    return {format(
        "%s: %lld of %zu patches (%.1f %%)%s face another patch nearer than their own size (at corners and "
        "contacts; one is at %.3g, %.3g, %.3g relative to the scene's centre): %s, and the form factor varies "
        "across such a patch; use a smaller --patch-size (fewer patches are affected) or --method shoot",
        method.c_str(), static_cast<long long>(count), n, 100.0 * static_cast<double>(count) / static_cast<double>(n),
        tests >= budget ? " or more" : "", centre[example].x, centre[example].y, centre[example].z, how.c_str())};
}

}  // namespace rad
