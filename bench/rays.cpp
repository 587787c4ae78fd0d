// Rays per second of the shoot kernel: cosine-distributed rays from shooter patches through the
// BVH, closest hit, one count per ray. Prints one line of CSV per configuration.
//
//   bench_rays [--scene FILE] [--patches N | --patch-size L] [--tessellate] [--shooters K]
//              [--rays R] [--repeats M] [--device D]
//
// --patches sets the patch size so the mesh has about N patches (default 16000), by a search
// that builds meshes of other sizes on the way (and so raises the peak memory); --patch-size L
// takes the patch size as it is. With
// --tessellate the patches themselves become the traced faces, so the BVH holds N faces
// instead of the scene's own (32 for the Cornell box): the case ../shared/NOTES measured.
// Run it under POCL_MAX_PTHREAD_COUNT=1 and =2 for per-core figures (bench/rays.sh does).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_support.h"
#include "cl/device_array.h"
#include "formfactor/ray_shooter.h"
#include "prepared/prepared_scene.h"
#include "scene/gltf_loader.h"
#include "shared_math.h"
#include "util/stopwatch.h"

namespace {

struct Options {
    std::string scene = "scenes/cornell-box.gltf";
    std::size_t patches = 16000;
    double patchSize = 0.0;  // > 0: used as it is, instead of searching for `patches`
    bool tessellate = false;
    std::uint32_t shooters = 64;
    std::uint32_t rays = 65536;
    int repeats = 5;
    std::string device;
};

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&] { return rad::bench::nextArgument(argc, argv, i); };
        if (a == "--scene") o.scene = next();
        else if (a == "--patches") o.patches = std::stoul(next());
        else if (a == "--patch-size") o.patchSize = std::stod(next());
        else if (a == "--tessellate") o.tessellate = true;
        else if (a == "--shooters") o.shooters = static_cast<std::uint32_t>(std::stoul(next()));
        else if (a == "--rays") o.rays = static_cast<std::uint32_t>(std::stoul(next()));
        else if (a == "--repeats") o.repeats = std::stoi(next());
        else if (a == "--device") o.device = next();
        else {
            std::fprintf(stderr, "bench_rays: unknown option %s\n", a.c_str());
            std::exit(2);
        }
    }
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    try {
        rad::Scene loaded = rad::loadGltf(o.scene);
        double patchSize = o.patchSize > 0.0 ? o.patchSize : rad::bench::patchSizeForAbout(loaded, o.patches);
        if (o.tessellate) {
            loaded = rad::bench::tessellated(loaded, rad::buildMesh(loaded, {patchSize, 100'000'000}));
            patchSize = 1e9;
        }
        const rad::PreparedScene prepared(std::move(loaded), {patchSize, 100'000'000}, rad::DeviceChoice{o.device});
        const rad::Mesh& mesh = prepared.mesh();
        const rad::WideBvh& bvh = prepared.bvh();
        const double bvhSeconds = prepared.bvhSeconds();
        rad::ComputeContext& compute = prepared.compute();
        rad::RayShooter shooter(compute, prepared.device());

        // Shooters spread evenly over the patch list; one row each.
        std::vector<rad::RayRequest> requests;
        for (std::uint32_t k = 0; k < o.shooters; ++k) {
            rad::RayRequest r;
            r.firstTriangle = static_cast<std::uint32_t>((static_cast<std::uint64_t>(k) * mesh.patches.size()) / o.shooters);
            r.rays = o.rays;
            r.scramble = rad_hash(k);
            r.row = k;
            requests.push_back(r);
        }
        const auto launches = rad::planLaunches(requests, rad::RayShooter::kMaxRaysPerLaunch);
        std::vector<rad_uint> zeros(std::size_t{o.shooters} * shooter.columns(), 0);
        auto counts = rad::DeviceArray<rad_uint>::upload(compute, zeros, "hit counts", rad::DeviceAccess::readWrite);
        std::vector<double> rate;
        for (int repeat = -1; repeat < o.repeats; ++repeat) {  // the first run warms up, untimed
            rad::Stopwatch clock;
            shooter.countHits(launches, counts);
            compute.finish();
            if (repeat >= 0) rate.push_back(double(o.shooters) * o.rays / clock.seconds());
        }
        std::sort(rate.begin(), rate.end());
        std::printf("scene,faces,patches,bvh_nodes,bvh_build_s,device,threads,rays,median_rays_per_s,min,max,peak_rss_mib\n");
        std::printf("%s,%zu,%zu,%zu,%.3f,%s,%s,%llu,%.4g,%.4g,%.4g,%.1f\n", o.scene.c_str(), mesh.faces.size(),
                    mesh.patches.size(), bvh.nodes.size(), bvhSeconds, compute.description().name.c_str(),
                    rad::bench::threadsSetting(), static_cast<unsigned long long>(o.shooters) * o.rays,
                    rate[rate.size() / 2], rate.front(), rate.back(), rad::bench::peakMemoryMiB());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_rays: %s\n", e.what());
        return 1;
    }
    return 0;
}
