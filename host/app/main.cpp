// radiosity: the command line. Parses, calls one subcommand, and turns errors into one line on
// stderr and an exit status: 0 success, 1 runtime or device failure, 2 bad input or usage.

#include <cmath>
#include <cstdio>
#include <new>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "util/error.h"

namespace {

constexpr const char* kExitCodes =
    "Exit status: 0 success; 1 runtime or device failure; 2 bad input or usage.";

int fail(int status, const char* what) {
    std::fprintf(stderr, "radiosity: error: %s\n", what);
    return status;
}


// CLI11's own PositiveNumber prints the whole range of double when it fails.
const CLI::Validator positive(
    [](const std::string& text) {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value) || !(value > 0.0) || !std::isfinite(value))
            return std::string("must be a positive number");
        return std::string();
    },
    "POSITIVE");

// Adds an option for a whole number that may be written 16000000, 16e6 or 1.6e7.
template <typename T>
CLI::Option* addCount(CLI::App* app, const std::string& name, T& value, const std::string& help, double min, double max) {
    return app
        ->add_option_function<double>(
            name,
            [&value, name, min, max](const double& v) {
                if (!(v >= min && v <= max) || std::floor(v) != v) {
                    char range[96];
                    std::snprintf(range, sizeof range, "must be a whole number from %.0f to %.0f", min, max);
                    throw CLI::ValidationError(name, range);
                }
                value = static_cast<T>(v);
            },
            help)
        ->type_name("N")
        ->default_str(std::to_string(value));
}

// Bytes, with an optional binary suffix: 4G, 512M, 1048576.
CLI::Option* addBytes(CLI::App* app, const std::string& name, std::uint64_t& value, const std::string& help) {
    return app
        ->add_option_function<std::string>(
            name,
            [&value, name](const std::string& text) {
                std::size_t used = 0;
                double number = 0.0;
                try {
                    number = std::stod(text, &used);
                } catch (const std::exception&) {
                    throw CLI::ValidationError(name, "must be a size such as 4G, 512M or 1048576");
                }
                const std::string suffix = text.substr(used);
                const double scale = suffix.empty() ? 1.0
                                     : suffix == "K" || suffix == "k" ? 1024.0
                                     : suffix == "M" || suffix == "m" ? 1048576.0
                                     : suffix == "G" || suffix == "g" ? 1073741824.0
                                     : suffix == "T" || suffix == "t" ? 1099511627776.0
                                                                      : -1.0;
                if (scale < 0 || !(number > 0) || number * scale > 1.8e19)
                    throw CLI::ValidationError(name, "must be a size such as 4G, 512M or 1048576");
                value = static_cast<std::uint64_t>(number * scale);
            },
            help)
        ->type_name("SIZE")
        ->default_str("4G");
}

