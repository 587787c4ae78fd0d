#pragma once
// The subcommands, one file each: add<Name>Command declares its options on the command line,
// run<Name> does the work. Each returns normally on success and throws rad::Error otherwise;
// main.cpp turns errors into a message and an exit status.

#include <cstdint>
#include <memory>
#include <string>

#include "app/cli_options.h"
#include "prepared/prepared_scene.h"
#include "solver/solve_strategy.h"
#include "util/options.h"

namespace CLI {
class App;
}

namespace rad {

class ProcessGroup;
class Ranks;

void runDevices();

// The command line's callbacks hold references into these, so they stay where main made them. A
// field bound to an option starts at the option's declared default (app/cli_options.h), which is
// the only place defaults are written.
struct ViewFactorArgs {
    ViewFactorArgs() = default;
    ViewFactorArgs(const ViewFactorArgs&) = delete;
    ViewFactorArgs& operator=(const ViewFactorArgs&) = delete;
    SceneInputArgs input;
    std::string output;   // empty: standard output
    std::string method;
    std::string level;    // surface | patch
    std::string format;   // csv | mtx
    std::string enforce;  // none | reciprocity | closure | both
    std::string patches;  // --patches FILE.csv: where each patch is (with --level patch)
    std::string toSpace;  // --to-space FILE.csv: per row, the share that left the scene
    OptionValues values;  // the methods' options, --rays and --max-memory
    std::unique_ptr<DeclaredOptions> declared;
};

CLI::App* addViewFactorsCommand(CLI::App& app, ViewFactorArgs& args);
// Under mpirun, surface shooting divides the surfaces among the ranks (parallel/ranks.h); only
// rank 0 writes and prints.
void runViewFactors(const ViewFactorArgs& args, const Ranks& ranks);

struct ExchangeArgs {
    ExchangeArgs() = default;
    ExchangeArgs(const ExchangeArgs&) = delete;
    ExchangeArgs& operator=(const ExchangeArgs&) = delete;
    SceneInputArgs input;
    std::string properties;               // CSV: surface,emissivity,temperature|heat_flux
    double defaultEmissivity = 0.0;       // 0: not given (the option's default)
    double defaultTemperature = 0.0;      // < 0: not given (the option's default is -1)
    double environmentTemperature = 0.0;  // K
    std::uint64_t rays = 0;               // per surface, over all batches
    std::uint32_t batches = 0;            // independent estimates, for the error bars
    std::string enforce;
    std::string output;          // CSV; empty: standard output
    std::string exchange;        // exchange factors and conductors; empty: none
    std::string exchangeFormat;  // csv | mtx
    std::string vtu;             // --vtu FILE: the results per patch on the geometry (VTK XML)
};

CLI::App* addExchangeCommand(CLI::App& app, ExchangeArgs& args);
// Under mpirun each batch's surfaces are divided among the ranks and gathered; rank 0 writes.
void runExchange(const ExchangeArgs& args, const ProcessGroup& group);

struct SolveArgs {
    SolveArgs() = default;
    SolveArgs(const SolveArgs&) = delete;
    SolveArgs& operator=(const SolveArgs&) = delete;
    SceneInputArgs input;
    LightingArgs lighting;
    std::string output;
    std::string camera;
    int width = 0, height = 0;
    int samples = 0;     // per pixel, at most
    double noise = 0.0;  // the sampled modes stop sooner at this image noise; 0: none
    int gatherRays = 0;  // direct mode: cosine rays per element for the solution's indirect light
    std::string render;  // the camera pass's mode (render/view_pass.h)
    bool quiet = false;
    bool debugMesh = false;   // also write render-mesh.png with the elements' edges
    bool elementCsv = false;  // also write elements.csv, the solution per element
    std::string vtu;          // --vtu FILE: the solution per element on the geometry (VTK XML)
    // --lightmap (lightmap/): bake a lightmap on the scene's own meshes.
    bool lightmap = false;
    double texelSize = 0.0;          // metres; 0: the atlas fills one page of lightmapSize
    std::uint32_t lightmapSize = 0;  // texels per side of a page; 0: LightmapOptions' choice
    std::uint32_t lightmapSamples = 0;
    std::string lightmapUv;       // auto, scene or atlas (LightmapOptions::Uv)
    std::string lightmapMode;     // the texels' indirect light: direct or final-gather
    bool lightmapRadiance = false;  // also write the radiance pages
    std::string method;
    std::string solver;
    OptionValues values;  // the options the strategies, methods and solvers declare
    std::unique_ptr<DeclaredOptions> declared;
};

CLI::App* addSolveCommand(CLI::App& app, SolveArgs& args);
// What a solve leaves besides its files (the Python module reads it): the prepared scene, the
// solution, and report.json's text as written. Empty on ranks other than 0.
struct SolveOutcome {
    std::unique_ptr<PreparedScene> scene;
    Solution solution;
    std::string report;
};
// Under mpirun every rank prepares the scene on its own device (--device may name one per rank)
// and the ranks share each batch's shots (solver/progressive_solver.h); the solution is bitwise
// that of one process, and rank 0 renders, writes and reports.
SolveOutcome runSolve(const SolveArgs& args, const ProcessGroup& group);

struct PathTraceArgs {
    PathTraceArgs() = default;
    PathTraceArgs(const PathTraceArgs&) = delete;
    PathTraceArgs& operator=(const PathTraceArgs&) = delete;
    SceneFileArgs scene;
    std::string output;
    std::string camera;
    int width = 0, height = 0;
    std::uint32_t samples = 0;     // paths per pixel, at most
    double noise = 0.0;            // stop sooner at this image noise; 0: none
    std::uint32_t maxBounces = 0;  // 0: no limit (Russian roulette)
    std::uint32_t seed = 0;
    bool noLightSampling = false;  // find emitting surfaces only where paths hit them
    std::string device;
    LightingArgs lighting;
};

CLI::App* addPathTraceCommand(CLI::App& app, PathTraceArgs& args);
void runPathTrace(const PathTraceArgs& args);

}  // namespace rad
