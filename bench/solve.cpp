// A whole progressive solve of a scene at about N patches to a tolerance: seconds, shots,
// batches, rays, rays per second, device time per kernel and the share of the solve spent in
// kernels (the rest is launching, transfers and waiting), the CPU time the solve took on all
// threads, and peak memory. One CSV line.
//
//   bench_solve [--scene FILE] [--patches N] [--rays R] [--tolerance T] [--batch K]
//               [--ratio X] [--min-rays M] [--counters L] [--seed S] [--device D]
//
// --counters: how the rays add into the delivered-power counters (formfactor/counter_layout.h):
// one-set (a work item per ray, as on GPUs), shared (a work group per compute unit taking rays,
// all adding into one set), per-thread (the same, a set each), or device (the default: the
// device's choice: per-thread on PoCL's CPU device, one-set elsewhere).

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "bench_support.h"
#include "prepared/prepared_scene.h"
#include "scene/gltf_loader.h"
#include "solver/progressive_solver.h"

int main(int argc, char** argv) {
    std::string scenePath = "scenes/cornell-box.gltf", device, counters = "device";
    std::size_t patches = 16000;
    rad::ProgressiveOptions options;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&] { return rad::bench::nextArgument(argc, argv, i); };
        if (a == "--scene") scenePath = next();
        else if (a == "--patches") patches = std::stoul(next());
        else if (a == "--rays") options.rays = static_cast<std::uint64_t>(std::stod(next()));
        else if (a == "--tolerance") options.tolerance = std::stod(next());
        else if (a == "--batch") options.maxShootersPerBatch = static_cast<std::uint32_t>(std::stoul(next()));
        else if (a == "--ratio") options.batchPowerRatio = std::stod(next());
        else if (a == "--min-rays") options.minRays = static_cast<std::uint32_t>(std::stoul(next()));
        else if (a == "--counters") counters = next();
        else if (a == "--seed") options.seed = static_cast<std::uint32_t>(std::stoul(next()));
        else if (a == "--device") device = next();
        else {
            std::fprintf(stderr, "bench_solve: unknown option %s\n", a.c_str());
            return 2;
        }
    }
    try {
        rad::Scene loaded = rad::loadGltf(scenePath);
        const double patchSize = rad::bench::patchSizeForAbout(loaded, patches);
        const rad::PreparedScene scene(std::move(loaded), {patchSize, 100'000'000}, rad::DeviceChoice{device, true});
        const rad::Mesh& mesh = scene.mesh();
        const rad::ElementMesh elements = rad::ElementMesh::uniform(mesh, 0.0);
        const unsigned threads = std::max(1u, scene.compute().description().computeUnits);
        if (counters == "one-set") options.counters = rad::CounterLayout{0, 1};
        else if (counters == "shared") options.counters = rad::CounterLayout{threads, 1};
        else if (counters == "per-thread") options.counters = rad::CounterLayout{threads, threads};
        else if (counters != "device") throw std::invalid_argument("--counters: one-set, shared, per-thread or device");
        rad::ProgressiveSolver solver(scene, elements);
        {
            rad::ProgressiveOptions warm = options;  // builds and caches the programs
            warm.maxShots = 1;
            solver.solve(warm);
        }
        const double cpuBefore = rad::bench::cpuSeconds();
        const rad::ProgressiveResult r = solver.solve(options);
        const double cpu = rad::bench::cpuSeconds() - cpuBefore;
        double kernels = 0.0;
        for (const auto& [name, seconds] : r.kernelSeconds) kernels += seconds;
        auto seconds = [&](const char* name) {
            const auto found = r.kernelSeconds.find(name);
            return found == r.kernelSeconds.end() ? 0.0 : found->second;
        };
        std::printf(
            "scene,patches,device,threads,rays_option,batch,shots,batches,rays,unshot,solve_s,rays_per_s,"
            "shoot_s,take_s,gather_s,prepare_s,kernel_share,cpu_s,takers,sets,peak_rss_mib\n");
        std::printf("%s,%zu,%s,%s,%llu,%u,%llu,%llu,%llu,%.3g,%.3f,%.4g,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%u,%u,%.1f\n",
                    scenePath.c_str(), mesh.patches.size(), scene.compute().description().name.c_str(),
                    rad::bench::threadsSetting(), static_cast<unsigned long long>(options.rays),
                    options.maxShootersPerBatch, static_cast<unsigned long long>(r.tallies.shots),
                    static_cast<unsigned long long>(r.tallies.batches), static_cast<unsigned long long>(r.tallies.rays),
                    r.unshotFraction, r.seconds, r.tallies.rays / r.seconds, seconds("shoot_power"), seconds("take_shots"),
                    seconds("gather"), seconds("prepare_shooters"), kernels / r.seconds, cpu, r.counters.takers,
                    r.counters.sets, rad::bench::peakMemoryMiB());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_solve: %s\n", e.what());
        return 1;
    }
    return 0;
}
