/* From a hit on a face to the patch it lands on: the face is split into n * n cells in the
 * order host/mesh/patch_grid.h defines; this is the same rule applied to barycentric weights. */
#ifndef RADIOSITY_PATCH_LOOKUP_H
#define RADIOSITY_PATCH_LOOKUP_H

inline uint grid_cell_index(uint n, float b1, float b2) {
    const float s = b1 * (float)n, t = b2 * (float)n;
    const uint a = (uint)clamp((int)floor(s), 0, (int)n - 1);
    uint b = (uint)clamp((int)floor(t), 0, (int)n - 1);
    uint down = 0u;
    if (a + b > n - 1u) {
        b = n - 1u - a; /* rounding put the point past the face's far edge */
    } else if (a + b < n - 1u) {
        down = (s - (float)a) + (t - (float)b) >= 1.0f ? 1u : 0u;
    }
    return 2u * n * b - b * b + 2u * a + down;
}

#endif
