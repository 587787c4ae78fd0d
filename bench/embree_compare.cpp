// The ray engine against Embree 3 on the same triangles and the same rays (issue 17, part 1).
// Embree is a benchmark's dependency only (Debian's libembree-dev), never the program's.
//
//   bench_embree_compare [--scene FILE] [--triangles N] [--shooters K] [--rays R]
//                        [--threads T] [--repeats M] [--device D]
//
// The scene's patches at about N patches become the traced triangles (as bench_rays
// --tessellate does). R rays in all leave K shooter triangles spread over the list, R / K each:
// origins uniform on the triangle, lifted off it by 1e-5 of the scene's diagonal, directions
// cosine-distributed about its normal, made once on the host. Both engines find the closest hit
// of exactly those rays: ours with kernels/probes.cl's probe_trace (the traversal every kernel
// uses) on the OpenCL device (run under POCL_MAX_PTHREAD_COUNT=T for T threads), Embree with
// rtcIntersect1 and with rtcIntersect16 (packets of 16 consecutive rays, one shooter's, with
// Embree's default incoherent context, which goes on ray by ray once a packet thins out) on T
// std::threads taking 1024 rays at a time, each with flush-to-zero and denormals-are-zero set as
// Embree asks. Rays per second are medians of M timed repeats after
// an untimed one; the hits agree when both name the same triangle, or both miss, or their
// distances differ by under 1e-4 of the distance (a ray through a shared edge may take either
// side). One line of CSV.
//
// --job viewfactors: the whole job a user runs instead, `radiosity viewfactors` at surface
// level, against the Embree program a user would write for it (about a hundred lines): each
// surface side casts R rays (--rays, per surface) from points drawn by area over its triangles,
// cosine-distributed about the normal; the closest hit's side is counted for its surface (a
// single-sided face's back for none); the factors are written as CSV. Ours is the program's own
// code (computeSurfaceViewFactors, the table, the correction and writeViewFactorCsv), timed by
// phase: the device's shooting and counting, reading the counts back, adding them up per
// surface, and the table and CSV; Embree's: the rays (sampling, tracing, counting) on T
// threads, and the CSV. Scene setup (our mesh, BVH and upload; Embree's build) is timed apart.
// The two tables must agree within their noise (the largest |F_ours - F_embree| over its
// standard error is printed). One line of CSV.

#include <embree3/rtcore.h>
#include <pmmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "bench_support.h"
#include "device/kernel_arguments.h"
#include "formfactor/enforce.h"
#include "formfactor/surface_view_factors.h"
#include "formfactor/view_factor_table.h"
#include "io/atomic_file.h"
#include "io/view_factor_csv.h"
#include "prepared/prepared_scene.h"
#include "scene/gltf_loader.h"
#include "shared_math.h"
#include "util/stopwatch.h"

namespace {

struct Options {
    std::string scene = "scenes/cornell-box.gltf";
    std::size_t triangles = 16000;
    std::uint32_t shooters = 64;
    std::uint32_t rays = 1u << 20;
    unsigned threads = 1;
    std::string job;  // "" (rays made on the host, closest hit) or "viewfactors" (the whole job)
    int repeats = 5;
    std::string device;
};

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&] { return rad::bench::nextArgument(argc, argv, i); };
        if (a == "--scene") o.scene = next();
        else if (a == "--triangles") o.triangles = std::stoul(next());
        else if (a == "--shooters") o.shooters = static_cast<std::uint32_t>(std::stoul(next()));
        else if (a == "--rays") o.rays = static_cast<std::uint32_t>(std::stoul(next()));
        else if (a == "--threads") o.threads = static_cast<unsigned>(std::stoul(next()));
        else if (a == "--repeats") o.repeats = std::stoi(next());
        else if (a == "--device") o.device = next();
        else if (a == "--job") o.job = next();
        else {
            std::fprintf(stderr, "bench_embree_compare: unknown option %s\n", a.c_str());
            std::exit(2);
        }
    }
    if (!o.job.empty() && o.job != "viewfactors") {
        std::fprintf(stderr, "bench_embree_compare: --job takes viewfactors\n");
        std::exit(2);
    }
    o.shooters = std::max(1u, o.shooters);
    if (o.job.empty()) o.rays = std::max(o.rays / o.shooters, 1u) * o.shooters;
    o.threads = std::max(1u, o.threads);
    o.repeats = std::max(1, o.repeats);
    return o;
}

struct Rays {
    std::vector<rad_float4> origins, directions;
};

