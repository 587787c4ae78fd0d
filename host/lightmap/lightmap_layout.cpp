#include "lightmap/lightmap_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <tuple>

#include <glm/geometric.hpp>

#include "lightmap/chart_atlas.h"
#include "util/error.h"

namespace rad {
namespace {

double uvArea(const std::array<glm::dvec2, 3>& t) {
    return 0.5 * std::fabs((t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y));
}

double faceArea(const Face& f) {
    return 0.5 *
           glm::length(glm::cross(glm::dvec3(f.p[1]) - glm::dvec3(f.p[0]), glm::dvec3(f.p[2]) - glm::dvec3(f.p[0])));
}

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", x);
    return text;
}

// Why the scene's TEXCOORD_1 cannot hold the lightmap, or empty where it can. Fills `layout`'s
// faces' texel coordinates on one page either way.
std::string sceneUvProblem(const Scene& scene, const Mesh& mesh, LightmapLayout& layout) {
    bool any = false;
    for (const Surface& s : scene.surfaces) any = any || !s.texCoords[1].empty();
    if (!any) return "the scene gives no TEXCOORD_1";
    const double side = layout.pageSize;
    std::vector<std::array<glm::dvec2, 3>> uv(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        const Surface& surface = scene.surfaces[face.sceneSurface];
        if (surface.texCoords[1].empty())
            return "surface '" + surface.name + "' has no TEXCOORD_1 (every baked primitive needs one)";
        for (int k = 0; k < 3; ++k) {
            const glm::vec2 t =
                surface.texCoords[1][surface.triangles[face.sceneTriangle][static_cast<std::size_t>(k)]];
            if (!(t.x >= 0.0f && t.x <= 1.0f && t.y >= 0.0f && t.y <= 1.0f))
                return "surface '" + surface.name +
                       "' has TEXCOORD_1 outside [0, 1] (a lightmap's UVs cover one "
                       "image once)";
            uv[f][static_cast<std::size_t>(k)] = glm::dvec2(t) * side;
        }
    }
    const UvLayoutCheck check = checkUvLayout(uv);
    if (!check.usable()) {
        std::string what = "its TEXCOORD_1 ";
        if (check.overlappingPairs > 0) {
            what += "has " + std::to_string(check.overlappingPairs) + " overlapping pairs of triangles (faces " +
                    std::to_string(check.examples[0][0]) + " and " + std::to_string(check.examples[0][1]) +
                    " the first)";
            if (check.degenerate > 0) what += " and ";
        }
        if (check.degenerate > 0) what += std::to_string(check.degenerate) + " triangles of no UV area";
        return what;
    }
    layout.texels = std::move(uv);
    return "";
}

void finishSceneLayout(const Mesh& mesh, LightmapLayout& layout) {
    layout.fromScene = true;
    layout.pages = 1;
    layout.pageOf.assign(mesh.faces.size(), 0);
    // Texel size: the median, by area, of each face's metres per texel edge.
    std::vector<std::pair<double, double>> sizes;  // (metres per texel, area)
    double used = 0.0, total = 0.0;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const double texels = uvArea(layout.texels[f]), area = faceArea(mesh.faces[f]);
        used += texels;
        if (texels > 0.0 && area > 0.0) {
            sizes.emplace_back(std::sqrt(area / texels), area);
            total += area;
        }
    }
    std::sort(sizes.begin(), sizes.end());
    double below = 0.0;
    for (const auto& [size, area] : sizes) {
        layout.texelSize = size;
        below += area;
        if (below >= 0.5 * total) break;
    }
    layout.largestStretch = 1.0;
    double stretched = 0.0;
    for (const auto& [size, area] : sizes) {
        const double ratio = (size * size) / (layout.texelSize * layout.texelSize);
        layout.largestStretch = std::max(layout.largestStretch, std::max(ratio, 1.0 / ratio));
        stretched += std::max(ratio, 1.0 / ratio) * area;
    }
    if (total > 0.0) layout.meanStretch = stretched / total;
    layout.areaUse = used / (static_cast<double>(layout.pageSize) * layout.pageSize);
    // Charts: faces joined by an edge they share with the same texel coordinates on both sides.
    std::map<std::tuple<double, double, double, double>, std::uint32_t> seen;
    std::vector<std::uint32_t> parent(mesh.faces.size());
    for (std::uint32_t f = 0; f < parent.size(); ++f) parent[f] = f;
    auto root = [&](std::uint32_t f) {
        while (parent[f] != f) f = parent[f] = parent[parent[f]];
        return f;
    };
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            glm::dvec2 a = layout.texels[f][static_cast<std::size_t>(k)],
                       b = layout.texels[f][static_cast<std::size_t>((k + 1) % 3)];
            if (std::tie(b.x, b.y) < std::tie(a.x, a.y)) std::swap(a, b);
            const auto key = std::make_tuple(a.x, a.y, b.x, b.y);
            const auto found = seen.emplace(key, f);
            if (!found.second) parent[root(f)] = root(found.first->second);
        }
    layout.charts = 0;
    std::vector<std::uint32_t> numberOf(parent.size(), 0xFFFFFFFFu);
    layout.chartOf.resize(parent.size());
    for (std::uint32_t f = 0; f < parent.size(); ++f) {
        const std::uint32_t r = root(f);
        if (numberOf[r] == 0xFFFFFFFFu) numberOf[r] = layout.charts++;
        layout.chartOf[f] = numberOf[r];
    }
}

