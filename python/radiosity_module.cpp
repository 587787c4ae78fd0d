// radiosity._radiosity: the binding under `import radiosity` (python/src/radiosity/__init__.py).
// A thin layer: the keyword arguments arrive as the command line's own arguments and are parsed
// by the commands' declared options (app/), so defaults, ranges and refusals are the program's;
// the work is the library's, called as the commands call it, so the numbers are the same bits.
// Errors become the package's exceptions; warnings come back as lists for Python's `warnings`.

#include <csignal>
#include <memory>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "app/console.h"
#include "app/interrupt.h"
#include "cl/device_list.h"
#include "formfactor/enforce.h"
#include "formfactor/sampling_checks.h"
#include "formfactor/view_factor_study.h"
#include "formfactor/view_factor_table.h"
#include "io/exchange_files.h"
#include "io/view_factor_csv.h"
#include "mesh/mesh.h"
#include "parallel/process_group.h"
#include "prepared/prepared_scene.h"
#include "scene/scene_files.h"
#include "thermal/radiative_exchange.h"
#include "thermal/thermal_properties.h"
#include "util/error.h"

namespace py = pybind11;

namespace {

using Matrix = py::array_t<double>;

Matrix matrix(std::size_t rows, std::size_t cols, double fill = 0.0) {
    Matrix m({rows, cols});
    double* p = m.mutable_data();
    for (std::size_t i = 0; i < rows * cols; ++i) p[i] = fill;
    return m;
}

template <typename T>
py::array_t<T> vector(const std::vector<T>& values) {
    py::array_t<T> a(values.size());
    if (!values.empty()) std::memcpy(a.mutable_data(), values.data(), values.size() * sizeof(T));
    return a;
}

// Parses `argv` (without the program's name: the command and its arguments) with the command
// `add` declares, as the program would. The command line must outlive the work, as in main():
// `args` refers to it (DeclaredOptions::refuseUnused reads what was given).
// `threads=N` is the program's --threads: PoCL reads its thread count once, when the process
// first reaches OpenCL. Until a computation (or a device listing) has completed, each call sets
// it anew; from then on a call may only ask for the count that one ran with (or none).
struct DeviceThreads {
    bool started = false;     // a computation has completed: OpenCL has its thread count
    std::uint32_t fixed = 0;  // the count it ran with (0: the default)
    std::uint32_t asked = 0;  // what the call under way asked for

    void use(std::uint32_t threads) {
        asked = threads;
        if (!started) {
            rad::applyThreads(threads);
            return;
        }
        if (threads != 0 && threads != fixed)
            throw rad::InputError("threads=" + std::to_string(threads) +
                                  ": the CPU device's threads are fixed by the process's first computation (" +
                                  (fixed ? "threads=" + std::to_string(fixed) : std::string("the default")) +
                                  "); give threads on the first call");
    }
    void completed() {
        if (started) return;
        started = true;
        fixed = asked;
    }
};
DeviceThreads deviceThreads;

template <typename Args>
std::unique_ptr<CLI::App> parse(CLI::App* (*add)(CLI::App&, Args&), Args& args, const std::vector<std::string>& argv,
                                bool computes = true) {
    auto app = std::make_unique<CLI::App>("radiosity");
    app->require_subcommand(1);
    std::uint32_t threads = 0;
    rad::addThreadsOption(add(*app, args), threads);
    std::vector<const char*> pointers{"radiosity"};
    for (const std::string& a : argv) pointers.push_back(a.c_str());
    try {
        app->parse(static_cast<int>(pointers.size()), pointers.data());
    } catch (const CLI::ParseError& e) {
        throw rad::InputError(e.what());
    }
    if (computes) deviceThreads.use(threads);
    return app;
}

// Collects the warnings the commands emit while `work` runs, instead of printing them.
struct CollectedWarnings {
    std::vector<std::string> list;
    CollectedWarnings() {
        rad::warningSink() = [this](const std::string& w) { list.push_back(w); };
    }
    ~CollectedWarnings() { rad::warningSink() = nullptr; }
    void add(const std::vector<std::string>& warnings) { list.insert(list.end(), warnings.begin(), warnings.end()); }
};

// A view-factor table as Python reads it: dense or sparse, and the program's own CSV and Matrix
// Market text.
struct Table {
    rad::ViewFactorTable table;

