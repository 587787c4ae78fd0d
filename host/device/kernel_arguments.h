#pragma once
// The host's side of every kernel's own parameters (kernels/kernel_args.h): one struct per
// pack, with the kernel's parameter names as fields, bound in the pack's order by DeviceKernel
// (cl/kernel_pack.h). The scene's pack is DeviceScene's (device/device_scene.h).

#include "cl/kernel_pack.h"
#include "kernel_args.h"
#include "shared_types.h"

namespace rad {

RAD_HOST_PACK(ShootArgs, RAD_SHOOT_ARGS)
RAD_HOST_PACK(ShootPowerArgs, RAD_SHOOT_POWER_ARGS)
RAD_HOST_PACK(LightCausticsArgs, RAD_LIGHT_CAUSTICS_ARGS)
RAD_HOST_PACK(PrepareShootersArgs, RAD_PREPARE_SHOOTERS_ARGS)
RAD_HOST_PACK(TakeShotsArgs, RAD_TAKE_SHOTS_ARGS)
RAD_HOST_PACK(GatherArgs, RAD_GATHER_ARGS)
RAD_HOST_PACK(MemberPowersArgs, RAD_MEMBER_POWERS_ARGS)
RAD_HOST_PACK(GatherRowsArgs, RAD_GATHER_ROWS_ARGS)
RAD_HOST_PACK(HemicubeRowsArgs, RAD_HEMICUBE_ROWS_ARGS)
RAD_HOST_PACK(PunctualDirectArgs, RAD_PUNCTUAL_DIRECT_ARGS)
RAD_HOST_PACK(EnvironmentDirectArgs, RAD_ENVIRONMENT_DIRECT_ARGS)
RAD_HOST_PACK(DirectVariationArgs, RAD_DIRECT_VARIATION_ARGS)
RAD_HOST_PACK(RenderArgs, RAD_RENDER_ARGS)
RAD_HOST_PACK(ViewPassArgs, RAD_VIEW_PASS_ARGS)
RAD_HOST_PACK(ElementIndirectArgs, RAD_ELEMENT_INDIRECT_ARGS)
RAD_HOST_PACK(LightmapTexelsArgs, RAD_LIGHTMAP_TEXELS_ARGS)
RAD_HOST_PACK(PathtraceArgs, RAD_PATHTRACE_ARGS)
RAD_HOST_PACK(ProbeFixedPartArgs, RAD_PROBE_FIXED_PART_ARGS)
RAD_HOST_PACK(ProbePickArgs, RAD_PROBE_PICK_ARGS)
RAD_HOST_PACK(ProbeGridCellArgs, RAD_PROBE_GRID_CELL_ARGS)
RAD_HOST_PACK(ProbeLocateElementArgs, RAD_PROBE_LOCATE_ELEMENT_ARGS)
RAD_HOST_PACK(ProbeTraceArgs, RAD_PROBE_TRACE_ARGS)
RAD_HOST_PACK(ProbeShaftArgs, RAD_PROBE_SHAFT_ARGS)
RAD_HOST_PACK(ProbeLightsArgs, RAD_PROBE_LIGHTS_ARGS)
RAD_HOST_PACK(ProbeSamplesArgs, RAD_PROBE_SAMPLES_ARGS)
RAD_HOST_PACK(ProbeMapsArgs, RAD_PROBE_MAPS_ARGS)
RAD_HOST_PACK(ProbeEnvironmentArgs, RAD_PROBE_ENVIRONMENT_ARGS)
RAD_HOST_PACK(ProbeGlossyArgs, RAD_PROBE_GLOSSY_ARGS)

// The solution's pack a path reads (kernels/view_path.h), which the camera pass and the lightmap
// bind before their own: ViewPathInputs (render/view_path_inputs.h) fills it.
RAD_HOST_PACK(ViewSolutionArgs, RAD_VIEW_SOLUTION_ARGS)

}  // namespace rad
