#include "formfactor/patch_matrix.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "cl/buffers.h"
#include "cl/error.h"
#include "formfactor/launch_plan.h"
#include "formfactor/ray_shooter.h"
#include "util/error.h"
#include "shared_math.h"

namespace rad {
namespace {

constexpr double kUnit = 4294967296.0;  // kernels write F in units of 2^-32
constexpr std::uint64_t kRowBufferBytes = 64ull << 20;
// Distinguishes these sample sequences from other estimators' with the same seed.
constexpr std::uint32_t kMatrixStream = 0x5f5e0003u;

using Row = std::vector<std::pair<std::uint32_t, float>>;

// Rows of a batch of shooters: F entries and the fraction that reached no patch.
struct RowBatch {
    std::vector<Row> rows;
    std::vector<float> missed;
    double weightSum = 0.0;  // hemicube: summed over the batch's cubes
};

std::string size(std::uint64_t bytes) {
    if (bytes < (1u << 20)) return std::to_string((bytes + 1023) >> 10) + " KiB";
    return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB";
}

class RowSource {
public:
    virtual ~RowSource() = default;
    virtual std::uint32_t batchSize() const = 0;
    virtual RowBatch rows(const std::vector<cl_uint>& shooters) = 0;
};

class ShootRows : public RowSource {
public:
    ShootRows(ComputeContext& compute, const DeviceScene& scene, const FormFactorOptions& o)
        : compute_(compute), shooter_(compute, scene), options_(o), patches_(scene.patchCount) {}

    std::uint32_t batchSize() const override {
        const std::uint64_t byMemory = kRowBufferBytes / (std::uint64_t{shooter_.columns()} * 4);
        const std::uint64_t byWork = std::max<std::uint64_t>(1, (1u << 22) / options_.raysPerPatch);
        return static_cast<std::uint32_t>(std::clamp<std::uint64_t>(std::min(byMemory, byWork), 1, patches_));
    }

    RowBatch rows(const std::vector<cl_uint>& shooters) override {
        std::vector<RayRequest> requests;
        for (std::uint32_t k = 0; k < shooters.size(); ++k) {
            RayRequest r;
            r.firstTriangle = shooters[k];
            r.rays = options_.raysPerPatch;
            r.scramble = rad_hash2(rad_hash2(options_.seed, kMatrixStream), shooters[k]);
            r.row = k;
            requests.push_back(r);
        }
        const std::size_t count = shooters.size() * shooter_.columns();
        cl::Buffer counts = uploadBuffer(compute_, std::vector<cl_uint>(count, 0), "hit counts", CL_MEM_READ_WRITE);
        const std::vector<Launch> launches = planLaunches(requests, RayShooter::kMaxRaysPerLaunch);
        shooter_.countHits(launches, counts);
        const std::vector<cl_uint> c = readBuffer<cl_uint>(compute_, counts, count);
        RowBatch batch;
        const double rays = options_.raysPerPatch;
        for (std::size_t k = 0; k < shooters.size(); ++k) {
            const cl_uint* row = c.data() + k * shooter_.columns();
            Row entries;
            for (std::uint32_t j = 0; j < patches_; ++j)
                if (row[j] != 0) entries.emplace_back(j, static_cast<float>(row[j] / rays));
            batch.rows.push_back(std::move(entries));
            batch.missed.push_back(static_cast<float>((row[shooter_.escapedColumn()] + row[shooter_.blackColumn()]) / rays));
        }
        return batch;
    }

private:
    ComputeContext& compute_;
    RayShooter shooter_;
    FormFactorOptions options_;
    std::uint32_t patches_;
};

// Hemicube and gather: one kernel writes K x (patchCount + 1) fixed-point values.
class KernelRows : public RowSource {
public:
    KernelRows(ComputeContext& compute, const DeviceScene& scene, const FormFactorOptions& o)
        : compute_(compute), scene_(scene), options_(o), patches_(scene.patchCount) {
        const bool hemicube = o.method == FormFactorMethod::Hemicube;
        kernel_ = scene.kernel(compute.program(hemicube ? "hemicube.cl" : "gather.cl"), hemicube ? "hemicube_rows" : "gather_rows");
    }

    std::uint32_t batchSize() const override {
        const std::uint64_t byMemory = kRowBufferBytes / ((std::uint64_t{patches_} + 1) * 4);
        const std::uint64_t perShooter =
            options_.method == FormFactorMethod::Hemicube
                ? 3ull * options_.hemicubeResolution * options_.hemicubeResolution
                : std::uint64_t{patches_} * 3 * std::max(1u, options_.shadowRays);
        const std::uint64_t byWork = std::max<std::uint64_t>(1, (1ull << 24) / perShooter);
        return static_cast<std::uint32_t>(std::clamp<std::uint64_t>(std::min(byMemory, byWork), 1, patches_));
    }