    Matrix dense(bool errors) const {
        const std::size_t n = table.size();
        Matrix m = matrix(n, n, 0.0);
        double* p = m.mutable_data();
        for (std::size_t i = 0; i < n; ++i)
            for (const rad::ViewFactorEntry& e : table.rows[i])
                p[i * n + e.to] = errors ? e.standardError : e.factor;
        return m;
    }
    // CSR parts: data, indices, indptr (the entries stored, ascending by column).
    py::tuple csr(bool errors) const {
        std::vector<double> data;
        std::vector<std::int64_t> indices, indptr{0};
        for (const auto& row : table.rows) {
            for (const rad::ViewFactorEntry& e : row) {
                data.push_back(errors ? e.standardError : e.factor);
                indices.push_back(e.to);
            }
            indptr.push_back(static_cast<std::int64_t>(data.size()));
        }
        return py::make_tuple(vector(data), vector(indices), vector(indptr));
    }
    std::string csv() const {
        std::ostringstream out;
        rad::writeViewFactorCsv(out, table);
        return out.str();
    }
    std::string mtx() const {
        std::ostringstream out;
        rad::writeViewFactorMatrixMarket(out, table);
        return out.str();
    }
};

py::dict sceneInfo(const std::vector<std::string>& argv) {
    // The scene options of `viewfactors` (files, --unit, --patch-size, --max-patches); meshed on
    // the host only, no device.
    rad::ViewFactorArgs args;
    const auto commandLine = parse(&rad::addViewFactorsCommand, args, argv, false);  // loads, computes nothing
    CollectedWarnings warnings;
    py::dict out;
    {
        py::gil_scoped_release release;
        rad::Scene scene = rad::loadScene(args.input.scene);
        rad::printWarnings(scene);
        const rad::Mesh mesh = rad::buildMesh(scene, {args.input.patchSize, args.input.maxPatches});
        py::gil_scoped_acquire acquire;
        std::vector<std::string> names;
        std::vector<double> areas;
        std::vector<std::uint32_t> patches;
        for (const rad::MeshSurface& s : mesh.surfaces) {
            names.push_back(s.name);
            areas.push_back(s.area);
            patches.push_back(s.patchCount);
        }
        out["names"] = names;
        out["areas"] = vector(areas);
        out["patches"] = vector(patches);
        out["faces"] = mesh.faces.size();
        out["patch_count"] = mesh.patches.size();
        out["patch_size"] = mesh.patchSize;
        out["path"] = scene.path;
        out["emitters"] = scene.anyEmitter();
    }
    out["warnings"] = warnings.list;
    return out;
}

// The patches' geometry (--level patch): what `viewfactors --patches FILE` writes, as arrays.
void patchGeometry(py::dict& out, const rad::PreparedScene& scene) {
    const rad::Mesh& mesh = scene.mesh();
    const glm::dvec3 origin = scene.scene().origin;
    const std::size_t n = mesh.patches.size();
    Matrix centroids = matrix(n, 3), normals = matrix(n, 3);
    py::array_t<double> corners({n, std::size_t(3), std::size_t(3)});
    std::vector<double> areas(n);
    std::vector<std::uint32_t> surface(n);
    double* c = centroids.mutable_data();
    double* nn = normals.mutable_data();
    double* k = corners.mutable_data();
    for (std::size_t i = 0; i < n; ++i) {
        const rad::Patch& patch = mesh.patches[i];
        glm::dvec3 centroid(0.0);
        for (const glm::vec3& p : patch.p) centroid += glm::dvec3(p) / 3.0;
        centroid += origin;
        for (int a = 0; a < 3; ++a) {
            c[i * 3 + a] = centroid[a];
            nn[i * 3 + a] = patch.normal[a];
            for (int b = 0; b < 3; ++b) k[i * 9 + a * 3 + b] = origin[b] + static_cast<double>(patch.p[a][b]);
        }
        areas[i] = patch.area;
        surface[i] = patch.surface;
    }
    out["patch_centroids"] = centroids;
    out["patch_normals"] = normals;
    out["patch_corners"] = corners;
    out["patch_areas"] = vector(areas);
    out["patch_surfaces"] = vector(surface);
    std::vector<std::string> names;
    for (const rad::MeshSurface& s : mesh.surfaces) names.push_back(s.name);
    out["surface_names"] = names;
}

py::dict viewFactors(const std::vector<std::string>& argv) {
    rad::ViewFactorArgs args;
    const auto commandLine = parse(&rad::addViewFactorsCommand, args, argv);
    rad::ViewFactorRequest request;
    request.method = args.method;
    request.level = args.level;
    request.seed = args.input.seed;
    request.values = args.values;
    args.declared->refuseUnused(rad::viewFactorOptionsUsed(request),
                                "--method " + args.method + " at --level " + args.level);
    const rad::Enforce mode = rad::parseEnforce(args.enforce);
    CollectedWarnings warnings;
    auto table = std::make_shared<Table>();
    py::dict out;
    {
        py::gil_scoped_release release;
        rad::Scene loaded = rad::loadScene(args.input.scene);
        rad::printWarnings(loaded);
        auto check = [&](const rad::PreparedScene& meshed) {
            rad::emitWarnings(rad::viewFactorChecks(meshed.mesh(), request));
        };
        const rad::PreparedScene scene(std::move(loaded), {args.input.patchSize, args.input.maxPatches},
                                       rad::DeviceChoice{rad::deviceForRank(args.input.device, 0)}, check);
        rad::ViewFactorStudy study = rad::computeViewFactorStudy(scene, request);
        rad::emitWarnings(study.warnings);
        const rad::EnforceSummary enforced = rad::enforce(study.table, mode);
        table->table = std::move(study.table);
        py::gil_scoped_acquire acquire;
        out["how"] = study.how;
        out["enforce"] = rad::enforceName(mode);
        out["largest_change"] = enforced.largestChange;
        out["closed_rows"] = enforced.closedRows;
        out["patch_count"] = scene.mesh().patches.size();
        out["device"] = scene.compute().description().name;
        if (args.level == "patch") patchGeometry(out, scene);
    }
    out["names"] = table->table.names;
    out["areas"] = vector(table->table.areas);
    out["missed"] = vector(table->table.missed);
    out["table"] = table;
    out["warnings"] = warnings.list;
    deviceThreads.completed();
    return out;
}

py::dict exchange(const std::vector<std::string>& argv) {
    rad::ExchangeArgs args;
    const auto commandLine = parse(&rad::addExchangeCommand, args, argv);
    // The checks runExchange makes before loading.
    const rad::Enforce mode = rad::parseEnforce(args.enforce);
    if (args.rays < args.batches)
        throw rad::InputError("--rays " + std::to_string(args.rays) + " cannot be split into " +
                              std::to_string(args.batches) + " batches");
    rad::ThermalDefaults defaults;
    if (args.defaultEmissivity > 0.0) {
        if (args.defaultEmissivity > 1.0) throw rad::InputError("--default-emissivity must lie in (0, 1]");
        defaults.emissivity = args.defaultEmissivity;
    }
    if (args.defaultTemperature >= 0.0) defaults.temperature = args.defaultTemperature;
    CollectedWarnings warnings;
    py::dict out;
    {
        py::gil_scoped_release release;
        rad::Scene loaded = rad::loadScene(args.input.scene);
        rad::printWarnings(loaded);
        const std::uint64_t perBatch = args.rays / args.batches;
        std::vector<rad::SurfaceCondition> conditions;
        auto check = [&](const rad::PreparedScene& meshed) {
            std::vector<std::string> names;
            for (const rad::MeshSurface& s : meshed.mesh().surfaces) names.push_back(s.name);
            conditions = rad::readThermalProperties(args.properties, names, defaults);
            rad::emitWarnings(rad::smallReceivers(meshed.mesh(), "shoot", 0, perBatch * args.batches, true));
        };
        const rad::PreparedScene scene(std::move(loaded), {args.input.patchSize, args.input.maxPatches},
                                       rad::DeviceChoice{rad::deviceForRank(args.input.device, 0)}, check);
        rad::ExchangeOptions options;
        options.raysPerSurface = args.rays;
        options.batches = args.batches;
        options.seed = args.input.seed;
        options.enforce = mode;
        options.environmentTemperature = args.environmentTemperature;
        const rad::ExchangeEstimate estimate = rad::estimateExchange(scene, conditions, options);
        const std::vector<std::vector<double>> g = rad::exchangeFactors(estimate.problem);
        rad::emitWarnings(rad::exchangeWarnings(estimate, args.batches));
        std::ostringstream csv, gcsv;
        rad::writeNetHeatCsv(csv, estimate);
        rad::writeExchangeCsv(gcsv, estimate, g);

        py::gil_scoped_acquire acquire;
        const std::size_t n = estimate.table.size();
        std::vector<double> emissivity(n);
        for (std::size_t i = 0; i < n; ++i) emissivity[i] = estimate.problem.conditions[i].emissivity;
        Matrix gm = matrix(n, n), conductors = matrix(n, n);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                gm.mutable_data()[i * n + j] = g[i][j];
                conductors.mutable_data()[i * n + j] = emissivity[i] * estimate.problem.area[i] * g[i][j];
            }
        auto table = std::make_shared<Table>();
        table->table = estimate.table;
        out["names"] = estimate.table.names;
        out["areas"] = vector(estimate.problem.area);
        out["emissivity"] = vector(emissivity);
        out["temperature"] = vector(estimate.solution.temperature);
        out["net_heat"] = vector(estimate.solution.netHeat);
        out["net_flux"] = vector(estimate.solution.netFlux);
        out["radiosity"] = vector(estimate.solution.radiosity);
        out["irradiance"] = vector(estimate.solution.irradiance);
        out["net_heat_stderr"] = vector(estimate.netHeatStandardError);
        out["temperature_stderr"] = vector(estimate.temperatureStandardError);
        out["to_environment"] = estimate.solution.toEnvironment;
        out["exchange_factors"] = gm;
        out["conductors"] = conductors;
        out["view_factors"] = table;
        out["missed"] = vector(estimate.table.missed);
        out["rays_per_surface"] = estimate.raysPerSurface;
        out["enforce"] = rad::enforceName(mode);
        out["largest_change"] = estimate.enforced.largestChange;
        out["closed_rows"] = estimate.enforced.closedRows;
        out["error_bars"] = estimate.errorBars;
        out["csv"] = csv.str();
        out["exchange_csv"] = gcsv.str();
    }
    out["warnings"] = warnings.list;
    deviceThreads.completed();
    return out;
}

