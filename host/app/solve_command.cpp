// radiosity solve: prepare the scene, solve it by the strategy the method and solver choose
// (solver/solve_strategy.h), render the view, write the outputs, report. Each stage is one
// function below; none knows how the others work.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include <unistd.h>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "app/console.h"
#include "app/interrupt.h"
#include "app/progress.h"
#include "formfactor/estimator.h"
#include "io/atomic_file.h"
#include "io/baked_gltf.h"
#include "io/checkpoint.h"
#include "io/element_csv.h"
#include "io/image_files.h"
#include "io/lightmapped_gltf.h"
#include "io/solve_report.h"
#include "io/vtu_file.h"
#include "lightmap/lightmap_layout.h"
#include "lightmap/texel_bake.h"
#include "lightmap/texel_fill.h"
#include "device/device_elements.h"
#include "mesh/vertices.h"
#include "parallel/process_group.h"
#include "prepared/prepared_scene.h"
#include "render/renderer.h"
#include "render/view.h"
#include "render/view_pass.h"
#include "render/view_path_inputs.h"
#include "scene/scene_files.h"
#include "shared_math.h"
#include "solver/matrix_solvers.h"
#include "solver/progressive_options.h"
#include "solver/solve_strategy.h"
#include "solver/surface_means.h"
#include "util/error.h"
#include "util/stopwatch.h"