// The options' own limits, before any work.
void checkLayoutOptions(const std::string& path, const LightmapOptions& options) {
    if (options.pageSize != 0 && (options.pageSize < 8 || options.pageSize > 8192))
        throw InputError(path + ": a lightmap page must be 8 to 8192 texels on a side (got " +
                         std::to_string(options.pageSize) + ")");
    if (!(options.texelSize >= 0.0) || !std::isfinite(options.texelSize))
        throw InputError(path + ": the lightmap's texel size must be a positive number of metres (got " +
                         number(options.texelSize) + ")");
    if (!(options.attachShare >= 0.0 && options.attachShare <= 1.0))
        throw InputError(path + ": the lightmap's attach share must be 0 to 1 of a page (got " +
                         number(options.attachShare) + ")");
}

constexpr std::uint32_t kDefaultPageSize = 1024;

// Atlases of the mesh's faces at the texel and page sizes the options leave open; a face too
// large for a page is refused with its name as the user knows it.
class AtlasMaker {
public:
    AtlasMaker(const Scene& scene, const Mesh& mesh, const LightmapOptions& options)
        : scene_(scene), mesh_(mesh), triangles_(mesh.faces.size()) {
        std::vector<std::uint32_t> material(mesh.faces.size());
        for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
            for (int k = 0; k < 3; ++k)
                triangles_[f][static_cast<std::size_t>(k)] = glm::dvec3(mesh.faces[f].p[static_cast<std::size_t>(k)]);
            area_ += faceArea(mesh.faces[f]);
            material[f] = static_cast<std::uint32_t>(mesh.faces[f].material);
        }
        options_.gutter = options.gutter;
        charts_ = makeCharts(triangles_, material, chartOptions(options));
    }

    // At both sizes given.
    Atlas atTexelSize(double texelSize, std::uint32_t pageSize) const {
        AtlasAttempt attempt = at(texelSize, pageSize);
        if (!attempt.atlas) refuse(attempt.oversized, texelSize, pageSize);
        return std::move(*attempt.atlas);
    }

    // At the texel size given, on the smallest page from 64 to 4096 texels (by powers of two)
    // that holds it whole, else on pages of 4096. Pages smaller than the surface's own texels
    // are not tried.
    Atlas onSmallestPage(double texelSize) const {
        const double texels = area_ / (texelSize * texelSize);
        std::uint32_t pageSize = 64;
        while (pageSize < kLargestSearchedPage && double(pageSize) * pageSize < texels) pageSize *= 2;
        for (;; pageSize *= 2) {
            AtlasAttempt attempt = at(texelSize, pageSize);
            if (!attempt.atlas) {
                if (pageSize == kLargestSearchedPage) refuse(attempt.oversized, texelSize, pageSize);
                continue;
            }
            if (attempt.atlas->pages <= 1 || pageSize == kLargestSearchedPage) return std::move(*attempt.atlas);
        }
    }

    // Small texels that put everything on one page. The packed charts' extent goes about as the
    // inverse square of the texel size, so each try scales the texel size by the square root of
    // the pages it filled (the last page by its rows) over 0.99, within the interval between the
    // largest size found too small and the smallest that fits, until the last page is filled to
    // 97 % or eight tries are spent: the smallest size that fitted.
    Atlas onOnePage(std::uint32_t pageSize) const {
        if (!(area_ > 0.0)) throw InputError(scene_.path + ": the scene has no surface area to lay a lightmap on");
        double tooSmall = 0.0, fits = INFINITY;
        std::optional<Atlas> best;
        double size = std::sqrt(area_ / 0.65) / pageSize;  // the surface at 65 % of the page
        for (int tries = 0; tries < 60; ++tries) {
            AtlasAttempt attempt = at(size, pageSize);
            double next;
            if (!attempt.atlas) {  // a face larger than a page: larger texels
                tooSmall = std::max(tooSmall, size);
                next = size * 1.5;
            } else {
                const double filled = attempt.atlas->pagesFilled;
                if (attempt.atlas->pages <= 1) {
                    if (size < fits) fits = size, best = std::move(*attempt.atlas);
                    if (filled >= 0.97) break;
                } else {
                    tooSmall = std::max(tooSmall, size);
                }
                next = size * std::sqrt(std::max(filled, 1e-6) / 0.99);
            }
            if (best && (tries >= 7 || fits <= tooSmall * 1.002)) break;
            // Stay strictly inside what is known; halve the interval where the scaling would not.
            if (!(next > tooSmall && next < fits)) next = std::isfinite(fits) ? 0.5 * (tooSmall + fits) : tooSmall * 1.5;
            size = next;
        }
        if (!best)
            throw InputError(scene_.path + ": found no texel size that puts the lightmap on one page of " +
                             std::to_string(pageSize) + " texels; give --texel-size");
        return std::move(*best);
    }

