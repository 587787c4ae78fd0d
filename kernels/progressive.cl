/* Progressive refinement in power form, around a batch of shots.
 *   prepare_shooters: before the shots, each shooter's elements get their shares of its rays,
 *               in proportion to the unshot power each holds (incident[e].w, the sum over
 *               channels), and give that power up to the shot;
 * shoot.cl's shoot_power then adds, for every element e, the power the batch's rays delivered
 * to it (64-bit fixed point per channel; columns elementCount and elementCount + 1 hold what
 * left the scene and what died on black backs; with mirrors or glass in the scene, columns
 * elementCount + 2 + e once more what reached e by way of them), into one set of counters or, on
 * PoCL's CPU device, one set per thread, which the gather adds. Then:
 *   take_shots: each shooter's unshot power loses what its rays carried (negative when an
 *               overshooting solve shot light the patch has not yet received: it owes it);
 *   gather:     each element e of patch j receives its delivered power P_e (only those the
 *               shots marked touched: shared_types.h): incident_e += P_e,
 *               its own unshot power (incident_e.w) grows by the sum over channels of
 *               rho_j P_e, and unshot_j += rho_j (sum of P_e over j's elements); caustic_e
 *               adds the part of P_e that came by way of mirrors or glass; and the unshot
 *               power is reduced for the host.
 * Work item g of gather owns the clusters of patches g, g + G, g + 2G, ... (G work items;
 * mesh/patch_clusters.h, a patch of its own where none is small): it reports the sum of their
 * patches' unshot power and the cluster with the most power to shoot, so the host reads G
 * partials, not every patch.
 *   member_powers: the power to shoot of each patch of the clusters the host chose, which it
 *               shares the cluster's rays out by.
 * Overshooting (solver/amplification.h): a patch's power to shoot is its unshot power
 * plus rho_j A_j K, K (per channel) the irradiance the host expects the unshot power still to
 * bring; with K = 0 it is the unshot power, bit for bit. A cluster's is the sum of its patches'.
 * The order of every floating-point operation is fixed: results do not depend on how many
 * threads run the work items. */
#pragma OPENCL FP_CONTRACT OFF

#include "kernel_args.h"
#include "fixed_point.h"

/* ends: per element, the end of its share of 2^32 within its patch (the last is implied). With
 * no unshot power on record (a state from before elements held theirs), shares follow area:
 * an element's area is its patch's times scale^2. */
__kernel void prepare_shooters(RAD_KERNEL_PARAMS(RAD_PREPARE_SHOOTERS_ARGS)) {
    const uint k = get_global_id(0);
    if (k >= shooterCount) return;
    const uint patch = shooters[k].patch;
    const uint first = elementStart[patch], last = elementStart[patch + 1u];
    /* Elements that owe power (negative, after an overshooting solve's corrections) get none. */
    float total = 0.0f;
    for (uint e = first; e < last; ++e) total += fmax(incident[e].w, 0.0f);
    const bool byArea = !(total > 0.0f);
    if (byArea) {
        total = 0.0f;
        for (uint e = first; e < last; ++e) total += frames[e].z * frames[e].z;
    }
    float sum = 0.0f;
    for (uint e = first; e < last; ++e) {
        sum += byArea ? frames[e].z * frames[e].z : fmax(incident[e].w, 0.0f);
        /* Saturating: 4294967295.0f is 2^32 in float, and converting 2^32 with a plain cast is
         * undefined; PoCL's AVX-512 and AVX2 builds gave 2^32 - 1 and 0 for it (an element
         * before others of no power), so the solve's bits depended on the CPU. */
        ends[e] = convert_uint_sat(sum / total * 4294967296.0f);
        incident[e].w = 0.0f;
    }
}

/* A shot takes at most what the shooter had, either way (makeShooter rounds towards zero), so
 * the difference keeps the sign of what it had: owed power stays owed until it is shot back. */
__kernel void take_shots(RAD_KERNEL_PARAMS(RAD_TAKE_SHOTS_ARGS)) {
    const uint k = get_global_id(0);
    if (k >= shooterCount) return;
    const uint patch = shooters[k].patch;
    unshot[patch] = unshot[patch] - vload4(0, shooters[k].taken);
}

/* The power delivered to `column`, summed over the `sets` counter sets (`stride` columns
 * apart; shoot.cl's shoot_power), modulo 2^64 as the device added it; zeroes them all. */