namespace rad {
namespace {

// Checked before the work starts; the directory itself is made only when the outputs are ready.
void checkOutputDirectory(const std::string& dir) {
    std::error_code ec;
    if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
        throw InputError("--output " + dir + ": exists and is not a directory");
}

void makeOutputDirectory(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw RuntimeFailure("--output " + dir + ": cannot create the directory: " + ec.message());
}

struct Prepared {
    std::unique_ptr<PreparedScene> scene;
    View view;
    std::optional<LightmapLayout> lightmap;  // --lightmap: laid out before the solve, to refuse early
};

// This machine's memory, or 0 where it cannot be told.
std::uint64_t physicalMemoryBytes() {
    const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && size > 0 ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(size) : 0;
}

LightmapOptions lightmapOptions(const SolveArgs& args) {
    LightmapOptions options;
    options.texelSize = args.texelSize;
    options.pageSize = args.lightmapSize;
    options.uv = args.lightmapUv == "scene"   ? LightmapOptions::Uv::scene
                 : args.lightmapUv == "atlas" ? LightmapOptions::Uv::atlas
                                              : LightmapOptions::Uv::automatic;
    return options;
}

// Loads and prepares the scene, refusing before any device work what cannot be solved. Every
// rank does this alike (the geometry is replicated), each on its own device.
Prepared prepare(const SolveArgs& args, const ProcessGroup& group, SolveReport& report) {
    Stopwatch stage;
    Scene loaded = loadScene(args.input.scene);
    applyLighting(args.lighting, loaded);
    if (group.root()) printWarnings(loaded);  // every rank reads the same scene: one says so
    report.warnings = loaded.warnings;
    if (!loaded.anyEmitter()) refuseUnlitScene(args.input.scene.name(), "there is nothing to solve");
    const View view = chooseView(loaded, args.camera);  // fail on a bad camera name before the work
    checkOutputDirectory(args.output);
    if (!args.vtu.empty()) {
        checkOutputFile("--vtu", args.vtu, args.output);
        const std::filesystem::path vtu(args.vtu);
        if (vtu.parent_path().lexically_normal() ==
                (std::filesystem::path(args.output) / "x").lexically_normal().parent_path() &&
            vtu.extension() != ".vtu")
            throw InputError("--vtu " + args.vtu + ": in the output folder, name it *.vtu (the other outputs are "
                             "written there)");
    }
    report.seconds.load = stage.seconds();

    auto emitsPower = [&](const PreparedScene& meshed) {
        double emittedPower = 0.0;  // W, all channels: zero when emitters are too small to represent
        const std::vector<glm::vec3> exitance = meshed.patches().exitance();
        for (std::size_t p = 0; p < exitance.size(); ++p)
            emittedPower +=
                static_cast<double>(meshed.patches().area[p]) * (exitance[p].x + exitance[p].y + exitance[p].z);
        for (const auto& emitter : meshed.emitters().list()) {
            if (emitter->delivery() == DirectDelivery::none) continue;  // surfaces: counted as the patches hold them
            const glm::dvec3 power = emitter->power();
            emittedPower += power.x + power.y + power.z;
        }
        if (!(emittedPower > 0.0))
            throw FileError(args.input.scene.name(),
                            "the emitters emit no power in single precision (their area or radiance is too small)");
    };
    auto scene =
        std::make_unique<PreparedScene>(std::move(loaded), MeshOptions{args.input.patchSize, args.input.maxPatches},
                                        DeviceChoice{deviceForRank(args.input.device, group.rank())}, emitsPower);
    report.seconds.mesh = scene->meshSeconds();
    report.seconds.bvh = scene->bvhSeconds() + scene->deviceSeconds();
    std::optional<LightmapLayout> lightmap;
    if (args.lightmap) {
        Stopwatch layoutTime;
        lightmap = layoutLightmap(scene->scene(), scene->mesh(), lightmapOptions(args));
        report.seconds.lightmapLayout = layoutTime.seconds();
        const std::uint64_t need = lightmapHostBytes(*lightmap);
        const std::uint64_t have = physicalMemoryBytes();
        if (have > 0 && need > have / 5 * 4) {
            auto gib = [](std::uint64_t b) { return std::to_string((b + (1ull << 29)) >> 30) + " GiB"; };
            throw InputError(args.input.scene.name() + ": a lightmap of " + std::to_string(lightmap->pages) + " page(s) of " +
                             std::to_string(lightmap->pageSize) + " x " + std::to_string(lightmap->pageSize) +
                             " texels needs about " + gib(need) + " of memory, and this machine has " + gib(have) +
                             ": use a larger --texel-size or a smaller --lightmap-size");
        }
        if (!lightmap->note.empty() && group.root())
            emitWarning(args.input.scene.name() + ": lightmap: " + lightmap->note, &report.warnings);
    }
    return {std::move(scene), view, std::move(lightmap)};
}

// Runs the strategy, with progress on stderr, SIGINT and SIGTERM stopping it between batches
// where the strategy can stop (elsewhere they end the program as usual), and its warnings kept
// for the report. Under mpirun every rank runs it and they share the shots; rank 0 speaks, and
// an interrupt any rank received stops them all at the same batch.
Solution solve(const SolveArgs& args, SolveStrategy& strategy, const PreparedScene& scene, const ProcessGroup& group,
               SolveReport& report) {
    Stopwatch stage;
    if (strategy.stopsWhenInterrupted()) installInterruptHandlers();
    const bool speak = group.root() && !args.quiet;
    ProgressDisplay display(args.values.number(kToleranceOption));
    SolveControl control;
    control.group = &group;
    control.progress = [&](const SolveProgress& p) {
        if (speak) display.update(p);
    };
    control.interrupted = [&group]() { return anyProcess(group, interruptRequested()); };
    control.saveState = writeCheckpoint;
    control.loadState = readCheckpoint;
    control.note = [&](const std::string& line) {
        if (speak) std::fprintf(stderr, "solve: %s\n", line.c_str());
    };
    control.warn = [&](const std::string& warning) {
        if (!group.root()) return;
        display.finish();  // a warning starts its own line, not the progress bar's
        emitWarning(warning, &report.warnings);
    };
    strategy.check(scene, control);
    Solution solution = strategy.solve(scene, control);
    display.finish();
    report.seconds.solve = stage.seconds();
    report.seconds.sumOverRanks = solution.sumSeconds;
    return solution;
}

// The view, and the light per vertex (radiance B / pi) that both the image and lit.glb show;
// and the solution on the device, made once for the camera pass and the lightmap: the element
// trees, and what the sampled modes' paths read (ViewPathInputs), with the indirect light per
// element where either of them takes the direct mode.
struct Rendered {
    MeshVertices vertices;
    std::vector<glm::vec3> radiance;
    std::vector<glm::vec3> irradiance;  // the light arriving at each vertex (textured faces, the sampled modes)
    std::vector<glm::vec3> caustic;     // of it, what came by way of mirrors and glass (empty: not kept apart)
    std::shared_ptr<const DeviceElements> deviceElements;
    std::optional<ViewPathInputs> paths;  // for the sampled modes and the lightmap
    Image image;
    std::optional<Image> meshImage;  // --debug-mesh
};

Rendered render(const SolveArgs& args, const PreparedScene& scene, const Solution& solution, const View& view,
                bool baking, SolveReport& report) {
    Stopwatch stage;
    Rendered out;
    out.deviceElements = scene.device().elements(solution.elements);
    out.vertices = weldVertices(scene.mesh(), solution.elements);
    out.radiance = vertexValues(solution.elements, out.vertices, solution.radiosity);
    for (glm::vec3& r : out.radiance) r /= static_cast<float>(kPi);
    out.irradiance = vertexValues(solution.elements, out.vertices, solution.irradiance);
    if (!solution.causticIrradiance.empty())
        out.caustic = vertexValues(solution.elements, out.vertices, solution.causticIrradiance);
    RenderOptions options{args.width, args.height, args.samples};
    const std::optional<RenderMode> named = renderModeNamed(args.render);
    if (!named) throw InputError("--render " + args.render + ": not a mode (radiosity, direct, final-gather)");
    const RenderMode mode = *named;
    const bool bakeDirect = baking && renderModeNamed(args.lightmapMode) == RenderMode::direct;
    ViewPassOptions pass;
    pass.width = args.width;
    pass.height = args.height;
    pass.samples = static_cast<std::uint32_t>(args.samples);
    pass.noise = args.noise;
    pass.mode = mode;
    pass.seed = args.input.seed;
    pass.indirectRaysPerElement = static_cast<std::uint32_t>(args.gatherRays);
    // The sampled modes' pixel sums first: a device that cannot hold the image refuses before
    // the inputs' gather.
    std::optional<PixelSums> sums;
    if (mode != RenderMode::radiosity) sums.emplace(viewPassSums(scene, pass));
    // The inputs serve the lightmap too; their time counts as the render's.
    if (mode != RenderMode::radiosity || baking)
        out.paths.emplace(scene,
                          ViewPathSolution{solution.elements, *out.deviceElements, out.vertices, solution.irradiance,
                                           out.caustic},
                          mode == RenderMode::direct || bakeDirect, static_cast<std::uint32_t>(args.gatherRays),
                          args.input.seed);
    if (mode == RenderMode::radiosity) {
        out.image = renderView(scene, *out.deviceElements, out.vertices, out.radiance, view, options, &out.irradiance);
    } else {
        PixelEstimate estimate = renderViewPass(scene, *out.paths, view, pass, *sums);
        out.image = std::move(estimate.image);
        report.renderRays = estimate.rays;
        report.samplesTaken = estimate.samples;
        report.imageNoise = estimate.noise;
    }
    report.renderMode = args.render;
    if (args.debugMesh) {
        options.wireframe = true;
        out.meshImage =
            renderView(scene, *out.deviceElements, out.vertices, out.radiance, view, options, &out.irradiance);
    }
    report.seconds.render = stage.seconds();
    return out;
}

// --lightmap: the texels baked, their gutters filled and seams stitched, and what lightmapped.glb
// shows: the radiance over an emissive strength S, sRGB-encoded in 8 bits. Reflected radiance
// is at most E / pi, so S is the brightest E / pi of all but the top 0.1 % of the texels: the
// lit surfaces use the 8 bits' whole range, and what is brighter (emitters) clips.
struct Lightmapped {
    BakedLightmap baked;
    double strength = 1.0;
};

std::optional<Lightmapped> bakeLightmapStage(const SolveArgs& args, const PreparedScene& scene,
                                             const Solution& solution, const Rendered& rendered,
                                             const std::optional<LightmapLayout>& layout, SolveReport& report) {
    if (!layout) return std::nullopt;
    Stopwatch stage;
    const ViewPathSolution paths{solution.elements, *rendered.deviceElements, rendered.vertices, solution.irradiance,
                                 rendered.caustic};
    LightmapBakeOptions options;
    options.samples = args.lightmapSamples;
    options.mode = renderModeNamed(args.lightmapMode).value_or(RenderMode::finalGather);
    options.seed = args.input.seed;
    options.indirectRaysPerElement = static_cast<std::uint32_t>(args.gatherRays);
    Lightmapped out;
    out.baked = bakeLightmap(scene, paths, *rendered.paths, *layout, options);
    if (out.baked.sharedTexels > 0)
        emitWarning(args.input.scene.name() + ": lightmap: " + std::to_string(out.baked.sharedTexels) +
                        " texels hold parts of two or more charts of the scene's TEXCOORD_1 (less than a texel "
                        "apart); each holds its anchor's chart only, so filtering at those charts' edges reads the "
                        "other chart's light",
                    &report.warnings);
    fillGutters(out.baked, std::max<std::uint32_t>(LightmapOptions{}.gutter, 1));
    const SeamReport seams = stitchSeams(out.baked, *layout, scene.mesh(), LightmapOptions{}.charts.creaseDegrees);
    std::vector<float> brightest;
    for (const LightmapPage& page : out.baked.pages)
        for (std::size_t i = 0; i < page.area.size(); ++i)
            if (page.area[i] > 0.0)
                brightest.push_back(std::max({page.irradiance[i].x, page.irradiance[i].y, page.irradiance[i].z}) /
                                    static_cast<float>(kPi));
    if (!brightest.empty()) {
        const std::size_t k = std::min(brightest.size() - 1, static_cast<std::size_t>(0.999 * brightest.size()));
        std::nth_element(brightest.begin(), brightest.begin() + static_cast<std::ptrdiff_t>(k), brightest.end());
        if (brightest[k] > 0.0f) out.strength = brightest[k];
    }
    LightmapSummary& l = report.lightmap;
    l.baked = true;
    l.fromScene = layout->fromScene;
    l.note = layout->note;
    l.mode = renderModeName(options.mode);
    l.pages = layout->pages;
    l.pageSize = layout->pageSize;
    l.charts = layout->charts;
    l.samples = options.samples;
    l.texelSize = layout->texelSize;
    l.areaUse = layout->areaUse;
    l.largestStretch = layout->largestStretch;
    l.meanStretch = layout->meanStretch;
    l.texels = out.baked.texels;
    l.backSides = out.baked.backSides;
    l.rays = out.baked.rays;
    l.seamEdges = seams.edges;
    l.seamMismatchBefore = seams.mismatchBefore;
    l.seamMismatchAfter = seams.mismatchAfter;
    l.emissiveStrength = out.strength;
    report.seconds.lightmap = stage.seconds();
    return out;
}

// The lightmap's files, named lightmap.exr, ... for one page and lightmap-0.exr, ... for more.
std::vector<std::string> writeLightmap(const SolveArgs& args, const PreparedScene& scene, const LightmapLayout& layout,
                                       const Lightmapped& lightmap) {
    const std::filesystem::path dir(args.output);
    std::vector<std::string> written;
    std::vector<Image> radiance;
    const std::size_t pages = lightmap.baked.pages.size();
    for (std::size_t p = 0; p < pages; ++p) {
        const LightmapPage& page = lightmap.baked.pages[p];
        const std::string suffix = pages == 1 ? "" : "-" + std::to_string(p);
        const int side = static_cast<int>(lightmap.baked.size);
        writeExr((dir / ("lightmap" + suffix + ".exr")).string(), Image{side, side, page.irradiance});
        written.push_back("lightmap" + suffix + ".exr");
        radiance.push_back(Image{side, side, page.radiance});
        if (args.lightmapRadiance) {
            writeExr((dir / ("lightmap-radiance" + suffix + ".exr")).string(), radiance.back());
            written.push_back("lightmap-radiance" + suffix + ".exr");
        }
        writePngPreview((dir / ("lightmap" + suffix + ".png")).string(), radiance.back());
        written.push_back("lightmap" + suffix + ".png");
    }
    writeLightmappedGltf((dir / "lightmapped.glb").string(), scene.scene(), scene.mesh(), layout, radiance,
                         lightmap.strength);
    written.push_back("lightmapped.glb");
    return written;
}

// Every output but the report, each written whole or not at all; their names, in order.
std::vector<std::string> writeOutputs(const SolveArgs& args, const PreparedScene& scene, const Solution& solution,
                                      const Rendered& rendered, const std::optional<LightmapLayout>& layout,
                                      const std::optional<Lightmapped>& lightmap, SolveReport& report) {
    Stopwatch stage;
    makeOutputDirectory(args.output);
    const std::filesystem::path dir(args.output);
    writeExr((dir / "render.exr").string(), rendered.image);
    writePngPreview((dir / "render.png").string(), rendered.image);
    const BakedTextures textures{scene.scene(), rendered.irradiance};
    writeBakedGltf((dir / "lit.glb").string(), scene.mesh(), solution.elements, rendered.vertices, rendered.radiance,
                   scene.scene().origin, &textures);
    std::vector<std::string> written = {"render.exr", "render.png", "lit.glb", "report.json"};
    if (rendered.meshImage) {
        writePngPreview((dir / "render-mesh.png").string(), *rendered.meshImage);
        written.push_back("render-mesh.png");
    }
    if (args.elementCsv) {
        writeFileAtomically((dir / "elements.csv").string(), [&](std::ostream& out) {
            writeElementCsv(out, scene, solution.elements, solution.radiosity);
        });
        written.push_back("elements.csv");
    }
    if (layout && lightmap)
        for (std::string& name : writeLightmap(args, scene, *layout, *lightmap)) written.push_back(std::move(name));
    if (!args.vtu.empty()) {
        writeFileAtomically(args.vtu, [&](std::ostream& out) {
            writeVtu(out, solutionGrid(scene, solution.elements, solution.radiosity, solution.irradiance));
        });
        // Listed by its name when it is in the output folder, else by its absolute path.
        const std::filesystem::path vtu = std::filesystem::absolute(args.vtu).lexically_normal();
        // (through a child name, so that "out/" and "out" are the same folder)
        const bool inFolder = vtu.parent_path() == (std::filesystem::absolute(dir) / "x").lexically_normal().parent_path();
        written.push_back(inFolder ? vtu.filename().string() : vtu.string());
    }
    report.seconds.write = stage.seconds();  // the report itself is written after this is taken
    return written;
}

void describe(SolveReport& report, const SolveArgs& args, const PreparedScene& scene, const Solution& solution,
              const Rendered& rendered, const View& view) {
    const Mesh& mesh = scene.mesh();
    report.scene = args.input.scene.name();
    report.method = args.method;
    report.solver = args.solver;
    report.methodParameters = solution.parameters;
    report.rays = args.values.count64(kRaysOption);
    report.minRays = args.values.count32(kMinRaysOption);
    report.tolerance = args.values.number(kToleranceOption);
    report.maxShots = args.values.count64(kMaxShotsOption);
    report.timeLimit = args.values.number(kTimeLimitOption);
    report.seed = args.input.seed;
    report.patchSize = mesh.patchSize;
    report.camera = view.name;
    report.width = args.width;
    report.height = args.height;
    report.samplesPerPixel = args.samples;
    report.noiseTarget = args.noise;
    const DeviceDescription& d = scene.compute().description();
    report.platform = d.platform;
    report.device = d.name;
    report.deviceType = d.type;
    report.deviceVersion = d.version;
    report.driver = d.driver;
    report.faces = mesh.faces.size();
    report.patches = mesh.patches.size();
    report.vertices = rendered.vertices.positions.size();
    report.tallies = solution.tallies;
    report.rayPowerScale = solution.rayPowerScale;
    report.expectedNoise = solution.expectedNoise;
    report.stopped = solution.stopped;
    report.iterations = solution.iterations;
    report.residual = solution.residual;
    report.unshotFraction = solution.unshotFraction;
    report.energy = solution.energy;
    report.elements = solution.elements.elements().size();
    report.refinementPasses = solution.refinementPasses;
    report.clusters = solution.clusters;
    report.pooled = solution.pooled;
    report.adaptive = args.values.flag(kAdaptiveOption);
    report.sky = scene.scene().sky;
    if (const auto& map = scene.scene().environment) {
        report.environment = map->path;
        report.environmentStrength = map->strength;
        report.environmentWidth = map->width;
        report.environmentHeight = map->height;
    }
    const auto means = surfaceMeans(mesh, solution.elements, solution.radiosity);
    const auto perSurface = elementsPerSurface(mesh, solution.elements);
    for (std::size_t s = 0; s < mesh.surfaces.size(); ++s)
        report.surfaces.push_back(
            {mesh.surfaces[s].name, mesh.surfaces[s].area, means[s], mesh.surfaces[s].patchCount, perSurface[s]});
}

}  // namespace

CLI::App* addSolveCommand(CLI::App& app, SolveArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "solve", "Light the scene by radiosity; write render.exr, render.png, lit.glb, report.json.");
    args.declared = std::make_unique<DeclaredOptions>(cmd, &args.values);
    DeclaredOptions& options = *args.declared;
    addSceneInputOptions(options, args.input);
    addLightingOptions(options, args.lighting);
    options.bind(OptionSpec::text("--output", "directory for the outputs", "out"), args.output);
    options.bind(OptionSpec::text("--camera", "render from the camera of this name (default: the scene's first)"),
                 args.camera);
    options.bind(OptionSpec::count("--width", "image width in pixels", 512, 1, 16384), args.width);
    options.bind(OptionSpec::count("--height", "image height in pixels", 512, 1, 16384), args.height);
    options.bind(OptionSpec::count("--samples",
                                   "samples per pixel, as pathtrace counts them; the radiosity mode stratifies them "
                                   "over the squarest grid they fill (16: 4 x 4, 8: 4 x 2; at most 256), the sampled "
                                   "modes over the pixel by their own sequences (with --noise, the most)",
                                   4, 1, 1u << 30),
                 args.samples);
    options.bind(OptionSpec::fraction("--noise",
                                      "direct and final-gather: stop sooner, once the image's noise (the root of the "
                                      "pixels' mean variance over their mean luminance, measured from the samples) "
                                      "is at most this; 0: never",
                                      0.0, 0.0, 1.0),
                 args.noise);
    options.bind(OptionSpec::choice("--render",
                                    "the camera pass: radiosity (the solution interpolated over the elements), direct "
                                    "(direct light per pixel by light sampling, the solution's indirect light "
                                    "interpolated) or final-gather (direct light per pixel, indirect light gathered per "
                                    "pixel from the solution)",
                                    renderModeName(RenderMode::radiosity),
                                    {renderModeName(RenderMode::radiosity), renderModeName(RenderMode::direct),
                                     renderModeName(RenderMode::finalGather)}),
                 args.render);
    options.bind(OptionSpec::count("--gather-rays",
                                   "direct mode: cosine rays from each element that gather the solution's indirect "
                                   "light there",
                                   256, 1, 65536),
                 args.gatherRays);
    options.bind(OptionSpec::flag("--quiet", "no progress display"), args.quiet);
    options.bind(OptionSpec::flag("--debug-mesh", "also write render-mesh.png, the image with the elements' edges"),
                 args.debugMesh);
    options.bind(OptionSpec::flag("--element-csv", "also write elements.csv: per element its surface, centroid, "
                                                   "normal, area, reflectance and radiosity"),
                 args.elementCsv);

