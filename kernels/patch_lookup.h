/* From a hit on a face to the patch it lands on: the face is split into n * n cells in the
 * order host/mesh/patch_grid.h defines (rad_grid_index, written once for both sides); this
 * finds the cell that a hit's barycentric weights fall in. */
#ifndef RADIOSITY_PATCH_LOOKUP_H
#define RADIOSITY_PATCH_LOOKUP_H

#include "shared_math.h" /* rad_grid_index: the host numbers the cells by the same rule */

typedef struct {
    uint index;      /* the cell's index within the face */
    float3 weights;  /* the point's weights on the cell's three corners, in the cell's order */
} GridPoint;

inline GridPoint grid_locate(uint n, float b1, float b2) {
    const float s = b1 * (float)n, t = b2 * (float)n;
    const uint a = (uint)clamp((int)floor(s), 0, (int)n - 1);
    uint b = (uint)clamp((int)floor(t), 0, (int)n - 1);
    if (a + b > n - 1u) b = n - 1u - a; /* rounding put the point past the face's far edge */
    const float fs = s - (float)a, ft = t - (float)b;
    const bool down = a + b < n - 1u && fs + ft >= 1.0f;
    GridPoint p;
    p.index = rad_grid_index(n, a, b, down ? 1u : 0u);
    /* up cell (a,b) (a+1,b) (a,b+1); down cell (a+1,b) (a+1,b+1) (a,b+1) */
    p.weights = down ? (float3)(1.0f - ft, fs + ft - 1.0f, 1.0f - fs) : (float3)(1.0f - fs - ft, fs, ft);
    p.weights = clamp(p.weights, 0.0f, 1.0f);
    return p;
}

inline uint grid_cell_index(uint n, float b1, float b2) { return grid_locate(n, b1, b2).index; }

#endif
