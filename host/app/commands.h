#pragma once
// The subcommands. Each returns normally on success and throws rad::Error otherwise;
// main.cpp turns errors into a message and an exit status.

#include <cstdint>
#include <string>

namespace rad {

void runDevices();

struct ViewFactorArgs {
    std::string scene;
    std::uint64_t rays = 1'000'000;
    double patchSize = 0.0;          // 0: derived from the scene
    std::uint32_t seed = 1;
    std::string device;
    std::string output;              // empty: standard output
    std::uint64_t maxPatches = 10'000'000;
};

void runViewFactors(const ViewFactorArgs& args);

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
};

void runSolve(const SolveArgs& args);

}  // namespace rad