    options.bind(OptionSpec::text("--vtu",
                                  "also write the solution on the geometry to this VTK file for ParaView (.vtu, one "
                                  "triangle per element: radiosity and irradiance RGB in W/m^2, surface, side, patch, "
                                  "area)"),
                 args.vtu);
    options.bind(OptionSpec::flag("--lightmap",
                                  "also bake a lightmap on the scene's own meshes: lightmap.exr (irradiance per texel, "
                                  "W/m^2; one file per page), lightmap.png (a preview of the radiance) and "
                                  "lightmapped.glb (the scene with the lightmap on TEXCOORD_1 as an emissive texture)"),
                 args.lightmap);
    options.bind(OptionSpec::positive("--texel-size", "lightmap: metres per texel (default: about the smallest that "
                                                      "puts the atlas on one page)")
                     .needing("--lightmap"),
                 args.texelSize);
    options.bind(OptionSpec::count("--lightmap-size",
                                   "lightmap: texels per side of a page (default: 1024, or with --texel-size the "
                                   "smallest power of two from 64 to 4096 that holds the atlas on one page)",
                                   0, 8, 8192)
                     .needing("--lightmap"),
                 args.lightmapSize);
    options.bind(
        OptionSpec::count("--lightmap-samples", "lightmap: samples per texel, over its footprint", 64, 1, 65536)
            .needing("--lightmap"),
        args.lightmapSamples);
    options.bind(OptionSpec::choice("--lightmap-uv",
                                    "lightmap: auto (the scene's TEXCOORD_1 where every triangle has one and none "
                                    "overlap, else a made atlas), scene (TEXCOORD_1 or an error) or atlas (always a "
                                    "made one)",
                                    "auto", {"auto", "scene", "atlas"})
                     .needing("--lightmap"),
                 args.lightmapUv);
    options.bind(OptionSpec::choice("--lightmap-mode",
                                    "lightmap: the texels' indirect light gathered per sample from the solution "
                                    "(final-gather), or interpolated over its elements (direct: faster, but it carries "
                                    "light up to an element across a contact)",
                                    renderModeName(RenderMode::finalGather),
                                    {renderModeName(RenderMode::direct), renderModeName(RenderMode::finalGather)})
                     .needing("--lightmap"),
                 args.lightmapMode);
    options.bind(OptionSpec::flag("--lightmap-radiance",
                                  "lightmap: also write lightmap-radiance.exr, the radiance a viewer sees (Le + rho E / "
                                  "pi)")
                     .needing("--lightmap"),
                 args.lightmapRadiance);

