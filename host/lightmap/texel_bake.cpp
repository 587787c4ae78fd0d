#include "lightmap/texel_bake.h"

#include <algorithm>

#include "device/kernel_arguments.h"
#include "lightmap/texel_footprints.h"
#include "shared_math.h"
#include "util/error.h"
#include "util/sample_streams.h"

namespace rad {
namespace {

// Texels per launch, and samples per texel in one: constants, so the launches depend on the
// layout and the sample count alone. 16 samples as the camera pass's launches (render/
// pixel_estimate.cpp says why: llvmpipe ends long loops).
constexpr std::size_t kTexelsPerLaunch = 1u << 16;
constexpr std::uint32_t kMaxSamplesPerLaunch = 16;

// Which side of each face the lightmap holds: the front, or for a double-sided face the side
// whose chart received more light on it in the solution (the luminance of the light arriving
// at its elements, times their area, summed over the chart's double-sided faces), so
// that a panel whose normal points away from its lamp is not baked dark. Decided per chart, so
// the faces of one chart, and the seams and contacts between them, are all on one side.
std::vector<bool> bakedBacks(const Mesh& mesh, const ViewPathSolution& solution, const LightmapLayout& layout) {
    auto received = [&](std::uint32_t firstPatch, std::uint32_t subdivision) {
        double sum = 0.0;
        const auto& start = solution.elements.elementStart();
        for (std::uint32_t p = firstPatch; p < firstPatch + subdivision * subdivision; ++p)
            for (std::uint32_t e = start[p]; e < start[p + 1]; ++e) {
                const glm::vec3& c = solution.elementIrradiance[e];
                sum += (0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z) * solution.elements.elements()[e].area;
            }
        return sum;
    };
    std::vector<double> front(layout.charts, 0.0), back(layout.charts, 0.0);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        if (face.backPatch == kNoPatch) continue;
        front[layout.chartOf[f]] += received(face.frontPatch, face.subdivision);
        back[layout.chartOf[f]] += received(face.backPatch, face.subdivision);
    }
    std::vector<bool> out(mesh.faces.size(), false);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        out[f] = mesh.faces[f].backPatch != kNoPatch && back[layout.chartOf[f]] > front[layout.chartOf[f]];
    return out;
}

}  // namespace

std::uint64_t lightmapHostBytes(const LightmapLayout& layout) {
    const std::uint64_t texels = std::uint64_t{layout.pageSize} * layout.pageSize;
    // Per texel of every page: irradiance, radiance, variance, area (36 bytes), the radiance's
    // copy and PNG that lightmapped.glb is built from (16) and the strength's list (4). Per
    // texel of the page at work: its footprint's pieces and lists as built (about 150 bytes per
    // texel holding surface, which at most all do) and the pull-push levels (75). A 2048-texel
    // page of the Cornell box (half its texels hold surface) ran in 1.27 GB resident; this says
    // 1.17 GB.
    return layout.pages * texels * 56 + texels * (150 + 75);
}

BakedLightmap bakeLightmap(const PreparedScene& scene, const ViewPathSolution& solution, const LightmapLayout& layout,
                           const LightmapBakeOptions& options) {
    const ViewPathInputs inputs(scene, solution, options.mode == RenderMode::direct, options.indirectRaysPerElement,
                                options.seed);
    return bakeLightmap(scene, solution, inputs, layout, options);
}

namespace {

void checkBake(const ViewPathInputs& inputs, const LightmapLayout& layout, const LightmapBakeOptions& options) {
    if (options.samples < 1) throw InputError("the lightmap needs at least one sample per texel");
    if (options.mode == RenderMode::radiosity)
        throw InputError("the lightmap's texels are baked in the direct or final-gather mode");
    if (options.mode == RenderMode::direct && !inputs.direct())
        throw InputError("the direct-mode lightmap needs the solution's indirect light per element");
    const std::uint64_t side = layout.pageSize;
    // layoutLightmap refuses more texels than the keys number (2^32) and more charts than the
    // chart numbers hold beside RAD_LIGHTMAP_BACK.
    if (std::uint64_t{layout.pages} * side * side > 0xFFFFFFFFull || layout.charts >= RAD_LIGHTMAP_BACK)
        throw InputError("a lightmap of " + std::to_string(layout.pages) + " pages of " + std::to_string(side) +
                         " texels a side and " + std::to_string(layout.charts) +
                         " charts is more than this program numbers");
}

// One launch's texels summed over their samples.
struct TexelSums {
    explicit TexelSums(std::size_t count)
        : irradiance(count, glm::dvec3(0.0)), radiance(count, glm::dvec3(0.0)), squares(count, 0.0), counted(count, 0.0) {}
    std::vector<glm::dvec3> irradiance, radiance;
    std::vector<double> squares;  // of the irradiance's luminance
    std::vector<double> counted;  // samples on the anchor's side
    std::uint64_t rays = 0;
};

// The bake of one layout: the faces' corners and charts on the device for the whole of it,
// then page by page, launch by launch, the texels' samples summed and their means kept.
class TexelBake {
public:
    TexelBake(const PreparedScene& scene, const ViewPathSolution& solution, const ViewPathInputs& inputs,
              const LightmapLayout& layout, const LightmapBakeOptions& options, BakedLightmap& out)
        : scene_(scene), layout_(layout), options_(options), out_(out),
          kernel_(scene.device().kernel<LightmapTexelsArgs>("lightmap.cl", "lightmap_texels", inputs.arguments())) {
        uploadFaces(solution);
        args_.faceCorners = corners_;
        args_.chartOfFace = charts_;
        args_.mode = viewPathMode(options.mode);
        args_.seed = rad_hash2(options.seed, kLightmapTexelsStream);
        args_.near = static_cast<float>(options.nearPatches * scene.mesh().patchSize);
    }

