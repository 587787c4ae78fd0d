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
    viewfactors->add_option("--rays", vf.rays, "rays cast from each surface in all, spread over it by area")
        ->capture_default_str()
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{0xFFFFFFFFull}));
    viewfactors->add_option("--patch-size", vf.patchSize, "longest patch edge in metres (default: 1/32 of the scene's diagonal)")
        ->check(positive);
    viewfactors->add_option("--seed", vf.seed, "seed of the sample sequences; the same seed gives the same numbers")
        ->capture_default_str();
    viewfactors->add_option("--device", vf.device, "OpenCL device: index, cpu, gpu, or part of its name (see 'devices')");
    viewfactors->add_option("--output", vf.output, "write the CSV to this file instead of standard output");
    viewfactors->add_option("--max-patches", vf.maxPatches, "refuse meshes with more patches than this")
        ->capture_default_str();

    rad::SolveArgs sv;
    CLI::App* solve = app.add_subcommand(
        "solve", "Light the scene by progressive radiosity; write render.exr, render.png, lit.glb, report.json.");
    solve->add_option("SCENE", sv.scene, "glTF scene (.gltf or .glb)")->required();
    solve->add_option("--output", sv.output, "directory for the outputs")->capture_default_str();
    solve->add_option("--patch-size", sv.patchSize, "longest patch edge in metres (default: 1/32 of the scene's diagonal)")
        ->check(positive);
    solve->add_option("--rays", sv.rays,
                      "rays for a shot of all the emitted power; each shot casts rays in proportion to its power")
        ->capture_default_str()
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 40));
    solve->add_option("--min-rays", sv.minRays, "rays of the weakest shots")
        ->capture_default_str()
        ->check(CLI::Range(std::uint32_t{1}, std::uint32_t{1} << 30));
    solve->add_option("--tolerance", sv.tolerance, "stop when unshot / emitted power falls below this")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    solve->add_option("--max-shots", sv.maxShots, "stop after this many shots (0: no limit)")->capture_default_str();
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
    solve->add_option("--max-patches", sv.maxPatches, "refuse meshes with more patches than this")->capture_default_str();
    solve->add_flag("--quiet", sv.quiet, "no progress display");

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
