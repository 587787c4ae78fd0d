#pragma once
// What `radiosity viewfactors` computes, for the command and the Python module alike: at
// --level surface with --method shoot, rays from whole surfaces (--rays each, or rounds until
// --target-error); otherwise the chosen method's patch matrix, per patch or summed up per
// surface. The table comes back as estimated; correcting it (enforce.h) and writing it are the
// caller's.

#include <cstdint>
#include <string>
#include <vector>

#include "formfactor/patch_matrix.h"
#include "formfactor/surface_view_factors.h"
#include "formfactor/view_factor_table.h"
#include "mesh/mesh.h"
#include "parallel/process_group.h"
#include "prepared/prepared_scene.h"
#include "util/options.h"

namespace rad {

// Surface shooting's own options (--method shoot at --level surface).
extern const OptionSpec kSurfaceRaysOption;   // --rays, per surface
extern const OptionSpec kTargetErrorOption;   // --target-error
extern const OptionSpec kMaxRaysOption;       // --max-rays, with --target-error

struct ViewFactorRequest {
    std::string method = "shoot";   // a form-factor method (formfactor/estimator.h)
    std::string level = "surface";  // surface | patch
    std::uint32_t seed = 1;
    OptionValues values;  // the methods' options, surface shooting's and --max-memory; defaults where not given
};

// --method shoot at --level surface: rays from whole surfaces, no patch matrix.
bool shootsFromSurfaces(const ViewFactorRequest& request);
// The options the request reads, for DeclaredOptions::refuseUnused.
std::vector<OptionSpec> viewFactorOptionsUsed(const ViewFactorRequest& request);
// Warnings from the mesh alone, before the device work (small receivers, near fields).
std::vector<std::string> viewFactorChecks(const Mesh& mesh, const ViewFactorRequest& request);

struct ViewFactorStudy {
    ViewFactorTable table;              // as estimated, not corrected
    std::string how;                    // a few words for the summary: "1000000 rays per surface"
    std::vector<std::string> warnings;  // rays lost on black backs; a --target-error not reached
};

// Every process of `group` ends with the same table, bitwise one process's.
ViewFactorStudy computeViewFactorStudy(const PreparedScene& scene, const ViewFactorRequest& request,
                                       const ProcessGroup& group = oneProcess());

// Rays that end on the back of a single-sided face count toward no surface: the row's factors
// then sum to less than what the surface sees. Warnings for the surfaces that lost more than
// 0.1 % of their rays so (surface_view_factors.h's blackBackWarnings): from surface shooting,
// or from a patch matrix by rays (per surface side, its patches' shares weighted by area; none
// for matrices that do not count them).
std::vector<std::string> blackBackWarnings(const SurfaceViewFactors& factors);
std::vector<std::string> blackBackWarnings(const Mesh& mesh, const PatchMatrix& matrix);

}  // namespace rad