// SIGINT and SIGTERM stop a solve after its current batch, as in the program; Python's own
// handlers come back when it returns.
struct InterruptScope {
    struct sigaction oldInt{}, oldTerm{};
    InterruptScope() {
        sigaction(SIGINT, nullptr, &oldInt);
        sigaction(SIGTERM, nullptr, &oldTerm);
        rad::clearInterruptRequest();
    }
    ~InterruptScope() {
        sigaction(SIGINT, &oldInt, nullptr);
        sigaction(SIGTERM, &oldTerm, nullptr);
        rad::clearInterruptRequest();
    }
};

py::dict solve(const std::vector<std::string>& argv) {
    rad::SolveArgs args;
    const auto commandLine = parse(&rad::addSolveCommand, args, argv);
    CollectedWarnings warnings;
    py::dict out;
    {
        py::gil_scoped_release release;
        rad::SolveOutcome outcome;
        {
            InterruptScope interrupts;
            outcome = rad::runSolve(args, rad::oneProcess());
        }
        const rad::PreparedScene& scene = *outcome.scene;
        const rad::Mesh& mesh = scene.mesh();
        const auto& elements = outcome.solution.elements.elements();
        const std::size_t n = elements.size();
        py::gil_scoped_acquire acquire;
        Matrix centroids = matrix(n, 3), normals = matrix(n, 3), rho = matrix(n, 3), b = matrix(n, 3),
               h = matrix(n, 3);
        std::vector<double> area(n);
        std::vector<std::uint32_t> surface(n), patch(n), level(n);
        for (std::size_t e = 0; e < n; ++e) {
            const rad::Element& element = elements[e];
            const rad::Patch& p = mesh.patches[element.patch];
            // As elements.csv: corners relative to the scene's origin in float, the centroid in double.
            const glm::dvec3 centroid = scene.scene().origin + (glm::dvec3(element.p[0]) + glm::dvec3(element.p[1]) +
                                                                glm::dvec3(element.p[2])) /
                                                                   3.0;
            const glm::vec3 r = scene.patches().reflectance[element.patch];
            for (int k = 0; k < 3; ++k) {
                centroids.mutable_data()[e * 3 + k] = centroid[k];
                normals.mutable_data()[e * 3 + k] = p.normal[k];
                rho.mutable_data()[e * 3 + k] = r[k];
                b.mutable_data()[e * 3 + k] = outcome.solution.radiosity[e][k];
                h.mutable_data()[e * 3 + k] =
                    outcome.solution.irradiance.empty() ? 0.0 : outcome.solution.irradiance[e][k];
            }
            area[e] = element.area;
            surface[e] = p.surface;
            patch[e] = element.patch;
            level[e] = element.level;
        }
        std::vector<std::string> names;
        for (const rad::MeshSurface& s : mesh.surfaces) names.push_back(s.name);
        out["report"] = outcome.report;
        out["surface_names"] = names;
        out["element_centroids"] = centroids;
        out["element_normals"] = normals;
        out["element_reflectance"] = rho;
        out["element_radiosity"] = b;
        out["element_irradiance"] = h;
        out["element_areas"] = vector(area);
        out["element_surfaces"] = vector(surface);
        out["element_patches"] = vector(patch);
        out["element_levels"] = vector(level);
        out["output"] = args.output;
    }
    out["warnings"] = warnings.list;
    deviceThreads.completed();
    return out;
}