// The point of triangle (p0, p1, p2) that two uniform numbers pick, uniformly by area.
glm::vec3 pointOn(const std::array<glm::vec3, 3>& p, float u, float v) {
    if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
    return p[0] + u * (p[1] - p[0]) + v * (p[2] - p[0]);
}

// The cosine-distributed direction about unit normal n that two uniform numbers pick.
glm::vec3 cosineDirection(const glm::vec3& n, float u, float v) {
    const glm::vec3 a = std::fabs(n.x) > 0.5f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 t = glm::normalize(glm::cross(a, n)), b = glm::cross(n, t);
    const float r = std::sqrt(u), phi = 6.2831853f * v;
    return r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0f, 1.0f - r * r)) * n;
}

// R / K cosine rays from each of K triangles spread over the face list.
Rays makeRays(const rad::Mesh& mesh, const Options& o, float lift) {
    Rays rays;
    const std::uint32_t perShooter = o.rays / o.shooters;
    for (std::uint32_t k = 0; k < o.shooters; ++k) {
        const rad::Face& f = mesh.faces[(std::uint64_t{k} * mesh.faces.size()) / o.shooters];
        for (std::uint32_t i = 0; i < perShooter; ++i) {
            auto unit = [&](std::uint32_t salt) { return (rad_hash2(rad_hash2(k, i), salt) >> 8) * 0x1p-24f; };
            const glm::vec3 p = pointOn(f.p, unit(1), unit(2)) + lift * f.normal;
            const glm::vec3 d = cosineDirection(f.normal, unit(3), unit(4));
            rays.origins.push_back({{p.x, p.y, p.z, 0.0f}});
            rays.directions.push_back({{d.x, d.y, d.z, 0.0f}});
        }
    }
    return rays;
}

// Embree 3 on the same triangles: a device and a scene, released when this goes.
class EmbreeScene {
public:
    explicit EmbreeScene(const rad::Mesh& mesh) : device_(rtcNewDevice("threads=1")) {
        if (!device_) throw std::runtime_error("Embree: rtcNewDevice failed");
        scene_ = rtcNewScene(device_);
        rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * mesh.faces.size()));
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.faces.size()));
        for (std::size_t f = 0; f < mesh.faces.size(); ++f)
            for (int c = 0; c < 3; ++c) {
                for (int x = 0; x < 3; ++x) vertices[9 * f + 3 * c + x] = mesh.faces[f].p[c][x];
                indices[3 * f + c] = static_cast<unsigned>(3 * f + c);
            }
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene_, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(scene_);
        if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) throw std::runtime_error("Embree: building the scene failed");
    }
    ~EmbreeScene() {
        rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
    }
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    // Closest hits of rays [first, first + count): face (or -1) and distance.
    void trace1(const Rays& rays, std::size_t first, std::size_t count, int* faces, float* t) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (std::size_t i = first; i < first + count; ++i) {
            const rad_float4 &o = rays.origins[i], &d = rays.directions[i];
            t[i] = std::numeric_limits<float>::infinity();
            faces[i] = closest(glm::vec3(o.s[0], o.s[1], o.s[2]), glm::vec3(d.s[0], d.s[1], d.s[2]), context, &t[i]);
        }
    }

    // The same in packets of 16 consecutive rays.
    void trace16(const Rays& rays, std::size_t first, std::size_t count, int* faces, float* t) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (std::size_t base = first; base < first + count; base += 16) {
            alignas(64) RTCRayHit16 h{};
            alignas(64) int valid[16];
            for (int j = 0; j < 16; ++j) {
                const std::size_t i = base + j;
                valid[j] = i < first + count ? -1 : 0;
                const std::size_t r = valid[j] ? i : base;
                set(h.ray.org_x[j], h.ray.org_y[j], h.ray.org_z[j], rays.origins[r]);
                set(h.ray.dir_x[j], h.ray.dir_y[j], h.ray.dir_z[j], rays.directions[r]);
                h.ray.tnear[j] = 0.0f;
                h.ray.tfar[j] = std::numeric_limits<float>::infinity();
                h.ray.mask[j] = 0xFFFFFFFFu;
                h.hit.geomID[j] = RTC_INVALID_GEOMETRY_ID;
            }
            rtcIntersect16(valid, scene_, &context, &h);
            for (int j = 0; j < 16 && base + j < first + count; ++j) {
                faces[base + j] = h.hit.geomID[j] == RTC_INVALID_GEOMETRY_ID ? -1 : static_cast<int>(h.hit.primID[j]);
                t[base + j] = h.ray.tfar[j];
            }
        }
    }

    // The closest hit of one ray: its triangle, or -1 (and its distance in *distance, if given).
    int closest(const glm::vec3& origin, const glm::vec3& direction, RTCIntersectContext& context,
                float* distance = nullptr) const {
        RTCRayHit h{};
        h.ray.org_x = origin.x, h.ray.org_y = origin.y, h.ray.org_z = origin.z;
        h.ray.dir_x = direction.x, h.ray.dir_y = direction.y, h.ray.dir_z = direction.z;
        h.ray.tnear = 0.0f;
        h.ray.tfar = std::numeric_limits<float>::infinity();
        h.ray.mask = 0xFFFFFFFFu;
        h.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &context, &h);
        if (distance) *distance = h.ray.tfar;
        return h.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1 : static_cast<int>(h.hit.primID);
    }

