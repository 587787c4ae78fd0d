/* Counter-based randomness: every number is a function of (seed, source, sample index), never
 * of the thread or work-group that computes it. Samples are 4-D Sobol points (dimension 0 is
 * the van der Corput sequence; 1-3 use Joe and Kuo's primitive polynomials), Owen-scrambled
 * per dimension with a hash keyed by the source (Laine and Karras's hash-based nested uniform
 * scramble, as refined by Burley 2020). Scrambling keeps Sobol's stratification and makes the
 * estimate unbiased, with an independent scramble per source. */
#ifndef RADIOSITY_RNG_H
#define RADIOSITY_RNG_H

#include "shared_math.h" /* rad_hash, rad_hash2: the host keys sequences with the same hash */

/* Direction numbers, one row per bit of the sample index, one column per dimension. */
__constant uint kSobolDirections[32][4] = {
    {0x80000000u, 0x80000000u, 0x80000000u, 0x80000000u}, {0x40000000u, 0xc0000000u, 0xc0000000u, 0xc0000000u},
    {0x20000000u, 0xa0000000u, 0x60000000u, 0x20000000u}, {0x10000000u, 0xf0000000u, 0x90000000u, 0x50000000u},
    {0x08000000u, 0x88000000u, 0xe8000000u, 0xf8000000u}, {0x04000000u, 0xcc000000u, 0x5c000000u, 0x74000000u},
    {0x02000000u, 0xaa000000u, 0x8e000000u, 0xa2000000u}, {0x01000000u, 0xff000000u, 0xc5000000u, 0x93000000u},
    {0x00800000u, 0x80800000u, 0x68800000u, 0xd8800000u}, {0x00400000u, 0xc0c00000u, 0x9cc00000u, 0x25400000u},
    {0x00200000u, 0xa0a00000u, 0xee600000u, 0x59e00000u}, {0x00100000u, 0xf0f00000u, 0x55900000u, 0xe6d00000u},
    {0x00080000u, 0x88880000u, 0x80680000u, 0x78080000u}, {0x00040000u, 0xcccc0000u, 0xc09c0000u, 0xb40c0000u},
    {0x00020000u, 0xaaaa0000u, 0x60ee0000u, 0x82020000u}, {0x00010000u, 0xffff0000u, 0x90550000u, 0xc3050000u},
    {0x00008000u, 0x80008000u, 0xe8808000u, 0x208f8000u}, {0x00004000u, 0xc000c000u, 0x5cc0c000u, 0x51474000u},
    {0x00002000u, 0xa000a000u, 0x8e606000u, 0xfbea2000u}, {0x00001000u, 0xf000f000u, 0xc5909000u, 0x75d93000u},
    {0x00000800u, 0x88008800u, 0x6868e800u, 0xa0858800u}, {0x00000400u, 0xcc00cc00u, 0x9c9c5c00u, 0x914e5400u},
    {0x00000200u, 0xaa00aa00u, 0xeeee8e00u, 0xdbe79e00u}, {0x00000100u, 0xff00ff00u, 0x5555c500u, 0x25db6d00u},
    {0x00000080u, 0x80808080u, 0x8000e880u, 0x58800080u}, {0x00000040u, 0xc0c0c0c0u, 0xc0005cc0u, 0xe54000c0u},
    {0x00000020u, 0xa0a0a0a0u, 0x60008e60u, 0x79e00020u}, {0x00000010u, 0xf0f0f0f0u, 0x9000c590u, 0xb6d00050u},
    {0x00000008u, 0x88888888u, 0xe8006868u, 0x800800f8u}, {0x00000004u, 0xccccccccu, 0x5c009c9cu, 0xc00c0074u},
    {0x00000002u, 0xaaaaaaaau, 0x8e00eeeeu, 0x200200a2u}, {0x00000001u, 0xffffffffu, 0xc5005555u, 0x50050093u},
};

inline uint4 reverse_bits4(uint4 x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
}

/* Each bit of the result depends only on the same and lower bits of x: applied to reversed
 * bits it permutes every dyadic interval within its parent, which is Owen's scramble. */
inline uint4 owen_scramble4(uint4 x, uint4 seed) {
    x = reverse_bits4(x);
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return reverse_bits4(x);
}

inline uint4 sobol4(uint index) {
    uint4 x = (uint4)(0u);
    for (int bit = 0; index != 0u; index >>= 1, ++bit)
        x ^= vload4(0, kSobolDirections[bit]) & (uint4)(0u - (index & 1u));
    return x;
}

/* Sample `index` of the sequence keyed by `key`: four 32-bit fixed-point coordinates. */
inline uint4 scrambled_sobol4(uint index, uint key) {
    const uint4 seed = (uint4)(rad_hash2(key, 1u), rad_hash2(key, 2u), rad_hash2(key, 3u), rad_hash2(key, 4u));
    return owen_scramble4(sobol4(index), seed);
}

/* 32-bit fixed point to a float in [0, 1). */
inline float4 unit_float4(uint4 x) { return convert_float4(x >> 8) * 0x1p-24f; }
inline float unit_float(uint x) { return (float)(x >> 8) * 0x1p-24f; }

/* Sample `index` at `depth` of a pixel's paths: point `shuffled` of the Sobol sequence keyed by
 * (seed, pixel, depth), where `shuffled` is the index under a nested uniform scramble keyed the
 * same way (Burley, "Practical Hash-based Owen Scrambling", 2020). The shuffle pairs the
 * samples of different depths at random. Without it, sample `index` at every depth would be
 * the same Sobol point under another scramble, whose leading bits differ only by a flip
 * common to all indices: the roulette at every depth would decide alike, and a pixel's mean
 * would stop converging after a few samples. */
inline uint4 path_sample(uint seed, uint pixel, uint depth, uint index) {
    const uint key = rad_hash2(rad_hash2(seed, pixel), depth);
    const uint shuffled = owen_scramble4((uint4)(index), (uint4)(rad_hash2(key, 5u))).x;
    return scrambled_sobol4(shuffled, key);
}

#endif
