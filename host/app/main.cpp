// radiosity: the command line. Declares the subcommands (each in its own file), parses, calls
// one, and turns errors into one line on stderr and an exit status: 0 success, 1 runtime or
// device failure, 2 bad input or usage.

#include <cstdint>
#include <cstdio>
#include <new>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "parallel/ranks.h"
#include "util/error.h"

namespace {

constexpr const char* kExitCodes = "Exit status: 0 success; 1 runtime or device failure; 2 bad input or usage.";

// The ranks of this run (one without mpirun), for the error path.
const rad::Ranks* runRanks = nullptr;

int fail(int status, const char* what) {
    if (runRanks && runRanks->size() > 1) {
        // The other ranks may be waiting in a collective: end them all.
        std::fprintf(stderr, "radiosity: error (rank %d of %d): %s\n", runRanks->rank(), runRanks->size(), what);
        std::fflush(stderr);
        runRanks->abort(status);
    }
    std::fprintf(stderr, "radiosity: error: %s\n", what);
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    const rad::Ranks ranks(&argc, &argv);
    runRanks = &ranks;
    CLI::App app{"Radiosity, view factors and heat exchange for glTF, OBJ, STL and PLY scenes, computed on OpenCL devices."};
    app.footer(kExitCodes);
    app.require_subcommand(1);

    app.add_subcommand("devices", "List the OpenCL platforms and devices, with the index --device takes.");
    rad::ViewFactorArgs viewFactors;
    rad::addViewFactorsCommand(app, viewFactors);
    rad::SolveArgs solve;
    rad::addSolveCommand(app, solve);
    rad::PathTraceArgs pathTrace;
    rad::addPathTraceCommand(app, pathTrace);
    rad::ExchangeArgs exchange;
    rad::addExchangeCommand(app, exchange);
    std::uint32_t threads = 0;
    for (CLI::App* command : app.get_subcommands({})) rad::addThreadsOption(command, threads);
    app.set_version_flag("--version", "radiosity " RADIOSITY_VERSION);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "radiosity: error: %s (see --help)\n", e.what());
        return 2;
    }

    rad::applyThreads(threads);  // before the first OpenCL call
    try {
        // Listing devices and path tracing are not divided: under mpirun rank 0 does them whole.
        if (app.got_subcommand("devices") && ranks.root()) rad::runDevices();
        if (app.got_subcommand("viewfactors")) rad::runViewFactors(viewFactors, ranks);
        if (app.got_subcommand("solve")) rad::runSolve(solve, ranks);
        if (app.got_subcommand("pathtrace") && ranks.root()) rad::runPathTrace(pathTrace);
        if (app.got_subcommand("exchange")) rad::runExchange(exchange, ranks);
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
