#pragma once
// The subcommands. Each returns normally on success and throws rad::Error otherwise;
// main.cpp turns errors into a message and an exit status.

#include <cstdint>
#include <string>

namespace CLI {
class App;
}

namespace rad {

void runDevices();

// How form factors are estimated, for both commands.
struct MethodArgs {
    std::string method = "shoot";        // shoot | hemicube | gather
    std::uint32_t raysPerPatch = 4096;   // shoot, when a whole patch matrix is built
    std::uint32_t hemicubeResolution = 128;
    bool hemicubeJitter = false;
    std::uint32_t shadowRays = 16;
    std::uint64_t maxMemory = 4ull << 30;
};

struct ViewFactorArgs {
    std::string scene;
    std::uint64_t rays = 1'000'000;
    double patchSize = 0.0;          // 0: derived from the scene
    std::uint32_t seed = 1;
    std::string device;
    std::string output;              // empty: standard output
    std::uint64_t maxPatches = 10'000'000;
    MethodArgs method;
    std::string level = "surface";   // surface | patch
    std::string format = "csv";      // csv | mtx
    std::string enforce = "none";    // none | reciprocity | closure | both
};

void runViewFactors(const ViewFactorArgs& args);

// The estimator options the method arguments ask for (shared by both commands).
struct FormFactorOptions;
FormFactorOptions formFactorOptions(const MethodArgs& args, std::uint32_t seed);

struct SolveArgs {
    std::string scene;
    std::string output = "out";
    double patchSize = 0.0;
    std::uint64_t rays = 16'000'000;
    std::uint32_t minRays = 128;
    double tolerance = 1e-3;
    std::uint64_t maxShots = 0;
    double timeLimit = 0.0;
    std::uint32_t seed = 1;
    std::string device;
    std::string camera;
    int width = 512, height = 512;
    int samplesPerSide = 2;
    std::uint64_t maxPatches = 10'000'000;
    bool quiet = false;
    std::string checkpoint;          // save the solver's state here
    double checkpointEvery = 60.0;   // seconds between saves
    std::string resume;              // continue from this saved state
    MethodArgs method;
    std::string solver = "progressive";  // progressive | jacobi | gauss-seidel | direct
    int bounces = 0;                 // jacobi: stop after this many bounces (0: to tolerance)
    double residual = 1e-6;          // jacobi, gauss-seidel: stop below this residual
    // Two levels and adaptive refinement.
    double elementSize = 0.0;        // starting receivers' longest edge (0: one element per patch)
    bool adaptive = false;
    double refineThreshold = 0.05;
    double minElementSize = 0.0;     // 0: the patch size / 16
    std::uint64_t maxElements = 4'000'000;
    int refinePasses = 4;
    bool debugMesh = false;          // also write render-mesh.png with the elements' edges
    bool elementCsv = false;         // also write elements.csv, the solution per element
};

void runSolve(const SolveArgs& args);

struct PathTraceArgs {
    std::string scene;
    std::string output = "out/pathtrace.exr";
    std::string camera;
    int width = 256, height = 256;
    std::uint32_t samples = 64;      // paths per pixel
    std::uint32_t maxBounces = 0;    // 0: no limit (Russian roulette)
    std::uint32_t seed = 1;
    std::string device;
};

// Declares the subcommand and its options (app/pathtrace_command.cpp).
CLI::App* addPathTraceCommand(CLI::App& app, PathTraceArgs& args);
void runPathTrace(const PathTraceArgs& args);

}  // namespace rad
