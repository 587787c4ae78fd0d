/* A lightmap's texels (host/lightmap/texel_bake.h): per texel, the light arriving at its
 * footprint on the surface, as the camera pass finds it at a pixel's point (view_path.h).
 *
 * A texel's footprint is what the surface holds of it: pieces of faces (TexelPiece), never a
 * point outside them, so a texel whose square reaches past the chart's edge, into a wall that
 * meets it or below a floor it stands on, samples only its own surface. Within a face, though,
 * something may stand on the surface: a wall on a floor, a box on a table. A texel then stands
 * for one side of that contact, the side of its anchor (TexelAnchor: the footprint's point
 * nearest the texel's centre): a sample counts only where a segment from the anchor to it, just
 * above the surface, meets no face of another chart. So a texel centred in a wall's shadow
 * averages only the shadow, and one centred under a box only the dark under it; the texels'
 * values change across the contact within one texel, as bilinear filtering between their
 * centres shows them, without one side's light averaged into the other's texel.
 *
 * Sample s of texel k is a point of its footprint, uniform by area (one number picks the piece
 * by its share, and, rescaled, draws the point with a second), the sequences keyed by (seed,
 * key k) as a pixel's are (rng.h, path_sample); so a texel's value depends on the seed, its key
 * and the sample count only.
 *
 * At the point, the path starts on the face's baked side (its front, or for a double-sided face
 * the side its chart received more light on in the solution: host/lightmap/texel_bake.h) as at
 * a camera's hit, shading it as a white diffuse surface without emission: it returns E / pi, E
 * the irradiance (direct light by light sampling, plus the solution's indirect light
 * interpolated (direct mode) or gathered (final gather), plus what came by way of mirrors and
 * glass). The texel's radiance is what a
 * camera would see of a diffuse point: Le + rho E / pi with the material (and its textures) at
 * that point; on a mirror, rough metal or glass face, whose look depends on the view, Le only.
 *
 * A texel whose anchor lies inside something closed (the floor under a box standing on it, a
 * plate under a bolt's head) sees only the black backs of single-sided faces around it: its
 * light is the dark inside, which bilinear filtering would spread half a texel onto the surface
 * outside. Its anchor casts RAD_LIGHTMAP_PROBES cosine-distributed rays; where every one meets a
 * black back, no sample counts, so the texel stays empty and takes its value from its
 * neighbours as gutters do (host/lightmap/texel_fill.h). One open direction keeps it: the
 * floor behind a single-sided wall, or a wall's part below a floor, sees the sky or the space
 * below too. Inside closed double-sided faces, which have no black side, nothing is found. */
#pragma OPENCL FP_CONTRACT OFF

#include "kernel_args.h"
#include "view_path.h"

/* The unit normal of the side of `face` the lightmap holds. */
inline float3 baked_normal(__global const FaceInfo* faces, __global const uint* chartOfFace, uint face) {
    const float3 n = vload3(0, faces[face].normal);
    return (chartOfFace[face] & RAD_LIGHTMAP_BACK) != 0u ? -n : n;
}

/* The point of face `face` at barycentrics (b1, b2); its corners from faceCorners (xyz, three
 * per face). */
inline float3 face_point(__global const float4* faceCorners, uint face, float b1, float b2) {
    const float3 v0 = faceCorners[3u * face].xyz, v1 = faceCorners[3u * face + 1u].xyz,
                 v2 = faceCorners[3u * face + 2u].xyz;
    return v0 + b1 * (v1 - v0) + b2 * (v2 - v0);
}

#define RAD_LIGHTMAP_PROBES 8u

/* Whether every one of RAD_LIGHTMAP_PROBES cosine-distributed rays from `from` about the normal
 * n (in strata of 4 x 2, keyed by the texel) meets the black back of a face. */
inline bool enclosed_by_backs(const ViewPath* path, float3 from, float3 n, uint seed, uint key, uint* traced) {
    float3 t, b;
    frame_about(n, &t, &b);
    for (uint i = 0u; i < RAD_LIGHTMAP_PROBES; ++i) {
        const uint4 u = path_sample(seed, key, RAD_KEY_TEXEL_PROBE, i);
        const float2 cell = (float2)((float)(i & 3u) + unit_float(u.x), (float)(i >> 2) + unit_float(u.y));
        const float3 d = cosine_hemisphere(cell * (float2)(0.25f, 0.5f));
        const float3 dir = d.x * t + d.y * b + d.z * n;
        const Hit hit = trace_closest(&path->scene.geometry, from, dir);
        ++*traced;
        if (hit.face < 0) return false;
        __global const FaceInfo* face = &path->scene.geometry.faces[hit.face];
        const bool front = dot3(dir, vload3(0, face->normal)) < 0.0f;
        const uint kind = material_kind(&path->scene, hit.face);
        if (!material_black_side(kind, (front ? face->frontPatch : face->backPatch) != RAD_NO_PATCH)) return false;
    }
    return true;
}