// The form-factor estimator's options, shared by viewfactors and solve.
void addMethodOptions(CLI::App* app, rad::MethodArgs& m) {
    app->add_option("--method", m.method, "form factors by: shoot (rays), hemicube, gather (point-to-polygon + shadow rays)")
        ->capture_default_str()
        ->check(CLI::IsMember({"shoot", "hemicube", "gather"}));
    addCount(app, "--rays-per-patch", m.raysPerPatch, "shoot: rays per patch when a whole patch matrix is built", 1,
             4294967295.0);
    addCount(app, "--hemicube-res", m.hemicubeResolution, "hemicube: pixels along the top face's edge (even)", 2, 8192);
    app->add_flag("--hemicube-jitter", m.hemicubeJitter, "hemicube: turn each cube by a random angle about the normal");
    addCount(app, "--shadow-rays", m.shadowRays, "gather: shadow rays per receiver point", 1, 65536);
    addBytes(app, "--max-memory", m.maxMemory, "refuse a form-factor matrix (or direct solve) larger than this");
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Radiosity and view factors for glTF scenes, computed on OpenCL devices."};
    app.footer(kExitCodes);
    app.require_subcommand(1);

    app.add_subcommand("devices", "List the OpenCL platforms and devices, with the index --device takes.");

    rad::ViewFactorArgs vf;
    CLI::App* viewfactors = app.add_subcommand(
        "viewfactors", "Surface-to-surface view factors by ray shooting, as CSV: from,to,F,stderr.");
    viewfactors->add_option("SCENE", vf.scene, "glTF scene (.gltf or .glb)")->required();
    addCount(viewfactors, "--rays", vf.rays, "rays cast from each surface in all, spread over it by area", 1, 4294967295.0);
    viewfactors->add_option("--patch-size", vf.patchSize, "longest patch edge in metres (default: 1/32 of the scene's diagonal)")
        ->check(positive);
    viewfactors->add_option("--seed", vf.seed, "seed of the sample sequences; the same seed gives the same numbers")
        ->capture_default_str();
    viewfactors->add_option("--device", vf.device, "OpenCL device: index, cpu, gpu, or part of its name (see 'devices')");
    viewfactors->add_option("--output", vf.output, "write the CSV to this file instead of standard output");
    addCount(viewfactors, "--max-patches", vf.maxPatches, "refuse meshes with more patches than this", 1, 1e12);
    addMethodOptions(viewfactors, vf.method);
    viewfactors->add_option("--level", vf.level, "surface-to-surface or patch-to-patch factors")
        ->capture_default_str()
        ->check(CLI::IsMember({"surface", "patch"}));
    viewfactors->add_option("--format", vf.format, "csv (from,to,F,stderr) or mtx (Matrix Market)")
        ->capture_default_str()
        ->check(CLI::IsMember({"csv", "mtx"}));
    viewfactors->add_option("--enforce", vf.enforce,
                            "correct the estimates: reciprocity (A_i F_ij = A_j F_ji), closure (closed rows sum to 1), both")
        ->capture_default_str()
        ->check(CLI::IsMember({"none", "reciprocity", "closure", "both"}));

    rad::SolveArgs sv;
    CLI::App* solve = app.add_subcommand(
        "solve", "Light the scene by progressive radiosity; write render.exr, render.png, lit.glb, report.json.");
    solve->add_option("SCENE", sv.scene, "glTF scene (.gltf or .glb)")->required();
    solve->add_option("--output", sv.output, "directory for the outputs")->capture_default_str();
    solve->add_option("--patch-size", sv.patchSize, "longest patch edge in metres (default: 1/32 of the scene's diagonal)")
        ->check(positive);
    addCount(solve, "--rays", sv.rays,
             "rays for a shot of all the emitted power; each shot casts rays in proportion to its power", 1, 1099511627776.0);
    addCount(solve, "--min-rays", sv.minRays, "rays of the weakest shots", 1, 1073741824.0);
    solve->add_option("--tolerance", sv.tolerance, "stop when unshot / emitted power falls below this")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    addCount(solve, "--max-shots", sv.maxShots, "stop after this many shots (0: no limit)", 0, 1e15);
    solve->add_option("--time-limit", sv.timeLimit, "stop after this many seconds of solving (0: no limit)")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1e9));
    solve->add_option("--seed", sv.seed, "seed of the sample sequences; the same seed gives the same numbers")
        ->capture_default_str();
    solve->add_option("--device", sv.device, "OpenCL device: index, cpu, gpu, or part of its name (see 'devices')");
    solve->add_option("--camera", sv.camera, "render from the camera of this name (default: the scene's first)");
    solve->add_option("--width", sv.width, "image width in pixels")->capture_default_str()->check(CLI::Range(1, 16384));
    solve->add_option("--height", sv.height, "image height in pixels")->capture_default_str()->check(CLI::Range(1, 16384));
    solve->add_option("--samples", sv.samplesPerSide, "samples per pixel along each side (n x n per pixel)")
        ->capture_default_str()
        ->check(CLI::Range(1, 16));
    addCount(solve, "--max-patches", sv.maxPatches, "refuse meshes with more patches than this", 1, 1e12);
    solve->add_flag("--quiet", sv.quiet, "no progress display");
    addMethodOptions(solve, sv.method);
    solve->add_option("--solver", sv.solver,
                      "progressive (default; with --method shoot it runs on the device), or on the whole matrix: "
                      "jacobi, gauss-seidel, direct")
        ->capture_default_str()
        ->check(CLI::IsMember({"progressive", "jacobi", "gauss-seidel", "direct"}));
    addCount(solve, "--bounces", sv.bounces, "jacobi: stop after this many bounces (1: direct light only; 0: to --residual)",
             0, 1e6);
    solve->add_option("--residual", sv.residual, "jacobi, gauss-seidel: stop when the residual falls below this")
        ->capture_default_str()
        ->check(positive);
    solve->add_option("--element-size", sv.elementSize,
                      "receivers finer than shooters: longest element edge in metres (default: one element per patch)")
        ->check(positive);
    solve->add_flag("--adaptive", sv.adaptive,
                    "split elements where the light bends across them (shadow edges, penumbrae) before the final solve");
    solve->add_option("--refine-threshold", sv.refineThreshold,
                      "adaptive: split elements where linear shading misses the light by more than this fraction of its level")
        ->capture_default_str()
        ->check(positive);
    solve->add_option("--min-element-size", sv.minElementSize, "adaptive: never split below this edge (default: patch size / 16)")
        ->check(positive);
    addCount(solve, "--max-elements", sv.maxElements, "adaptive: stop splitting at this many elements", 1, 1e12);
    addCount(solve, "--refine-passes", sv.refinePasses,
             "adaptive: at most this many passes by direct light (then one by a provisional solve)", 1, 64);
    solve->add_flag("--debug-mesh", sv.debugMesh, "also write render-mesh.png, the image with the elements' edges");
    solve->add_flag("--element-csv", sv.elementCsv,
                    "also write elements.csv: per element its surface, centroid, normal, area, reflectance and radiosity");
    solve->add_option("--checkpoint", sv.checkpoint,
                      "save the solver's state to this file now and then, and when the solve stops");
    solve->add_option("--checkpoint-every", sv.checkpointEvery, "seconds between checkpoints")
        ->capture_default_str()
        ->check(positive);
    solve->add_option("--resume", sv.resume,
                      "continue from a checkpoint of the same scene and options (same seed: bitwise the same result)");

    rad::PathTraceArgs pt;
    rad::addPathTraceCommand(app, pt);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "radiosity: error: %s (see --help)\n", e.what());
        return 2;
    }

    try {
        if (app.got_subcommand("devices")) rad::runDevices();
        if (app.got_subcommand("viewfactors")) rad::runViewFactors(vf);
        if (app.got_subcommand("solve")) rad::runSolve(sv);
        if (app.got_subcommand("pathtrace")) rad::runPathTrace(pt);
    } catch (const rad::InputError& e) {
        return fail(2, e.what());
    } catch (const rad::Error& e) {
        return fail(1, e.what());
    } catch (const std::bad_alloc&) {
        return fail(1, "out of memory");
    } catch (const std::exception& e) {
        return fail(1, e.what());
    }
    return 0;
}
