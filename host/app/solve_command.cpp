#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>

#include "app/commands.h"
#include "app/console.h"
#include "app/interrupt.h"
#include "app/progress.h"
#include "app/reliability.h"
#include "io/atomic_file.h"
#include "io/baked_gltf.h"
#include "io/element_csv.h"
#include "io/checkpoint.h"
#include "io/image_files.h"
#include "io/solve_report.h"
#include "mesh/mesh.h"
#include "mesh/device_elements.h"
#include "mesh/elements.h"
#include "mesh/vertices.h"
#include "solver/refinement.h"
#include "render/renderer.h"
#include "render/view.h"
#include "scene/gltf_loader.h"
#include "formfactor/patch_matrix.h"
#include "solver/matrix_solvers.h"
#include "solver/progressive_solver.h"
#include "solver/surface_means.h"
#include "util/error.h"
#include "util/fnv.h"
#include "util/stopwatch.h"
#include "shared_math.h"

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

// Identifies the problem a checkpoint belongs to: the scene's bytes, the mesh, and every
// option that steers which shots are taken (stopping criteria may differ on resume).
std::uint64_t problemFingerprint(const std::string& scenePath, const Mesh& mesh, const ProgressiveOptions& o) {
    std::ifstream in(scenePath, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return Fnv1a()
        .add(bytes)
        .add(mesh.patchSize)
        .add(static_cast<std::uint64_t>(mesh.patches.size()))
        .add(o.rays)
        .add(o.minRays)
        .add(o.seed)
        .add(o.maxShootersPerBatch)
        .add(o.batchPowerRatio)
        .value();
}

void describeDevice(SolveReport& report, const DeviceDescription& d) {
    report.platform = d.platform;
    report.device = d.name;
    report.deviceType = d.type;
    report.deviceVersion = d.version;
    report.driver = d.driver;
}

// What either path produces: radiosity per patch and its bookkeeping.
struct Solution {
    std::vector<glm::vec3> radiosity;
    EnergyBalance energy;
    std::string stopped;
    double unshotFraction = 0.0;
    std::uint64_t shots = 0, batches = 0, rays = 0;
    std::uint64_t iterations = 0;
    double residual = -1.0;
};

// The default: progressive refinement with ray shooting, resident on the device.
ProgressiveOptions progressiveOptions(const SolveArgs& args) {
    ProgressiveOptions options;
    options.rays = args.rays;
    options.minRays = args.minRays;
    options.tolerance = args.tolerance;
    options.maxShots = args.maxShots;
    options.timeLimit = args.timeLimit;
    options.seed = args.seed;
    return options;
}

Solution solveOnDevice(const SolveArgs& args, const PreparedScene& scene, const ElementMesh& elements) {
    const ProgressiveOptions options = progressiveOptions(args);
    const std::uint64_t fingerprint = problemFingerprint(args.scene, scene.mesh(), options);
    std::optional<SolverState> resumed;
    if (!args.resume.empty()) resumed = readCheckpoint(args.resume, fingerprint);
    installInterruptHandlers();
    ProgressDisplay display(args.tolerance);
    SolveHooks hooks;
    hooks.progress = [&](const SolveProgress& p) {
        if (!args.quiet) display.update(p);
    };
    hooks.interrupted = interruptRequested;
    if (!args.checkpoint.empty()) {
        hooks.checkpointEvery = args.checkpointEvery;
        hooks.checkpoint = [&](const SolverState& state) { writeCheckpoint(args.checkpoint, state, fingerprint); };
    }
    const ProgressiveResult result =
        ProgressiveSolver(scene, elements).solve(options, hooks, resumed ? &*resumed : nullptr);
    display.finish();
    Solution s;
    s.radiosity = result.radiosity;
    s.energy = result.energy;
    s.stopped = stopReasonName(result.stopped);
    s.unshotFraction = result.unshotFraction;
    s.shots = result.shots;
    s.batches = result.batches;
    s.rays = result.rays;
    return s;
}

// Adaptive refinement: passes by direct light, then one by a provisional solve with a quarter
// of the rays, to unshot 1e-2.
int refine(const SolveArgs& args, const PreparedScene& scene, ElementMesh& elements) {
    ProgressiveOptions provisional = progressiveOptions(args);
    provisional.rays = std::max<std::uint64_t>(1, args.rays / 4);
    provisional.tolerance = std::max(args.tolerance, 1e-2);
    provisional.maxShots = 0;
    provisional.timeLimit = 0.0;
    AdaptiveOptions options;
    options.marks.threshold = args.refineThreshold;
    options.marks.seed = args.seed;
    options.minEdge = args.minElementSize > 0.0 ? args.minElementSize : scene.mesh().patchSize / 16.0;
    options.maxElements = args.maxElements;
    options.passes = args.refinePasses;
    options.finalRays = args.rays;
    int number = 0;
    const auto passes = refineAdaptively(scene, elements, provisional, options,
                                         interruptRequested, [&](const RefinementPass& pass) {
        if (args.quiet) return;
        std::fprintf(stderr,
                     "solve: refinement pass %d (%s): %zu of %zu elements marked, %zu left whole for want of rays; "
                     "now %zu elements (%.2f s)\n",
                     ++number, pass.bySolution ? "provisional solve" : "direct light", pass.marked, pass.examined,
                     pass.tooFewRays, pass.after, pass.seconds);
    });
    return static_cast<int>(passes.size());
}

// The classic path: the whole form-factor matrix by the chosen estimator, then a full-matrix
// solver (or progressive refinement on the matrix).
Solution solveByMatrix(const SolveArgs& args, const PreparedScene& scene, SolveReport& report) {
    const Mesh& mesh = scene.mesh();
    const FormFactorOptions options = formFactorOptions(args.method, args.seed);
    MatrixSolveOptions solve;
    solve.solver = parseSolver(args.solver);
    solve.bounces = args.bounces;
    solve.tolerance = solve.solver == MatrixSolver::Progressive ? args.tolerance : args.residual;
    solve.maxMemory = args.method.maxMemory;
    // The direct solver's dense system is refused before the matrix is built, not after.
    const double denseBytes = 16.0 * static_cast<double>(mesh.patches.size()) * static_cast<double>(mesh.patches.size());
    if (solve.solver == MatrixSolver::Direct && denseBytes > static_cast<double>(solve.maxMemory))
        throw InputError("the direct solver needs a dense " + std::to_string(mesh.patches.size()) + " x " +
                         std::to_string(mesh.patches.size()) + " system: about " +
                         std::to_string(static_cast<std::uint64_t>(denseBytes / (1 << 20))) +
                         " MiB; --max-memory allows " + std::to_string(solve.maxMemory >> 20) +
                         " MiB (use --solver gauss-seidel, or a larger --patch-size)");
    const PatchMatrix matrix = buildPatchMatrix(scene, options);
    const PatchSystem& system = scene.patches();
    std::vector<glm::dvec3> exitance, reflectance;
    std::vector<double> area;
    for (std::size_t p = 0; p < system.size(); ++p) {
        exitance.emplace_back(system.exitance(p));
        reflectance.emplace_back(system.reflectance[p]);
        area.push_back(system.area[p]);
    }
    const MatrixSolveResult result = solveMatrix(matrix, exitance, reflectance, area, solve);
    Solution s;
    for (const glm::dvec3& b : result.radiosity) s.radiosity.emplace_back(b);
    s.energy = result.energy;
    s.iterations = result.iterations;
    s.residual = result.residual;
    s.stopped = solve.bounces > 0 && solve.solver == MatrixSolver::Jacobi ? "bounces"
                : result.converged                                         ? "tolerance"
                                                                           : "max-iterations";
    if (solve.solver == MatrixSolver::Progressive) {
        s.unshotFraction = result.residual;
        s.shots = result.iterations;
    }
    switch (options.method) {
        case FormFactorMethod::Shoot: report.methodParameters.emplace_back("rays_per_patch", options.raysPerPatch); break;
        case FormFactorMethod::Hemicube:
            report.methodParameters.emplace_back("hemicube_res", options.hemicubeResolution);
            report.methodParameters.emplace_back("hemicube_jitter", options.hemicubeJitter ? 1 : 0);
            report.methodParameters.emplace_back("hemicube_weight_sum", matrix.weightSum);
            break;
        case FormFactorMethod::Gather: report.methodParameters.emplace_back("shadow_rays", options.shadowRays); break;
    }
    if (solve.solver == MatrixSolver::Jacobi) report.methodParameters.emplace_back("bounces", solve.bounces);
    if (solve.solver == MatrixSolver::Jacobi || solve.solver == MatrixSolver::GaussSeidel)
        report.methodParameters.emplace_back("residual_tolerance", solve.tolerance);
    report.methodParameters.emplace_back("matrix_nonzeros", static_cast<double>(matrix.F.nonZeros()));
    return s;
}

}  // namespace

