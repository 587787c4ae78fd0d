#pragma once
// Small helpers the benchmarks share.

#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "mesh/mesh.h"
#include "scene/scene.h"

namespace rad::bench {

// The patch size that gives about `target` patches (the count falls as the size grows).
inline double patchSizeForAbout(const Scene& scene, std::size_t target) {
    double lo = 1e-4 * scene.bounds().diagonal(), hi = scene.bounds().diagonal();
    for (int i = 0; i < 40; ++i) {
        const double mid = std::sqrt(lo * hi);
        const std::size_t n = buildMesh(scene, {mid, 100'000'000}).patches.size();
        (n > target ? lo : hi) = mid;
    }
    return hi;
}

// A scene whose triangles are the mesh's patches, one surface per original surface side.
inline Scene tessellated(const Scene& scene, const Mesh& mesh) {
    Scene out;
    out.path = scene.path;
    out.materials = scene.materials;
    for (const MeshSurface& side : mesh.surfaces) {
        if (side.back) continue;
        Surface s;
        s.name = side.name;
        for (std::uint32_t k = 0; k < side.patchCount; ++k) {
            const Patch& p = mesh.patches[side.firstPatch + k];
            const auto base = static_cast<std::uint32_t>(s.positions.size());
            s.positions.insert(s.positions.end(), p.p.begin(), p.p.end());
            s.triangles.push_back({base, base + 1, base + 2});
            s.triangleMaterial.push_back(p.material);
        }
        out.surfaces.push_back(std::move(s));
    }
    return out;
}

inline double peakMemoryMiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.0;  // Linux reports KiB
}

// Seconds of CPU time (user + system) this process has used on all its threads: with the
// wall time it splits a parallel run's loss into work that grew and threads that waited.
inline double cpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

inline const char* threadsSetting() {
    const char* threads = std::getenv("POCL_MAX_PTHREAD_COUNT");
    return threads ? threads : "default";
}

// "--name value" argument parsing for the benchmarks: returns the value after `i`.
inline std::string nextArgument(int argc, char** argv, int& i) {
    if (i + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", argv[i]);
        std::exit(2);
    }
    return argv[++i];
}

}  // namespace rad::bench