    LightmapPage bakePage(std::uint32_t page) {
        const std::size_t texelsPerPage = std::size_t{layout_.pageSize} * layout_.pageSize;
        LightmapPage result;
        result.irradiance.assign(texelsPerPage, glm::vec3(0.0f));
        result.radiance.assign(texelsPerPage, glm::vec3(0.0f));
        result.variance.assign(texelsPerPage, 0.0f);
        result.area.assign(texelsPerPage, 0.0);
        const TexelFootprints footprints = texelFootprints(layout_, scene_.mesh(), page);
        out_.texels += footprints.texels.size();
        out_.sharedTexels += footprints.sharedTexels;
        for (std::size_t first = 0; first < footprints.texels.size(); first += kTexelsPerLaunch) {
            const std::size_t count = std::min(kTexelsPerLaunch, footprints.texels.size() - first);
            const TexelSums sums = sample(footprints, page * texelsPerPage, first, count);
            out_.rays += sums.rays;
            keepMeans(footprints, first, sums, result);
        }
        return result;
    }

private:
    // Each face's corners, and its chart with RAD_LIGHTMAP_BACK where its back is baked.
    void uploadFaces(const ViewPathSolution& solution) {
        const Mesh& mesh = scene_.mesh();
        const std::size_t faces = std::max<std::size_t>(mesh.faces.size(), 1);
        std::vector<rad_float4> cornerPoints(3 * faces, rad_float4{});
        for (std::size_t f = 0; f < mesh.faces.size(); ++f)
            for (std::size_t k = 0; k < 3; ++k) {
                const glm::vec3& p = mesh.faces[f].p[k];
                cornerPoints[3 * f + k] = {{p.x, p.y, p.z, 0.0f}};
            }
        corners_ = DeviceArray<rad_float4>::upload(scene_.compute(), cornerPoints, "faces' corners");
        std::vector<rad_uint> chartOf(faces, 0);
        std::copy(layout_.chartOf.begin(), layout_.chartOf.end(), chartOf.begin());
        const std::vector<bool> backs = bakedBacks(mesh, solution, layout_);
        for (std::size_t f = 0; f < backs.size(); ++f)
            if (backs[f]) {
                chartOf[f] |= RAD_LIGHTMAP_BACK;
                ++out_.backSides;
            }
        charts_ = DeviceArray<rad_uint>::upload(scene_.compute(), chartOf, "faces' charts");
    }