inline float4 delivered(__global uint* power, size_t column, float quantum, uint sets, uint stride) {
    uint total[6] = {0u, 0u, 0u, 0u, 0u, 0u};
    for (uint k = 0; k < sets; ++k) {
        __global uint* p = power + ((size_t)k * stride + column) * 6u;
        for (int c = 0; c < 3; ++c) {
            const uint lo = total[2 * c] + p[2 * c];
            total[2 * c + 1] += p[2 * c + 1] + (lo < total[2 * c] ? 1u : 0u);
            total[2 * c] = lo;
        }
        for (int i = 0; i < 6; ++i) p[i] = 0u;
    }
    return (float4)(fixed_to_float(total[0], total[1], quantum), fixed_to_float(total[2], total[3], quantum),
                    fixed_to_float(total[4], total[5], quantum), 0.0f);
}

/* Patch j's power to shoot: its unshot power plus what overshooting adds (the same bits in
 * gather and member_powers). */
inline float4 power_to_shoot(float4 left, float4 rho, float area, float4 overshoot) {
    return left + rho * (area * overshoot);
}

__kernel void gather(RAD_KERNEL_PARAMS(RAD_GATHER_ARGS)) {
    const uint g = get_global_id(0);
    if (g >= workItems) return;
    float sum = 0.0f;
    float4 sums = (float4)(0.0f);
    float4 largest = (float4)(0.0f, 0.0f, 0.0f, -1.0f);
    uint largestCluster = 0u;
    for (uint cluster = g; cluster < clusterCount; cluster += workItems) {
        float4 clusterPower = (float4)(0.0f);
        for (uint m = clusterStart[cluster]; m < clusterStart[cluster + 1u]; ++m) {
            const uint j = clusterMembers[m];
            /* Elements receive; what they receive is also their patch's, to shoot on. */
            const float4 rho = reflectance[j];
            float4 arriving = (float4)(0.0f);
            for (uint e = elementStart[j]; e < elementStart[j + 1u]; ++e) {
                /* No shot reached its block: its counters are all 0, as `delivered` left them. */
                if (touched[e >> RAD_TOUCHED_SHIFT] == 0u) continue;
                const float4 a = delivered(power, e, quantum, sets, columns);
                if (columns > elementCount + 2u) { /* specular transport: what came by specular paths */
                    const float4 c = delivered(power, elementCount + 2u + e, quantum, sets, columns);
                    if (c.x != 0.0f || c.y != 0.0f || c.z != 0.0f) caustic[e] += c;
                }
                if (a.x != 0.0f || a.y != 0.0f || a.z != 0.0f) {
                    const float4 reflected = rho * a;
                    incident[e] += (float4)(a.xyz, reflected.x + reflected.y + reflected.z);
                    arriving += a;
                }
            }
            float4 left = unshot[j];
            if (arriving.x != 0.0f || arriving.y != 0.0f || arriving.z != 0.0f) {
                left += rho * arriving;
                unshot[j] = left;
            }
            sum += fabs(left.x) + fabs(left.y) + fabs(left.z);
            sums += left;
            const float4 toShoot = power_to_shoot(left, rho, patchArea[j], overshoot);
            /* A cluster of one patch reports the patch's power itself, bit for bit. */
            clusterPower = m == clusterStart[cluster] ? toShoot : clusterPower + toShoot;
        }
        const float magnitude = fabs(clusterPower.x) + fabs(clusterPower.y) + fabs(clusterPower.z);
        if (magnitude > largest.w) {
            largest = (float4)(clusterPower.xyz, magnitude);
            largestCluster = cluster;
        }
    }
    vstore4(largest, 0, partials[g].largest);
    vstore4(sums, 0, partials[g].sums);
    partials[g].unshotSum = sum;
    partials[g].largestCluster = largestCluster;
    partials[g].pad[0] = 0u;
    partials[g].pad[1] = 0u;
    if (g == 0u) {
        /* What left the scene, and what black backs absorbed, in this batch. */
        lost[0] = delivered(power, elementCount, quantum, sets, columns);
        lost[1] = delivered(power, elementCount + 1u, quantum, sets, columns);
    }
}

/* powers[i]: the power to shoot of patch patches[i], as gather measured it. */
__kernel void member_powers(RAD_KERNEL_PARAMS(RAD_MEMBER_POWERS_ARGS)) {
    const uint i = get_global_id(0);
    if (i >= patchCount) return;
    const uint j = patches[i];
    powers[i] = power_to_shoot(unshot[j], reflectance[j], patchArea[j], overshoot);
}