void runSolve(const SolveArgs& args) {
    if (args.tolerance <= 0.0 && args.maxShots == 0 && args.timeLimit <= 0.0)
        throw InputError("--tolerance 0 never stops by itself: give --max-shots or --time-limit too");
    const bool matrixPath = args.method.method != "shoot" || args.solver != "progressive";
    if (matrixPath && (args.adaptive || args.elementSize > 0.0))
        throw InputError("--adaptive and --element-size work with the device's progressive solver (--method shoot "
                         "--solver progressive); the matrix methods solve per patch");
    if (args.adaptive && (!args.checkpoint.empty() || !args.resume.empty()))
        throw InputError("--checkpoint and --resume do not work with --adaptive yet");
    SolveReport report;
    report.scene = args.scene;
    Stopwatch stage;
    Scene loaded = loadGltf(args.scene);
    printWarnings(loaded);
    report.warnings = loaded.warnings;
    if (!loaded.anyEmitter())
        throw FileError(args.scene, "nothing in the scene emits light (no material has an emissive factor): "
                                    "there is nothing to solve");
    const View view = chooseView(loaded, args.camera);  // fail on a bad camera name before the work
    checkOutputDirectory(args.output);
    report.seconds.load = stage.seconds();

    const PreparedScene scene(std::move(loaded), {args.patchSize, args.maxPatches}, DeviceChoice{args.device});
    const Mesh& mesh = scene.mesh();
    report.seconds.mesh = scene.meshSeconds();
    report.seconds.bvh = scene.bvhSeconds() + scene.deviceSeconds();
    double emittedPower = 0.0;  // W, all channels: zero when emitters are too small to represent
    for (std::size_t p = 0; p < scene.patches().size(); ++p) {
        const glm::vec3 e = scene.patches().exitance(p);
        emittedPower += static_cast<double>(scene.patches().area[p]) * (e.x + e.y + e.z);
    }
    if (!(emittedPower > 0.0))
        throw FileError(args.scene, "the emitters emit no power in single precision (their area or radiance is too small)");

    stage = Stopwatch();
    const bool onDevice = args.method.method == "shoot" && args.solver == "progressive";
    if (!onDevice) emitWarnings(samplingWarnings(mesh, args.method, args.method.raysPerPatch, false), &report.warnings);
    ElementMesh elements = ElementMesh::uniform(mesh, onDevice ? args.elementSize : 0.0);
    int passes = 0;
    if (args.adaptive) passes = refine(args, scene, elements);
    const Solution result = onDevice ? solveOnDevice(args, scene, elements) : solveByMatrix(args, scene, report);
    report.seconds.solve = stage.seconds();
    if (onDevice) emitWarnings(rayHitWarnings(scene, elements, result.radiosity, args.rays), &report.warnings);

    stage = Stopwatch();
    const DeviceElements deviceElements(scene.compute(), elements);
    const MeshVertices vertices = weldVertices(mesh, elements);
    std::vector<glm::vec3> radiance = vertexValues(elements, vertices, result.radiosity);
    for (glm::vec3& r : radiance) r /= static_cast<float>(kPi);
    RenderOptions render{args.width, args.height, args.samplesPerSide};
    const Image image = renderView(scene, deviceElements, vertices, radiance, view, render);
    std::optional<Image> meshImage;
    if (args.debugMesh) {
        render.wireframe = true;
        meshImage = renderView(scene, deviceElements, vertices, radiance, view, render);
    }
    report.seconds.render = stage.seconds();

    stage = Stopwatch();
    makeOutputDirectory(args.output);
    const std::filesystem::path dir(args.output);
    const std::string exr = (dir / "render.exr").string(), png = (dir / "render.png").string(),
                      glb = (dir / "lit.glb").string(), json = (dir / "report.json").string();
    writeExr(exr, image);
    writePngPreview(png, image);
    writeBakedGltf(glb, mesh, elements, vertices, radiance, scene.scene().origin);
    if (meshImage) writePngPreview((dir / "render-mesh.png").string(), *meshImage);
    if (args.elementCsv)
        writeFileAtomically((dir / "elements.csv").string(), [&](std::ostream& out) {
            writeElementCsv(out, scene, elements, result.radiosity);
        });
    report.seconds.write = stage.seconds();  // the report itself is written after this is taken

    report.rays = args.rays;
    report.minRays = args.minRays;
    report.tolerance = args.tolerance;
    report.maxShots = args.maxShots;
    report.timeLimit = args.timeLimit;
    report.seed = args.seed;
    report.patchSize = mesh.patchSize;
    report.camera = view.name;
    report.width = args.width;
    report.height = args.height;
    report.samplesPerPixel = args.samplesPerSide * args.samplesPerSide;
    describeDevice(report, scene.compute().description());
    report.faces = mesh.faces.size();
    report.patches = mesh.patches.size();
    report.vertices = vertices.positions.size();
    report.shots = result.shots;
    report.batches = result.batches;
    report.raysCast = result.rays;
    report.stopped = result.stopped;
    report.method = args.method.method;
    report.solver = args.solver;
    report.iterations = result.iterations;
    report.residual = result.residual;
    report.unshotFraction = result.unshotFraction;
    report.energy = result.energy;
    report.elements = elements.elements().size();
    report.refinementPasses = passes;
    report.adaptive = args.adaptive;
    const auto means = surfaceMeans(mesh, elements, result.radiosity);
    const auto perSurface = elementsPerSurface(mesh, elements);
    for (std::size_t s = 0; s < mesh.surfaces.size(); ++s)
        report.surfaces.push_back({mesh.surfaces[s].name, mesh.surfaces[s].area, means[s], mesh.surfaces[s].patchCount,
                                   perSurface[s]});
    report.outputs = {"render.exr", "render.png", "lit.glb", "report.json"};
    if (meshImage) report.outputs.push_back("render-mesh.png");
    if (args.elementCsv) report.outputs.push_back("elements.csv");
    writeSolveReport(json, report);

    char progress[96];
    if (onDevice || args.solver == "progressive")
        std::snprintf(progress, sizeof progress, "%llu shots, unshot %.2e", static_cast<unsigned long long>(result.shots),
                      result.unshotFraction);
    else
        std::snprintf(progress, sizeof progress, "%s %s, %llu iterations, residual %.2e", args.method.method.c_str(),
                      args.solver.c_str(), static_cast<unsigned long long>(result.iterations), result.residual);
    std::string written;
    for (const std::string& name : report.outputs) written += (written.empty() ? "" : ", ") + (dir / name).string();
    std::fprintf(stderr, "solve: %zu patches, %zu elements, %s (stopped: %s), %.2f s; wrote %s\n",
                 mesh.patches.size(), elements.elements().size(), progress, report.stopped.c_str(),
                 report.seconds.load + report.seconds.mesh + report.seconds.bvh + report.seconds.solve +
                     report.seconds.render + report.seconds.write,
                 written.c_str());
}

}  // namespace rad