py::list devices() {
    deviceThreads.use(0);  // lists what the first computation will use
    py::list out;
    for (const rad::DeviceDescription& d : rad::listDevices()) {
        py::dict device;
        device["index"] = d.index;
        device["platform"] = d.platform;
        device["name"] = d.name;
        device["type"] = d.type;
        device["compute_units"] = d.computeUnits;
        device["global_memory"] = d.globalMemory;
        device["version"] = d.version;
        device["driver"] = d.driver;
        out.append(device);
    }
    deviceThreads.completed();
    return out;
}

}  // namespace

PYBIND11_MODULE(_radiosity, m) {
    m.doc() = "The radiosity program's library (use the package `radiosity`, not this module).";
    m.attr("version") = RADIOSITY_VERSION;

    // The package's exception classes (radiosity/errors.py), raised for the library's errors.
    py::module_ errors = py::module_::import("radiosity.errors");
    // Kept for the life of the process (released, so never decremented at exit).
    static const py::handle inputError = py::object(errors.attr("InputError")).release();
    static const py::handle fileError = py::object(errors.attr("FileError")).release();
    static const py::handle runtimeFailure = py::object(errors.attr("RuntimeFailure")).release();
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const rad::FileError& e) {
            py::object error = py::reinterpret_borrow<py::object>(fileError)(e.what());
            error.attr("path") = e.path();
            error.attr("problem") = e.problem();
            PyErr_SetObject(fileError.ptr(), error.ptr());
        } catch (const rad::InputError& e) {
            PyErr_SetString(inputError.ptr(), e.what());
        } catch (const rad::Error& e) {
            PyErr_SetString(runtimeFailure.ptr(), e.what());
        } catch (const std::bad_alloc&) {
            PyErr_SetString(runtimeFailure.ptr(), "out of memory");
        }
    });

    py::class_<Table, std::shared_ptr<Table>>(m, "Table")
        .def("dense", &Table::dense, py::arg("errors") = false)
        .def("csr", &Table::csr, py::arg("errors") = false)
        .def("csv", &Table::csv)
        .def("mtx", &Table::mtx);
    m.def("scene_info", &sceneInfo);
    m.def("view_factors", &viewFactors);
    m.def("exchange", &exchange);
    m.def("solve", &solve);
    m.def("devices", &devices);
}
