// How many bounces are enough? Jacobi with K bounces (E + rho F E + ... + (rho F)^K E) against
// the converged solution of the same matrix (Gauss-Seidel to 1e-10), for K = 1 .. 10: the
// relative RMS error (green channel) of per-patch radiosity over lit, non-emitting patches,
// area-weighted, and of the non-emitting surfaces' means, and the share of the emitted power
// still in flight. One CSV line per K.
//
//   bench_bounces [--scene FILE] [--patch-size L] [--rays-per-patch N] [--device D]

#include <cmath>
#include <cstdio>
#include <string>

#include "bench_support.h"
#include "prepared/prepared_scene.h"
#include "formfactor/patch_matrix.h"
#include "scene/gltf_loader.h"
#include "solver/matrix_solvers.h"
#include "solver/progressive_solver.h"
#include "solver/surface_means.h"
#include "util/stopwatch.h"

int main(int argc, char** argv) {
    std::string scenePath = "scenes/cornell-box.gltf", device;
    double patchSize = 0.05;
    rad::OptionValues options{{"--rays-per-patch", 20000}};
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&] { return rad::bench::nextArgument(argc, argv, i); };
        if (a == "--scene") scenePath = next();
        else if (a == "--patch-size") patchSize = std::stod(next());
        else if (a == "--rays-per-patch") options.setNumber("--rays-per-patch", std::stod(next()));
        else if (a == "--device") device = next();
        else {
            std::fprintf(stderr, "bench_bounces: unknown option %s\n", a.c_str());
            return 2;
        }
    }
    try {
        const rad::PreparedScene scene(rad::loadGltf(scenePath), {patchSize, 100'000'000}, rad::DeviceChoice{device});
        const rad::Mesh& mesh = scene.mesh();
        const rad::PatchMatrix matrix = rad::buildPatchMatrix(scene, "shoot", options, 1);
        std::vector<glm::dvec3> e, rho;
        std::vector<double> area;
        for (std::size_t p = 0; p < scene.patches().size(); ++p) {
            e.emplace_back(scene.patches().exitance(p));
            rho.emplace_back(scene.patches().reflectance[p]);
            area.push_back(scene.patches().area[p]);
        }
        rad::MatrixSolveOptions converged;
        converged.tolerance = 1e-10;
        const auto reference = rad::solveMatrix(matrix, e, rho, area, converged);
        std::printf("scene,patches,bounces,patch_rms_error,surface_rms_error,unshot_fraction,seconds\n");
        for (int k = 1; k <= 10; ++k) {
            rad::MatrixSolveOptions o;
            o.solver = rad::MatrixSolver::Jacobi;
            o.bounces = k;
            rad::Stopwatch clock;
            const auto r = rad::solveMatrix(matrix, e, rho, area, o);
            const double seconds = clock.seconds();
            double num = 0.0, den = 0.0;
            for (std::size_t p = 0; p < area.size(); ++p) {
                if (e[p].x + e[p].y + e[p].z > 0.0 || reference.radiosity[p].y <= 0.0) continue;
                const double d = r.radiosity[p].y - reference.radiosity[p].y;
                num += area[p] * d * d;
                den += area[p] * reference.radiosity[p].y * reference.radiosity[p].y;
            }
            std::vector<glm::vec3> b, ref;
            for (const auto& v : r.radiosity) b.emplace_back(v);
            for (const auto& v : reference.radiosity) ref.emplace_back(v);
            const rad::ElementMesh perPatch = rad::ElementMesh::uniform(mesh, 0.0);
            const auto sm = rad::surfaceMeans(mesh, perPatch, b), rm = rad::surfaceMeans(mesh, perPatch, ref);
            double snum = 0.0, sden = 0.0;
            for (std::size_t s = 0; s < sm.size(); ++s) {
                const rad::MeshSurface& surface = mesh.surfaces[s];
                if (e[surface.firstPatch].x + e[surface.firstPatch].y + e[surface.firstPatch].z > 0.0) continue;  // emitters
                snum += (sm[s].y - rm[s].y) * (sm[s].y - rm[s].y);
                sden += rm[s].y * rm[s].y;
            }
            const double unshot = (r.energy.unshot.x + r.energy.unshot.y + r.energy.unshot.z) /
                                  (r.energy.emitted.x + r.energy.emitted.y + r.energy.emitted.z);
            std::printf("%s,%zu,%d,%.4g,%.4g,%.4g,%.4f\n", scenePath.c_str(), mesh.patches.size(), k,
                        std::sqrt(num / den), std::sqrt(snum / sden), unshot, seconds);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_bounces: %s\n", e.what());
        return 1;
    }
    return 0;
}
