#pragma once
// The whole patch-to-patch form-factor matrix, by any of the three estimators, on the device:
//   shoot    - stratified rays from each patch (shoot.cl), F_ij = hits_j / rays;
//   hemicube - a hemicube of R x R pixels over each patch's centre (hemicube.cl), F_ij = the
//              delta form factors of the pixels that see j, renormalised to sum to 1;
//   gather   - point-to-polygon closed forms at three points of each receiver times the
//              visible fraction by shadow rays (gather.cl), F_ij = F_ji A_j / A_i.
// Rows are computed in batches of shooters and stored sparsely. Used by the full-matrix
// solvers and by patch-level view factors.

#include <cstdint>
#include <string>
#include <vector>

#include "formfactor/sparse_matrix.h"
#include "prepared/prepared_scene.h"

namespace rad {

enum class FormFactorMethod { Shoot, Hemicube, Gather };
const char* methodName(FormFactorMethod method);
FormFactorMethod parseMethod(const std::string& name);  // throws InputError

struct FormFactorOptions {
    FormFactorMethod method = FormFactorMethod::Shoot;
    std::uint32_t raysPerPatch = 4096;        // shoot
    std::uint32_t hemicubeResolution = 128;   // hemicube: pixels along the top face's edge (even)
    bool hemicubeJitter = false;              // hemicube: turn the cube by a random angle per patch
    std::uint32_t shadowRays = 16;            // gather: per receiver point
    std::uint32_t seed = 1;
    std::uint64_t maxMemory = 4ull << 30;     // bytes the matrix may take
};

struct PatchMatrix {
    SparseMatrix F;                 // F(i, j): the fraction of the power leaving patch i that reaches j
    std::vector<float> missed;      // per row: the fraction that reached no patch (escaped, or a black back)
    double weightSum = 0.0;         // hemicube: mean sum of a cube's delta form factors before renormalising
};

// Throws InputError when the matrix would exceed options.maxMemory (with the figure).
PatchMatrix buildPatchMatrix(const PreparedScene& scene, const FormFactorOptions& options);

}  // namespace rad