private:
    static void set(float& x, float& y, float& z, const rad_float4& v) { x = v.s[0], y = v.s[1], z = v.s[2]; }

    RTCDevice device_;
    RTCScene scene_;
};

// Runs trace(first, count) over all rays on `threads` threads taking 1024 rays at a time.
template <typename Trace>
void onThreads(std::size_t rays, unsigned threads, const Trace& trace) {
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
        _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
        for (std::size_t first; (first = next.fetch_add(1024)) < rays;)
            trace(first, std::min<std::size_t>(1024, rays - first));
    };
    std::vector<std::thread> pool;
    for (unsigned k = 1; k < threads; ++k) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// The scene's patches at about o.triangles patches, as a scene whose triangles they are.
rad::Scene tessellatedScene(const Options& o) {
    rad::Scene loaded = rad::loadGltf(o.scene);
    const double patchSize = rad::bench::patchSizeForAbout(loaded, o.triangles);
    return rad::bench::tessellated(loaded, rad::buildMesh(loaded, {patchSize, 100'000'000}));
}

// The Embree program's job: counts[from * (surfaces + 2) + to], the last two columns the rays
// that left the scene and those stopped by a single-sided face's back.
std::vector<std::uint64_t> embreeViewFactorCounts(const rad::Mesh& mesh, const EmbreeScene& embree,
                                                  std::uint32_t raysPerSurface, unsigned threads, float lift) {
    const std::size_t surfaces = mesh.surfaces.size(), columns = surfaces + 2;
    std::vector<std::vector<double>> cdf(surfaces);  // each side's patches by area
    for (std::size_t s = 0; s < surfaces; ++s) {
        double sum = 0.0;
        for (std::uint32_t k = 0; k < mesh.surfaces[s].patchCount; ++k)
            cdf[s].push_back(sum += mesh.patches[mesh.surfaces[s].firstPatch + k].area);
    }
    constexpr std::uint32_t kChunk = 4096;
    const std::uint64_t chunks = (raysPerSurface + kChunk - 1) / kChunk;
    std::vector<std::uint64_t> counts(surfaces * columns, 0);
    std::mutex sum;
    std::atomic<std::uint64_t> next{0};
    auto work = [&] {
        _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
        _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        std::vector<std::uint64_t> own(counts.size(), 0);
        for (std::uint64_t item; (item = next.fetch_add(1)) < surfaces * chunks;) {
            const std::size_t s = item / chunks;
            const std::uint32_t first = static_cast<std::uint32_t>((item % chunks) * kChunk);
            const std::uint32_t last = std::min(raysPerSurface, first + kChunk);
            std::uint64_t* row = own.data() + s * columns;
            for (std::uint32_t i = first; i < last; ++i) {
                auto unit = [&](std::uint32_t salt) {
                    return (rad_hash2(rad_hash2(static_cast<std::uint32_t>(s), i), salt) >> 8) * 0x1p-24f;
                };
                const double pick = unit(1) * cdf[s].back();
                const std::size_t k = std::min<std::size_t>(
                    std::upper_bound(cdf[s].begin(), cdf[s].end(), pick) - cdf[s].begin(), cdf[s].size() - 1);
                const rad::Patch& p = mesh.patches[mesh.surfaces[s].firstPatch + k];
                const glm::vec3 o = pointOn(p.p, unit(2), unit(3)) + lift * p.normal;
                const glm::vec3 d = cosineDirection(p.normal, unit(4), unit(5));
                const int hit = embree.closest(o, d, context);
                if (hit < 0) {
                    ++row[surfaces];
                    continue;
                }
                const rad::Face& f = mesh.faces[static_cast<std::size_t>(hit)];
                const std::uint32_t side = glm::dot(d, f.normal) < 0.0f ? f.frontPatch : f.backPatch;
                ++row[side == rad::kNoPatch ? surfaces + 1 : mesh.patches[side].surface];
            }
        }
        const std::lock_guard<std::mutex> lock(sum);
        for (std::size_t c = 0; c < counts.size(); ++c) counts[c] += own[c];
    };
    std::vector<std::thread> pool;
    for (unsigned k = 1; k < threads; ++k) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    return counts;
}