private:
    static constexpr std::uint32_t kLargestSearchedPage = 4096;

    // The options' charts, attaching those under attachShare of a page where no attach area is
    // set, up to an eighth of a page a side: the page at the texel size given or at one that
    // would fill 65 % of it (charts are made once, before the texel size search).
    ChartOptions chartOptions(const LightmapOptions& options) const {
        ChartOptions charts = options.charts;
        if (charts.attachArea > 0.0 || !(options.attachShare > 0.0) || !(area_ > 0.0)) return charts;
        const double page = options.pageSize == 0 ? kDefaultPageSize : options.pageSize;
        const double texel = options.texelSize > 0.0 ? options.texelSize : std::sqrt(area_ / 0.65) / page;
        const double pageSide = options.texelSize > 0.0 && options.pageSize == 0
                                    ? std::max(64.0 * texel, std::sqrt(area_))  // about the smallest page's
                                    : page * texel;
        charts.attachArea = options.attachShare * pageSide * pageSide;
        charts.attachExtent = pageSide / 8.0;
        return charts;
    }

    AtlasAttempt at(double texelSize, std::uint32_t pageSize) const {
        AtlasOptions o = options_;
        o.texelSize = texelSize;
        o.pageSize = pageSize;
        return tryAtlas(triangles_, charts_, o);
    }

    [[noreturn]] void refuse(const OversizedTriangle& oversized, double texelSize, std::uint32_t pageSize) const {
        const Face& face = mesh_.faces[oversized.triangle];
        throw InputError(scene_.path + ": lightmap: triangle " + std::to_string(face.sceneTriangle) + " of surface '" +
                         scene_.surfaces[face.sceneSurface].name + "' is larger than a page of " +
                         std::to_string(pageSize) + " texels at " + number(texelSize) +
                         " m per texel; use a texel size of " + number(oversized.fittingTexelSize) +
                         " m or more, or larger pages");
    }

    const Scene& scene_;
    const Mesh& mesh_;
    std::vector<std::array<glm::dvec3, 3>> triangles_;
    ChartSet charts_;  // the same at every texel size
    double area_ = 0.0;
    AtlasOptions options_;
};

LightmapLayout madeLayout(const Mesh& mesh, Atlas atlas) {
    LightmapLayout layout;
    layout.pageSize = atlas.pageSize;
    layout.pages = atlas.pages;
    layout.charts = static_cast<std::uint32_t>(atlas.charts.size());
    layout.texelSize = atlas.texelSize;
    layout.areaUse = atlas.areaUse;
    layout.largestStretch = atlas.largestStretch;
    layout.meanStretch = atlas.meanStretch;
    layout.texels = std::move(atlas.texels);
    layout.chartOf = atlas.chartOf;
    layout.pageOf.resize(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) layout.pageOf[f] = atlas.charts[atlas.chartOf[f]].page;
    return layout;
}

