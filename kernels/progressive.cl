/* Progressive refinement in power form: the updates after a batch of shots. shoot.cl's
 * shoot_power has added, for every patch j, the power the batch's rays delivered to it (64-bit
 * fixed point per channel; columns patchCount and patchCount + 1 hold what left the scene and
 * what died on black backs). Then:
 *   take_shots: each shooter's unshot power loses what its rays carried;
 *   gather:     each patch j receives its delivered power P_j: incident_j += P_j and
 *               unshot_j += rho_j P_j; and the unshot power is reduced for the host.
 * Work item g of gather owns the patches g, g + G, g + 2G, ... (G work items): it reports the
 * sum of their unshot power and the largest, so the host reads G partials, not every patch.
 * The order of every floating-point operation is fixed: results do not depend on how many
 * threads run the work items. */
#pragma OPENCL FP_CONTRACT OFF

#include "shared_types.h"
#include "fixed_point.h"

__kernel void take_shots(__global const Shooter* shooters, uint shooterCount, __global float4* unshot) {
    const uint k = get_global_id(0);
    if (k >= shooterCount) return;
    const uint patch = shooters[k].patch;
    unshot[patch] = fmax(unshot[patch] - vload4(0, shooters[k].taken), (float4)(0.0f));
}

inline float4 delivered(__global uint* power, size_t column, float quantum) {
    __global uint* p = power + column * 6u;
    const float4 value = (float4)(fixed_to_float(p[0], p[1], quantum), fixed_to_float(p[2], p[3], quantum),
                                  fixed_to_float(p[4], p[5], quantum), 0.0f);
    for (int i = 0; i < 6; ++i) p[i] = 0u;
    return value;
}

__kernel void gather(__global uint* power, float quantum, __global const float4* reflectance,
                     __global float4* incident, __global float4* unshot, uint patchCount, uint workItems,
                     __global UnshotPartial* partials, __global float4* lost) {
    const uint g = get_global_id(0);
    if (g >= workItems) return;
    float sum = 0.0f;
    float4 largest = (float4)(0.0f, 0.0f, 0.0f, -1.0f);
    uint largestPatch = 0u;
    for (uint j = g; j < patchCount; j += workItems) {
        const float4 arriving = delivered(power, j, quantum);
        float4 left = unshot[j];
        if (arriving.x != 0.0f || arriving.y != 0.0f || arriving.z != 0.0f) {
            incident[j] += arriving;
            left += reflectance[j] * arriving;
            unshot[j] = left;
        }
        const float total = left.x + left.y + left.z;
        sum += total;
        if (total > largest.w) {
            largest = (float4)(left.xyz, total);
            largestPatch = j;
        }
    }
    vstore4(largest, 0, partials[g].largest);
    partials[g].unshotSum = sum;
    partials[g].largestPatch = largestPatch;
    partials[g].pad[0] = 0u;
    partials[g].pad[1] = 0u;
    if (g == 0u) {
        /* What left the scene, and what black backs absorbed, in this batch. */
        lost[0] = delivered(power, patchCount, quantum);
        lost[1] = delivered(power, patchCount + 1u, quantum);
    }
}