    RowBatch rows(const std::vector<cl_uint>& shooters) override {
        const std::size_t count = shooters.size() * (std::size_t{patches_} + 1);
        std::vector<cl_uint> values(count, 0);
        try {
            cl::Buffer list = uploadBuffer(compute_, shooters, "shooter list");
            cl::Buffer out = uploadBuffer(compute_, values, "form-factor rows", CL_MEM_READ_WRITE);
            const auto k = static_cast<cl_uint>(shooters.size());
            if (options_.method == FormFactorMethod::Hemicube) {
                setKernelArgs(kernel_, DeviceScene::kArguments, list, k, static_cast<cl_uint>(options_.hemicubeResolution),
                              static_cast<cl_uint>(options_.hemicubeJitter ? rad_hash2(options_.seed, kMatrixStream) | 1u : 0u),
                              static_cast<cl_uint>(patches_), out);
                compute_.launch(kernel_, std::size_t{k} * 3 * options_.hemicubeResolution * options_.hemicubeResolution);
            } else {
                setKernelArgs(kernel_, DeviceScene::kArguments, list, k, static_cast<cl_uint>(options_.shadowRays),
                              static_cast<cl_uint>(rad_hash2(options_.seed, kMatrixStream)), static_cast<cl_uint>(patches_), out);
                compute_.launch(kernel_, std::size_t{k} * patches_);
            }
            values = readBuffer<cl_uint>(compute_, out, count);
        } catch (const cl::Error& e) {
            throwDeviceError(e, std::string("computing ") + methodName(options_.method) + " form factors");
        }
        RowBatch batch;
        for (std::size_t r = 0; r < shooters.size(); ++r) {
            const cl_uint* row = values.data() + r * (std::size_t{patches_} + 1);
            // The hemicube's rows hold delta form factors whose sum differs from 1 by the cube's
            // discretisation: renormalise by that sum (missed pixels included). Gather rows are
            // form factors already; what they do not account for counts as missed.
            double total = options_.method == FormFactorMethod::Hemicube
                               ? std::accumulate(row, row + patches_ + 1, 0.0)
                               : kUnit;
            if (!(total > 0.0)) total = kUnit;
            Row entries;
            double sum = 0.0;
            for (std::uint32_t j = 0; j < patches_; ++j)
                if (row[j] != 0) {
                    entries.emplace_back(j, static_cast<float>(row[j] / total));
                    sum += row[j] / total;
                }
            batch.rows.push_back(std::move(entries));
            batch.missed.push_back(options_.method == FormFactorMethod::Hemicube ? static_cast<float>(row[patches_] / total)
                                                                                 : static_cast<float>(std::max(0.0, 1.0 - sum)));
            batch.weightSum += total / kUnit;
        }
        return batch;
    }

private:
    ComputeContext& compute_;
    const DeviceScene& scene_;
    FormFactorOptions options_;
    std::uint32_t patches_;
    cl::Kernel kernel_;
};

}  // namespace

const char* methodName(FormFactorMethod method) {
    switch (method) {
        case FormFactorMethod::Shoot: return "shoot";
        case FormFactorMethod::Hemicube: return "hemicube";
        case FormFactorMethod::Gather: return "gather";
    }
    return "unknown";
}

FormFactorMethod parseMethod(const std::string& name) {
    if (name == "shoot") return FormFactorMethod::Shoot;
    if (name == "hemicube") return FormFactorMethod::Hemicube;
    if (name == "gather") return FormFactorMethod::Gather;
    throw InputError("--method " + name + ": use shoot, hemicube or gather");
}

PatchMatrix buildPatchMatrix(const PreparedScene& prepared, const FormFactorOptions& options) {
    ComputeContext& compute = prepared.compute();
    const Mesh& mesh = prepared.mesh();
    const DeviceScene& scene = prepared.device();
    if (options.method == FormFactorMethod::Hemicube && (options.hemicubeResolution < 2 || options.hemicubeResolution % 2 != 0))
        throw InputError("--hemicube-res must be an even number of at least 2 (the sides are R x R/2)");
    const auto patches = static_cast<std::uint32_t>(mesh.patches.size());
    std::unique_ptr<RowSource> source;
    if (options.method == FormFactorMethod::Shoot) source = std::make_unique<ShootRows>(compute, scene, options);
    else source = std::make_unique<KernelRows>(compute, scene, options);

    PatchMatrix matrix;
    matrix.F.columns = patches;
    double weightSum = 0.0;
    // Where even a dense matrix would fit there is nothing to guard; otherwise small batches
    // let the projection below refuse early, before much work is spent.
    const double dense = 8.0 * patches * static_cast<double>(patches);
    std::uint32_t batch = source->batchSize();
    if (dense > static_cast<double>(options.maxMemory)) batch = std::min(batch, std::max(1u, patches / 32));
    for (std::uint32_t first = 0; first < patches; first += batch) {
        std::vector<cl_uint> shooters(std::min(batch, patches - first));
        std::iota(shooters.begin(), shooters.end(), first);
        RowBatch rows = source->rows(shooters);
        for (std::size_t k = 0; k < rows.rows.size(); ++k) {
            matrix.F.appendRow(rows.rows[k]);
            matrix.missed.push_back(rows.missed[k]);
        }
        weightSum += rows.weightSum;
        // Refuse as soon as the rows so far say the whole matrix will not fit.
        const std::uint32_t done = matrix.F.rows();
        const double projected = static_cast<double>(matrix.F.bytes()) * patches / done;
        if (projected > static_cast<double>(options.maxMemory))
            throw InputError("the " + std::string(methodName(options.method)) + " form-factor matrix of " +
                             std::to_string(patches) + " patches would need about " +
                             size(static_cast<std::uint64_t>(projected)) + " (" + std::to_string(matrix.F.nonZeros()) +
                             " non-zeros in the first " + std::to_string(done) + " rows); --max-memory allows " +
                             size(options.maxMemory));
    }
    if (options.method == FormFactorMethod::Hemicube) matrix.weightSum = weightSum / std::max(1u, patches);
    return matrix;
}

}  // namespace rad