// The texels and charts are numbered in 32 bits (texel keys; chart numbers beside
// RAD_LIGHTMAP_BACK).
const LightmapLayout& numberable(const std::string& path, const LightmapLayout& layout) {
    const std::uint64_t side = layout.pageSize;
    if (std::uint64_t{layout.pages} * side * side > 0xFFFFFFFFull || layout.charts >= 0x80000000u)
        throw InputError(path + ": a lightmap of " + std::to_string(layout.pages) + " pages of " +
                         std::to_string(side) + " texels a side (" + std::to_string(layout.charts) +
                         " charts) is more than this program numbers (2^32 texels, 2^31 charts): use a larger "
                         "--texel-size");
    return layout;
}

}  // namespace

// In two phases: the scene's own TEXCOORD_1 where asked for or usable; else an atlas made at
// the texel and page sizes given, the texel size that puts it on one page, or the smallest page
// that holds it at the texel size given.
LightmapLayout layoutLightmap(const Scene& scene, const Mesh& mesh, const LightmapOptions& options) {
    checkLayoutOptions(scene.path, options);
    std::string sceneRefused;  // why not the scene's UVs, where it has some
    if (options.uv != LightmapOptions::Uv::atlas) {
        LightmapLayout layout;
        layout.pageSize = options.pageSize == 0 ? kDefaultPageSize : options.pageSize;
        const std::string problem = sceneUvProblem(scene, mesh, layout);
        if (problem.empty()) {
            finishSceneLayout(mesh, layout);
            if (options.texelSize > 0.0)
                layout.note = "the texel size applies to a made atlas only: the scene's TEXCOORD_1 is used as it is";
            return numberable(scene.path, layout);
        }
        if (options.uv == LightmapOptions::Uv::scene)
            throw InputError(scene.path + ": cannot bake into the scene's lightmap UVs: " + problem);
        bool any = false;
        for (const Surface& s : scene.surfaces) any = any || !s.texCoords[1].empty();
        if (any) sceneRefused = problem;
    }
    const AtlasMaker maker(scene, mesh, options);
    Atlas atlas;
    if (!(options.texelSize > 0.0))
        atlas = maker.onOnePage(options.pageSize == 0 ? kDefaultPageSize : options.pageSize);
    else if (options.pageSize == 0)
        atlas = maker.onSmallestPage(options.texelSize);
    else
        atlas = maker.atTexelSize(options.texelSize, options.pageSize);
    LightmapLayout layout = madeLayout(mesh, std::move(atlas));
    if (!sceneRefused.empty()) layout.note = sceneRefused + "; made an atlas instead";
    return numberable(scene.path, layout);
}

LightmapUvs lightmapUvs(const Scene& scene, const Mesh& mesh, const LightmapLayout& layout, std::size_t surface) {
    std::size_t firstFace = 0;
    for (std::size_t s = 0; s < surface; ++s) firstFace += scene.surfaces[s].triangles.size();
    const Surface& source = scene.surfaces[surface];
    LightmapUvs out;
    std::map<std::tuple<std::uint32_t, float, float, std::uint32_t>, std::uint32_t> made;
    const auto side = static_cast<double>(layout.pageSize);
    for (std::size_t t = 0; t < source.triangles.size(); ++t) {
        const std::size_t f = firstFace + t;
        if (f >= mesh.faces.size()) throw InputError(scene.path + ": the mesh does not hold the scene's triangles");
        std::array<std::uint32_t, 3> corners{};
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t v = source.triangles[t][k];
            const glm::vec2 uv(layout.texels[f][k] / side);
            const auto key = std::make_tuple(v, uv.x, uv.y, layout.pageOf[f]);
            const auto found = made.find(key);
            if (found != made.end()) {
                corners[k] = found->second;
                continue;
            }
            corners[k] = static_cast<std::uint32_t>(out.uv.size());
            made.emplace(key, corners[k]);
            out.vertexOf.push_back(v);
            out.uv.push_back(uv);
        }
        out.triangles.push_back(corners);
        out.page.push_back(layout.pageOf[f]);
    }
    return out;
}

}  // namespace rad
