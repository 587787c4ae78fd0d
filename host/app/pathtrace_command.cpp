// radiosity pathtrace: the reference image of a scene by unbiased path tracing
// (render/path_tracer.h), written to an EXR. Its options are declared here rather than in
// main.cpp, so the command stays in one file.

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "app/console.h"
#include "io/image_files.h"
#include "prepared/prepared_scene.h"
#include "render/path_tracer.h"
#include "render/view.h"
#include "scene/scene_files.h"
#include "util/error.h"
#include "util/stopwatch.h"

namespace rad {
namespace {

// Fails before the work when the output cannot be written; makes its directory.
void prepareOutput(const std::string& path) {
    const std::filesystem::path file(path);
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) throw InputError("--output " + path + ": is a directory");
    if (file.has_parent_path()) {
        std::filesystem::create_directories(file.parent_path(), ec);
        if (ec) throw RuntimeFailure("--output " + path + ": cannot create its directory: " + ec.message());
    }
}

}  // namespace

CLI::App* addPathTraceCommand(CLI::App& app, PathTraceArgs& args) {
    CLI::App* cmd = app.add_subcommand("pathtrace",
                                       "Reference image by unbiased path tracing (independent of patches), as an EXR.");
    DeclaredOptions options(cmd);
    addSceneFileOptions(options, args.scene);
    addLightingOptions(options, args.lighting);
    options.bind(OptionSpec::text("--output", "the EXR file to write", "out/pathtrace.exr"), args.output);
    options.bind(OptionSpec::text("--camera", "render from the camera of this name (default: the scene's first)"),
                 args.camera);
    options.bind(OptionSpec::count("--width", "image width in pixels", 256, 1, 16384), args.width);
    options.bind(OptionSpec::count("--height", "image height in pixels", 256, 1, 16384), args.height);
    options.bind(OptionSpec::count("--samples", "paths per pixel (with --noise, the most)", 64, 1, 1u << 30),
                 args.samples);
    options.bind(OptionSpec::fraction("--noise",
                                      "stop sooner, once the image's noise (the root of the pixels' mean variance over "
                                      "their mean luminance, measured from the samples) is at most this; 0: never",
                                      0.0, 0.0, 1.0),
                 args.noise);
    options.bind(OptionSpec::count("--max-bounces",
                                   "most reflections per path (1: direct light only; 0: no limit, Russian roulette "
                                   "ends paths)",
                                   0, 0, 4096),
                 args.maxBounces);
    options.bind(OptionSpec::count("--seed", "seed of the sample sequences; the same seed gives the same image", 1, 0,
                                   4294967295.0),
                 args.seed);
    options.bind(OptionSpec::flag("--no-light-sampling",
                                  "find emitting surfaces' light only where paths hit them (no shadow rays to them): "
                                  "the same image in the mean, noisier"),
                 args.noLightSampling);
    options.bind(OptionSpec::text("--device", "OpenCL device: index, cpu, gpu, or part of its name (see 'devices')"),
                 args.device);
    return cmd;
}

void runPathTrace(const PathTraceArgs& args) {
    Stopwatch clock;
    Scene loaded = loadScene(args.scene);
    applyLighting(args.lighting, loaded);
    printWarnings(loaded);
    if (!loaded.anyEmitter()) refuseUnlitScene(args.scene.name(), "the image would be black");
    const View view = chooseView(loaded, args.camera);  // a bad camera name fails before the work
    prepareOutput(args.output);

    // The path tracer reads faces, not patches: one patch per face keeps the device's tables small.
    const double wholeFace = 2.0 * std::max(loaded.bounds().diagonal(), 1e-30);
    const PreparedScene scene(std::move(loaded), {wholeFace, 1'000'000'000}, DeviceChoice{args.device});

    PathTraceOptions options;
    options.width = args.width;
    options.height = args.height;
    options.samples = args.samples;
    options.noise = args.noise;
    options.maxBounces = args.maxBounces;
    options.seed = args.seed;
    options.lightSampling = !args.noLightSampling;
    Stopwatch traceClock;
    const PathTraceResult result = pathTrace(scene, view, options);
    const double traceSeconds = traceClock.seconds();
    writeExr(args.output, result.image);
    std::fprintf(stderr,
                 "pathtrace: %d x %d, %u paths per pixel (noise %.3g), %llu rays in %.2f s (%.3g rays/s) on %s; %.2f s "
                 "in all; wrote %s\n",
                 args.width, args.height, result.samples, result.noise, static_cast<unsigned long long>(result.rays),
                 traceSeconds,
                 traceSeconds > 0 ? static_cast<double>(result.rays) / traceSeconds : 0.0,
                 scene.compute().description().name.c_str(), clock.seconds(), args.output.c_str());
}

}  // namespace rad