/* texelCount texels of the lightmap, texel t's sequences keyed by texelKeys[t] (its index in the
 * whole lightmap), its pieces pieces[pieceEnds[t - 1] .. pieceEnds[t] - 1] (from 0 for t = 0)
 * and its anchor anchors[t]. chartOfFace: per face, its chart, with RAD_LIGHTMAP_BACK set where
 * the face is baked on its back side. enclosure[t]: 0 until the anchor's probes have been cast
 * (the host clears it before a texel's first launch), then 1 where they found open space and 2
 * where only black backs, so that later launches of the same texels do not cast them again.
 * Writes, not adds, for samples
 * firstSample .. firstSample + sampleCount - 1: irradiance[t] (rgb: E summed over the samples
 * that count; w: the sum of the squares of E's luminance), radiance[t] (rgb: summed; w: how many
 * samples counted), rays[t]. */
__kernel void lightmap_texels(RAD_KERNEL_PARAMS(RAD_LIGHTMAP_TEXELS_KERNEL)) {
    const uint t = get_global_id(0);
    if (t >= texelCount) return;
    const ViewPath path = RAD_VIEW_PATH(mode, seed, near);
    const float lift = path.lift;
    const uint begin = t == 0u ? 0u : pieceEnds[t - 1u], end = pieceEnds[t];
    const uint key = texelKeys[t];
    float3 sumE = (float3)(0.0f), sumL = (float3)(0.0f);
    float squares = 0.0f;
    uint traced = 0u, counted = 0u;
    /* the anchor, lifted off its face as the path lifts its points */
    const TexelAnchor anchor = anchors[t];
    const uint anchorChart = chartOfFace[anchor.face] & ~RAD_LIGHTMAP_BACK;
    float3 fromAnchor = face_point(faceCorners, anchor.face, anchor.b1, anchor.b2);
    const float anchorLift = ray_offset(fromAnchor, fromAnchor, lift);
    fromAnchor += anchorLift * baked_normal(faces, chartOfFace, anchor.face);
    uint enclosedState = enclosure[t];
    if (begin < end && enclosedState == 0u) {
        enclosedState = enclosed_by_backs(&path, fromAnchor, baked_normal(faces, chartOfFace, anchor.face), seed, key,
                                          &traced)
                            ? 2u
                            : 1u;
        enclosure[t] = enclosedState;
    }
    const bool enclosed = enclosedState == 2u;
    for (uint s = 0u; begin < end && !enclosed && s < sampleCount; ++s) {
        const uint index = firstSample + s;
        const uint4 u = path_sample(seed, key, RAD_KEY_TEXEL, index);
        /* the piece: the first whose running share passes the number; the number, rescaled
         * within that piece's share, is then the point's first coordinate */
        const float pick = unit_float(u.x);
        uint k = begin;
        while (k + 1u < end && !(pick < pieces[k].end)) ++k;
        const float before = k == begin ? 0.0f : pieces[k - 1u].end;
        const float share = pieces[k].end - before;
        const float rescaled = share > 0.0f ? clamp((pick - before) / share, 0.0f, 0x1.fffffep-1f) : 0.5f;
        const float2 w = triangle_barycentrics((float2)(rescaled, unit_float(u.y)));
        __global const TexelPiece* piece = &pieces[k];
        const float2 b0 = (float2)(piece->b[0][0], piece->b[0][1]);
        const float2 b1 = (float2)(piece->b[1][0], piece->b[1][1]);
        const float2 b2 = (float2)(piece->b[2][0], piece->b[2][1]);
        const float2 b = b0 + w.x * (b1 - b0) + w.y * (b2 - b0);
        const uint face = piece->face;
        const float3 p = face_point(faceCorners, face, b.x, b.y);
        const float3 n = baked_normal(faces, chartOfFace, face);
        /* A texel holds one chart, the anchor's: where a scene's own UVs put two charts less
         * than a texel apart, a texel averages no two places of the surface. */
        if ((chartOfFace[face] & ~RAD_LIGHTMAP_BACK) != anchorChart) continue;
        /* Does the sample lie on the anchor's side of anything standing on the surface? */
        const float3 toSample = p + ray_offset(p, p, lift) * n - fromAnchor;
        const float apart = sqrt(dot3(toSample, toSample));
        if (apart > 0.0f) {
            /* along the segment only, past the anchor's own rounding */
            const Hit between = trace_within(&path.scene.geometry, fromAnchor, toSample * (1.0f / apart), apart);
            ++traced;
            if (between.face >= 0 && between.t > 2.0f * anchorLift &&
                (chartOfFace[between.face] & ~RAD_LIGHTMAP_BACK) != anchorChart)
                continue;
        }
        ++counted;
        Hit start;
        start.face = (int)face;
        start.t = 0.0f;
        start.b1 = b.x;
        start.b2 = b.y;
        const float3 e = RAD_PI * view_path_radiance(&path, p, -n, start, true, key, index, &traced);
        float3 rho, le;
        material_at(&path.scene, start, &rho, &le);
        sumE += e;
        sumL += material_is_diffuse(material_kind(&path.scene, face))
                    ? le + material_solution_reflectance(&path.scene, start, rho) * e * (1.0f / RAD_PI)
                    : le;
        const float lum = (0.2126f * e.x + 0.7152f * e.y) + 0.0722f * e.z;
        squares += lum * lum;
    }
    irradiance[t] = (float4)(sumE, squares);
    radiance[t] = (float4)(sumL, (float)counted);
    rays[t] = traced;
}
