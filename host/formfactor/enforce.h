#pragma once
// Corrections that make estimated view factors obey the laws exact ones obey, changing the
// estimates as little as possible and keeping every entry non-negative:
//   reciprocity: A_i F_ij = A_j F_ji. Each pair's two estimates of G_ij = A_i F_ij (from row i
//                and from row j) become their least-variance combination (inverse binomial
//                variances, rays_i / (A_i (1 - F_ij)): the row with the denser rays counts
//                more; equal weights, (G + G^T) / 2, for estimators without rays). Standard
//                errors are those of the combination.
//   closure:     rows of closed surfaces sum to 1: each such row is scaled to sum 1.
//   both:        symmetric and closed: after the reciprocity step, G_ij becomes d_i d_j G_ij,
//                with d found by symmetric Sinkhorn-Knopp iteration so that every closed row
//                sums to its area (open rows keep d = 1). Multiplicative, so zeros stay zero and
//                nothing turns negative; the relative change of each entry is d_i d_j - 1.
// A row is closed when the fraction that reached nothing is at most `closedBelow`.

#include <string>

#include "formfactor/view_factor_table.h"

namespace rad {

enum class Enforce { None, Reciprocity, Closure, Both };
Enforce parseEnforce(const std::string& name);  // throws InputError
const char* enforceName(Enforce mode);

// What every command that estimates view factors (viewfactors, exchange) does unless told
// otherwise: `both`. The estimates then obey reciprocity and closure as the exact factors do, so
// the net heats of a closed scene add up to zero and an open scene's balance holds with what
// leaves it. Open rows (more than `closedBelow` of the row reached nothing: space, or the black
// back of a single-sided face) are not scaled to sum 1: their loss to space keeps what the rays
// found, changed only by the reciprocity step and by the scale of the closed rows they share
// entries with. A row that truly loses less than `closedBelow` is closed (its loss dropped).
inline constexpr Enforce kDefaultEnforce = Enforce::Both;
// --enforce's help text, the same in every command.
const char* enforceHelp();

struct EnforceSummary {
    double largestChange = 0.0;  // max |F'_ij - F_ij|
    std::size_t closedRows = 0;
    int iterations = 0;          // Sinkhorn iterations (both)
};

EnforceSummary enforce(ViewFactorTable& table, Enforce mode, double closedBelow = 1e-3);

}  // namespace rad