    // The footprints' texels first .. first + count - 1, keyed from firstKey on, over all their
    // samples, kMaxSamplesPerLaunch at a time.
    TexelSums sample(const TexelFootprints& footprints, std::size_t firstKey, std::size_t first, std::size_t count) {
        ComputeContext& compute = scene_.compute();
        const rad_uint before = first == 0 ? 0 : footprints.ends[first - 1];
        std::vector<rad_uint> ends(count), keys(count);
        for (std::size_t i = 0; i < count; ++i) {
            ends[i] = footprints.ends[first + i] - before;
            keys[i] = static_cast<rad_uint>(firstKey + footprints.texels[first + i]);
        }
        const std::vector<TexelPiece> pieces(footprints.pieces.begin() + before,
                                             footprints.pieces.begin() + footprints.ends[first + count - 1]);
        const std::vector<TexelAnchor> anchors(footprints.anchors.begin() + static_cast<std::ptrdiff_t>(first),
                                               footprints.anchors.begin() + static_cast<std::ptrdiff_t>(first + count));
        // This launch's own arrays: piece lists, pieces, anchors, keys; sums and counts.
        const std::string texels = "lightmap (" + std::to_string(count) + " texels)";
        const auto endArray = DeviceArray<rad_uint>::upload(compute, ends, texels + ": piece lists");
        const auto pieceArray = DeviceArray<TexelPiece>::upload(compute, pieces, texels + ": pieces");
        const auto anchorArray = DeviceArray<TexelAnchor>::upload(compute, anchors, texels + ": anchors");
        const auto keyArray = DeviceArray<rad_uint>::upload(compute, keys, texels + ": keys");
        const auto eArray = DeviceArray<rad_float4>::allocate(compute, count, texels + ": irradiance", DeviceAccess::write);
        const auto lArray = DeviceArray<rad_float4>::allocate(compute, count, texels + ": radiance", DeviceAccess::write);
        const auto rayArray = DeviceArray<rad_uint>::allocate(compute, count, texels + ": ray counts", DeviceAccess::write);
        // Cleared: the first launch casts each anchor's probes and keeps what they found.
        const auto enclosureArray = DeviceArray<rad_uint>::upload(compute, std::vector<rad_uint>(count, 0u),
                                                                  texels + ": enclosure", DeviceAccess::readWrite);
        args_.pieceEnds = endArray;
        args_.pieces = pieceArray;
        args_.anchors = anchorArray;
        args_.texelKeys = keyArray;
        args_.texelCount = static_cast<rad_uint>(count);
        args_.irradiance = eArray;
        args_.radiance = lArray;
        args_.rays = rayArray;
        args_.enclosure = enclosureArray;
        TexelSums sums(count);
        std::vector<rad_float4> e(count), l(count);
        for (std::uint32_t s = 0; s < options_.samples; s += kMaxSamplesPerLaunch) {
            args_.firstSample = s;
            args_.sampleCount = std::min(kMaxSamplesPerLaunch, options_.samples - s);
            kernel_.launch(args_, count);
            eArray.enqueueRead(e);
            lArray.enqueueRead(l);
            const std::vector<rad_uint> rays = rayArray.read();
            for (std::size_t i = 0; i < count; ++i) {
                sums.irradiance[i] += glm::dvec3(e[i].s[0], e[i].s[1], e[i].s[2]);
                sums.squares[i] += e[i].s[3];
                sums.radiance[i] += glm::dvec3(l[i].s[0], l[i].s[1], l[i].s[2]);
                sums.counted[i] += l[i].s[3];
                sums.rays += rays[i];
            }
        }
        return sums;
    }

    // Only the samples on the anchor's side count; a texel with none stays empty.
    static void keepMeans(const TexelFootprints& footprints, std::size_t first, const TexelSums& sums,
                          LightmapPage& page) {
        for (std::size_t i = 0; i < sums.counted.size(); ++i) {
            const double n = sums.counted[i];
            if (!(n > 0.0)) continue;
            const std::size_t texel = footprints.texels[first + i];
            const glm::dvec3 mean = sums.irradiance[i] / n;
            page.irradiance[texel] = glm::vec3(mean);
            page.radiance[texel] = glm::vec3(sums.radiance[i] / n);
            page.area[texel] = footprints.area[first + i];
            const double luminance = 0.2126 * mean.x + 0.7152 * mean.y + 0.0722 * mean.z;
            const double spread =
                n > 1 ? std::max(0.0, sums.squares[i] - n * luminance * luminance) / (n - 1.0) : 0.0;
            page.variance[texel] = static_cast<float>(spread / n);
        }
    }

    const PreparedScene& scene_;
    const LightmapLayout& layout_;
    const LightmapBakeOptions& options_;
    BakedLightmap& out_;
    DeviceKernel<LightmapTexelsArgs> kernel_;
    DeviceArray<rad_float4> corners_;
    DeviceArray<rad_uint> charts_;
    LightmapTexelsArgs args_;
};

}  // namespace

BakedLightmap bakeLightmap(const PreparedScene& scene, const ViewPathSolution& solution, const ViewPathInputs& inputs,
                           const LightmapLayout& layout, const LightmapBakeOptions& options) {
    checkBake(inputs, layout, options);
    BakedLightmap out;
    out.size = layout.pageSize;
    out.samples = options.samples;
    TexelBake bake(scene, solution, inputs, layout, options, out);
    for (std::uint32_t page = 0; page < layout.pages; ++page) out.pages.push_back(bake.bakePage(page));
    return out;
}

}  // namespace rad