void writeEmbreeCsv(const std::string& path, const rad::Mesh& mesh, const std::vector<std::uint64_t>& counts,
                    std::uint32_t raysPerSurface) {
    const std::size_t surfaces = mesh.surfaces.size(), columns = surfaces + 2;
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (!out) throw std::runtime_error("cannot write " + path);
    std::fprintf(out, "from,to,F,stderr\n");
    for (std::size_t i = 0; i < surfaces; ++i)
        for (std::size_t j = 0; j < surfaces; ++j) {
            const double f = double(counts[i * columns + j]) / raysPerSurface;
            if (f > 0.0)
                std::fprintf(out, "%s,%s,%.9g,%.3g\n", mesh.surfaces[i].name.c_str(), mesh.surfaces[j].name.c_str(), f,
                             std::sqrt(f * (1.0 - f) / raysPerSurface));
        }
    std::fclose(out);
}

int runViewFactorJob(const Options& o) {
    rad::Scene loaded = tessellatedScene(o);
    rad::Stopwatch clock;
    const rad::PreparedScene prepared(std::move(loaded), {1e9, 100'000'000}, rad::DeviceChoice{o.device});
    const double ourSetup = clock.seconds();
    const rad::Mesh& mesh = prepared.mesh();
    // Ray origins lifted off their triangle as the program lifts them (host/device/device_scene.cpp).
    const float lift = prepared.device().lift();
    clock = rad::Stopwatch();
    const EmbreeScene embree(mesh);
    const double embreeSetup = clock.seconds();
    const std::string folder = std::filesystem::temp_directory_path().string();
    const std::string ourCsv = folder + "/bench_embree_job_ours.csv", embreeCsv = folder + "/bench_embree_job_embree.csv";

    rad::ViewFactorOptions options;
    options.raysPerSurface = o.rays;
    std::vector<double> ours, shooting, reading, adding, writing, embreeJob, embreeRays, embreeWrite;
    rad::SurfaceViewFactors factors;
    std::vector<std::uint64_t> counts;
    for (int repeat = -1; repeat < o.repeats; ++repeat) {
        rad::Stopwatch job;
        factors = rad::computeSurfaceViewFactors(prepared, options);
        rad::Stopwatch table;
        rad::ViewFactorTable corrected = rad::surfaceTable(factors);
        rad::enforce(corrected, rad::kDefaultEnforce);
        rad::writeFileAtomically(ourCsv, [&](std::ostream& out) { rad::writeViewFactorCsv(out, corrected); });
        const double tableSeconds = table.seconds(), jobSeconds = job.seconds();

        rad::Stopwatch theirs;
        counts = embreeViewFactorCounts(mesh, embree, o.rays, o.threads, lift);
        const double raysSeconds = theirs.seconds();
        writeEmbreeCsv(embreeCsv, mesh, counts, o.rays);
        const double theirSeconds = theirs.seconds();
        if (repeat < 0) continue;
        ours.push_back(jobSeconds);
        shooting.push_back(factors.seconds.shooting);
        reading.push_back(factors.seconds.reading);
        adding.push_back(factors.seconds.adding);
        writing.push_back(tableSeconds);
        embreeJob.push_back(theirSeconds);
        embreeRays.push_back(raysSeconds);
        embreeWrite.push_back(theirSeconds - raysSeconds);
    }
    std::remove(ourCsv.c_str());
    std::remove(embreeCsv.c_str());

    // The two estimates of each factor, uncorrected, against their combined standard error.
    const std::size_t surfaces = mesh.surfaces.size(), columns = surfaces + 2;
    double worst = 0.0;
    for (std::size_t i = 0; i < surfaces; ++i)
        for (std::size_t j = 0; j < surfaces; ++j) {
            const double a = factors.factor(i, j), b = double(counts[i * columns + j]) / o.rays;
            const double m = 0.5 * (a + b), se = std::sqrt(std::max(m * (1.0 - m), 1.0 / o.rays) * 2.0 / o.rays);
            worst = std::max(worst, std::fabs(a - b) / se);
        }
    const double totalRays = double(o.rays) * surfaces;
    const double ourJob = median(ours), theirJob = median(embreeJob);
    std::printf(
        "scene,triangles,surfaces,rays_per_surface,threads,device,ours_setup_s,ours_job_s,ours_shooting_s,"
        "ours_reading_s,ours_adding_s,ours_table_and_csv_s,ours_rays_per_s,embree_setup_s,embree_job_s,embree_rays_s,"
        "embree_csv_s,embree_rays_per_s,ratio_to_embree,largest_difference_in_stderr\n");
    std::printf("%s,%zu,%zu,%u,%u,%s,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.3f,%.2f\n",
                o.scene.c_str(), mesh.faces.size(), surfaces, o.rays, o.threads,
                prepared.compute().description().name.c_str(), ourSetup, ourJob, median(shooting), median(reading),
                median(adding), median(writing), totalRays / ourJob, embreeSetup, theirJob, median(embreeRays),
                median(embreeWrite), totalRays / theirJob, theirJob / ourJob, worst);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    try {
        if (o.job == "viewfactors") return runViewFactorJob(o);
        rad::Scene loaded = tessellatedScene(o);
        const float lift = 1e-5f * static_cast<float>(loaded.bounds().diagonal());
        const rad::PreparedScene prepared(std::move(loaded), {1e9, 100'000'000}, rad::DeviceChoice{o.device});
        const rad::Mesh& mesh = prepared.mesh();
        rad::ComputeContext& compute = prepared.compute();
        const Rays rays = makeRays(mesh, o, lift);
        const std::size_t n = rays.origins.size();

        // Ours: probe_trace over every ray.
        using rad::DeviceArray;
        const auto origins = DeviceArray<rad_float4>::upload(compute, rays.origins, "ray origins");
        const auto directions = DeviceArray<rad_float4>::upload(compute, rays.directions, "ray directions");
        const auto faces = DeviceArray<rad_int>::allocate(compute, n, "hit faces", rad::DeviceAccess::write);
        const auto hits = DeviceArray<rad_float4>::allocate(compute, n, "hits", rad::DeviceAccess::write);
        auto kernel = prepared.device().kernel<rad::ProbeTraceArgs>("probes.cl", "probe_trace");
        rad::ProbeTraceArgs args;
        args.origins = origins;
        args.directions = directions;
        args.hitFaces = faces;
        args.hits = hits;
        args.count = static_cast<rad_uint>(n);
        std::vector<double> ours, embree1, embree16;
        for (int repeat = -1; repeat < o.repeats; ++repeat) {
            rad::Stopwatch clock;
            kernel.launch(args, n);
            compute.finish();
            if (repeat >= 0) ours.push_back(n / clock.seconds());
        }
        const std::vector<rad_int> ourFaces = faces.read();
        const std::vector<rad_float4> ourHits = hits.read();

        const EmbreeScene embree(mesh);
        std::vector<int> faces1(n), faces16(n);
        std::vector<float> t1(n), t16(n);
        for (int repeat = -1; repeat < o.repeats; ++repeat) {
            rad::Stopwatch clock;
            onThreads(n, o.threads, [&](std::size_t first, std::size_t count) {
                embree.trace1(rays, first, count, faces1.data(), t1.data());
            });
            if (repeat >= 0) embree1.push_back(n / clock.seconds());
            clock = rad::Stopwatch();
            onThreads(n, o.threads, [&](std::size_t first, std::size_t count) {
                embree.trace16(rays, first, count, faces16.data(), t16.data());
            });
            if (repeat >= 0) embree16.push_back(n / clock.seconds());
        }
        std::size_t agree = 0, sameFace = 0, packetsAgree = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const int ours_ = ourFaces[i];
            const float ourT = ours_ < 0 ? std::numeric_limits<float>::infinity() : ourHits[i].s[0];
            sameFace += ours_ == faces1[i];
            agree += ours_ == faces1[i] || (ours_ >= 0 && faces1[i] >= 0 && std::fabs(ourT - t1[i]) <= 1e-4f * t1[i]);
            packetsAgree += faces16[i] == faces1[i];
        }
        const double oursRate = median(ours), embreeRate = median(embree1), packetRate = median(embree16);
        std::printf(
            "scene,triangles,rays,shooters,threads,device,ours_rays_per_s,embree1_rays_per_s,"
            "embree16_rays_per_s,ratio_to_embree1,ratio_to_embree16,same_face,agree,packets_agree\n");
        std::printf("%s,%zu,%zu,%u,%u,%s,%.4g,%.4g,%.4g,%.3f,%.3f,%.6f,%.6f,%.6f\n", o.scene.c_str(), mesh.faces.size(),
                    n, o.shooters, o.threads, compute.description().name.c_str(), oursRate, embreeRate, packetRate,
                    oursRate / embreeRate, oursRate / packetRate, double(sameFace) / n, double(agree) / n,
                    double(packetsAgree) / n);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_embree_compare: %s\n", e.what());
        return 1;
    }
    return 0;
}
