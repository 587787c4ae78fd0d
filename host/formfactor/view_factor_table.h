#pragma once
// View factors as users read them: named rows (surfaces or patches), each a sparse list of
// (to, F, standard error), the fraction of the row that reached nothing, and the areas that
// reciprocity needs. Built from surface shooting or from a patch matrix; written as CSV or
// Matrix Market; corrected for reciprocity and closure on request (enforce.h).

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "formfactor/patch_matrix.h"
#include "formfactor/surface_view_factors.h"
#include "mesh/mesh.h"

namespace rad {

struct ViewFactorEntry {
    std::uint32_t to = 0;
    double factor = 0.0;
    double standardError = std::numeric_limits<double>::quiet_NaN();  // NaN: no statistical estimate
};

struct ViewFactorTable {
    std::vector<std::string> names;
    std::vector<double> areas;                     // m^2
    std::vector<std::vector<ViewFactorEntry>> rows;  // by `to`, ascending
    std::vector<double> missed;                    // per row: the fraction that reached nothing
    // per row: the standard error of `missed` (binomial, from the row's rays; NaN where the
    // estimator gives no statistical error). Before enforce(), `missed` is 1 - the row's sum:
    // the share that leaves to space (or stops on the black back of a single-sided face).
    std::vector<double> missedError;
    // per row: how many independent rays its estimates amount to, so that the variance of an
    // entry is about F (1 - F) / rays (for rows built from patches of unequal area, Kish's
    // effective count); 0 or absent where the estimator gives no statistical error (hemicube,
    // gather). Reciprocity (enforce.h) weighs the two estimates of A_i F_ij = A_j F_ji by it.
    std::vector<double> rays;

    std::size_t size() const { return names.size(); }
    double factor(std::size_t from, std::size_t to) const;  // 0 where nothing is stored
};

// Per row, what left to space: 1 - the row's sum before any correction, and its standard error.
// Taken from a table before enforce(), which sets the share of closed rows to 0.
struct SpaceShares {
    std::vector<double> share, standardError;
};
SpaceShares spaceShares(const ViewFactorTable& uncorrected);

// Surface rows from surface shooting (with their binomial standard errors).
ViewFactorTable surfaceTable(const SurfaceViewFactors& factors);

// Surface rows aggregated from a patch matrix: F_ST = sum over i in S of (A_i / A_S) sum over j
// in T of F_ij. Matrices of ray counts (PatchMatrix::raysPerRow) carry the binomial error of
// their rays; others none.
ViewFactorTable surfaceTable(const Mesh& mesh, const PatchMatrix& matrix);

// Patch rows, named "<surface>#<k>" (the k-th patch of that surface side).
ViewFactorTable patchTable(const Mesh& mesh, const PatchMatrix& matrix);

// A patch's name in patch tables: its side of a surface and its number there ("floor#12").
std::string patchName(const Mesh& mesh, std::size_t patch);

}  // namespace rad