    // What the registries declare: the methods, the solvers and the strategies, and their options.
    std::vector<std::string> methods, solvers;
    std::string methodHelp = "form factors by:", solverHelp = "how the system is solved:";
    for (const FormFactorMethod& m : formFactorMethods()) {
        methods.push_back(m.name);
        methodHelp += std::string(methods.size() > 1 ? ";" : "") + " " + m.name + " (" + m.description + ")";
    }
    for (const MatrixSolverEntry& s : matrixSolvers()) {
        solvers.push_back(s.name);
        solverHelp += std::string(solvers.size() > 1 ? ";" : "") + " " + s.name + " (" + s.description + ")";
    }
    options.bind(OptionSpec::choice("--method", methodHelp, "shoot", methods), args.method);
    options.bind(OptionSpec::choice("--solver", solverHelp, "progressive", solvers), args.solver);
    for (const SolveStrategyEntry& s : solveStrategies()) options.add(s.options, s.chosenBy);
    for (const FormFactorMethod& m : formFactorMethods()) options.add(m.options, "--method " + m.name);
    for (const MatrixSolverEntry& s : matrixSolvers()) options.add(s.options, "--solver " + s.name);
    return cmd;
}

SolveOutcome runSolve(const SolveArgs& args, const ProcessGroup& group) {
    // Options that cannot work, or that the chosen method and solver would ignore, are refused
    // before anything is loaded.
    const std::unique_ptr<SolveStrategy> strategy =
        makeSolveStrategy({args.method, args.solver, args.values, args.input.seed});
    args.declared->refuseUnused(strategy->options(), "--method " + args.method + " --solver " + args.solver);
    if (renderModeNamed(args.render) == RenderMode::radiosity && args.samples > 256)
        throw InputError("--samples " + std::to_string(args.samples) +
                         ": the radiosity mode takes at most 256 (a grid in each pixel); direct and final-gather take "
                         "more");
    if (renderModeNamed(args.render) == RenderMode::radiosity && args.noise > 0.0)
        throw InputError("--noise: the radiosity mode does not sample (its image has no noise to measure); direct and "
                         "final-gather do");

    SolveReport report;
    Prepared prepared = prepare(args, group, report);
    const PreparedScene& scene = *prepared.scene;
    const DeviceDescription& device = scene.compute().description();
    report.rankDevices = gatherTexts(group, device.platform + ": " + device.name);
    Solution solution = solve(args, *strategy, scene, group, report);
    SolveOutcome outcome;
    if (!group.root()) return outcome;  // the others hold the same solution; rank 0 renders and writes
    const Rendered rendered = render(args, scene, solution, prepared.view, prepared.lightmap.has_value(), report);
    const std::optional<Lightmapped> lightmap =
        bakeLightmapStage(args, scene, solution, rendered, prepared.lightmap, report);
    report.outputs = writeOutputs(args, scene, solution, rendered, prepared.lightmap, lightmap, report);
    describe(report, args, scene, solution, rendered, prepared.view);
    outcome.report = reportJson(report);
    writeFileAtomically((std::filesystem::path(args.output) / "report.json").string(),
                        [&](std::ostream& out) { out << outcome.report; });

    std::string written;
    for (const std::string& name : report.outputs)
        written += (written.empty() ? "" : ", ") + (std::filesystem::path(args.output) / name).string();
    const std::string ranks = group.size() > 1 ? " on " + std::to_string(group.size()) + " ranks" : "";
    std::fprintf(stderr, "solve: %zu patches, %zu elements, %s (stopped: %s)%s, %.2f s; wrote %s\n",
                 scene.mesh().patches.size(), solution.elements.elements().size(), solution.summary.c_str(),
                 report.stopped.c_str(), ranks.c_str(),
                 report.seconds.load + report.seconds.mesh + report.seconds.bvh + report.seconds.solve +
                     report.seconds.render + report.seconds.lightmapLayout + report.seconds.lightmap +
                     report.seconds.write,
                 written.c_str());
    outcome.solution = std::move(solution);
    outcome.scene = std::move(prepared.scene);
    return outcome;
}

}  // namespace rad
