/* Counter-based randomness: every number is a function of (seed, source, sample index), never
 * of the thread or work-group that computes it. Samples are 4-D Sobol points (dimension 0 is
 * the van der Corput sequence; 1-3 use Joe and Kuo's primitive polynomials), Owen-scrambled
 * per dimension with a hash keyed by the source (Laine and Karras's hash-based nested uniform
 * scramble, as refined by Burley 2020). Scrambling keeps Sobol's stratification and makes the
 * estimate unbiased, with an independent scramble per source. */
#ifndef RADIOSITY_RNG_H
#define RADIOSITY_RNG_H

#include "shared_math.h" /* rad_hash, rad_hash2: the host keys sequences with the same hash */

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

/* The Sobol points' generator, four index bits at a time: entry [k][v] is the XOR of the
 * direction numbers of index bits 4k .. 4k + 3 that v sets, one column per dimension (made, and
 * checked by a test, by tests/layout/sobol_table.py, which holds the direction numbers). Eight
 * lookups per point where a bit at a time took up to 32 steps: the samples' keys shuffle the
 * index over all 32 bits (path_sample). */
__constant uint kSobolNibbles[8][16][4] = {
    {{0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u}, {0x80000000u, 0x80000000u, 0x80000000u, 0x80000000u},
     {0x40000000u, 0xc0000000u, 0xc0000000u, 0xc0000000u}, {0xc0000000u, 0x40000000u, 0x40000000u, 0x40000000u},
     {0x20000000u, 0xa0000000u, 0x60000000u, 0x20000000u}, {0xa0000000u, 0x20000000u, 0xe0000000u, 0xa0000000u},
     {0x60000000u, 0x60000000u, 0xa0000000u, 0xe0000000u}, {0xe0000000u, 0xe0000000u, 0x20000000u, 0x60000000u},
     {0x10000000u, 0xf0000000u, 0x90000000u, 0x50000000u}, {0x90000000u, 0x70000000u, 0x10000000u, 0xd0000000u},
     {0x50000000u, 0x30000000u, 0x50000000u, 0x90000000u}, {0xd0000000u, 0xb0000000u, 0xd0000000u, 0x10000000u},
     {0x30000000u, 0x50000000u, 0xf0000000u, 0x70000000u}, {0xb0000000u, 0xd0000000u, 0x70000000u, 0xf0000000u},
     {0x70000000u, 0x90000000u, 0x30000000u, 0xb0000000u}, {0xf0000000u, 0x10000000u, 0xb0000000u, 0x30000000u}},
    {{0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u}, {0x08000000u, 0x88000000u, 0xe8000000u, 0xf8000000u},
     {0x04000000u, 0xcc000000u, 0x5c000000u, 0x74000000u}, {0x0c000000u, 0x44000000u, 0xb4000000u, 0x8c000000u},
     {0x02000000u, 0xaa000000u, 0x8e000000u, 0xa2000000u}, {0x0a000000u, 0x22000000u, 0x66000000u, 0x5a000000u},
     {0x06000000u, 0x66000000u, 0xd2000000u, 0xd6000000u}, {0x0e000000u, 0xee000000u, 0x3a000000u, 0x2e000000u},
     {0x01000000u, 0xff000000u, 0xc5000000u, 0x93000000u}, {0x09000000u, 0x77000000u, 0x2d000000u, 0x6b000000u},
     {0x05000000u, 0x33000000u, 0x99000000u, 0xe7000000u}, {0x0d000000u, 0xbb000000u, 0x71000000u, 0x1f000000u},
     {0x03000000u, 0x55000000u, 0x4b000000u, 0x31000000u}, {0x0b000000u, 0xdd000000u, 0xa3000000u, 0xc9000000u},
     {0x07000000u, 0x99000000u, 0x17000000u, 0x45000000u}, {0x0f000000u, 0x11000000u, 0xff000000u, 0xbd000000u}},
    {{0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u}, {0x00800000u, 0x80800000u, 0x68800000u, 0xd8800000u},
     {0x00400000u, 0xc0c00000u, 0x9cc00000u, 0x25400000u}, {0x00c00000u, 0x40400000u, 0xf4400000u, 0xfdc00000u},
     {0x00200000u, 0xa0a00000u, 0xee600000u, 0x59e00000u}, {0x00a00000u, 0x20200000u, 0x86e00000u, 0x81600000u},
     {0x00600000u, 0x60600000u, 0x72a00000u, 0x7ca00000u}, {0x00e00000u, 0xe0e00000u, 0x1a200000u, 0xa4200000u},
     {0x00100000u, 0xf0f00000u, 0x55900000u, 0xe6d00000u}, {0x00900000u, 0x70700000u, 0x3d100000u, 0x3e500000u},
     {0x00500000u, 0x30300000u, 0xc9500000u, 0xc3900000u}, {0x00d00000u, 0xb0b00000u, 0xa1d00000u, 0x1b100000u},
     {0x00300000u, 0x50500000u, 0xbbf00000u, 0xbf300000u}, {0x00b00000u, 0xd0d00000u, 0xd3700000u, 0x67b00000u},
     {0x00700000u, 0x90900000u, 0x27300000u, 0x9a700000u}, {0x00f00000u, 0x10100000u, 0x4fb00000u, 0x42f00000u}},
    {{0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u}, {0x00080000u, 0x88880000u, 0x80680000u, 0x78080000u},
     {0x00040000u, 0xcccc0000u, 0xc09c0000u, 0xb40c0000u}, {0x000c0000u, 0x44440000u, 0x40f40000u, 0xcc040000u},
     {0x00020000u, 0xaaaa0000u, 0x60ee0000u, 0x82020000u}, {0x000a0000u, 0x22220000u, 0xe0860000u, 0xfa0a0000u},
     {0x00060000u, 0x66660000u, 0xa0720000u, 0x360e0000u}, {0x000e0000u, 0xeeee0000u, 0x201a0000u, 0x4e060000u},
     {0x00010000u, 0xffff0000u, 0x90550000u, 0xc3050000u}, {0x00090000u, 0x77770000u, 0x103d0000u, 0xbb0d0000u},
     {0x00050000u, 0x33330000u, 0x50c90000u, 0x77090000u}, {0x000d0000u, 0xbbbb0000u, 0xd0a10000u, 0x0f010000u},
     {0x00030000u, 0x55550000u, 0xf0bb0000u, 0x41070000u}, {0x000b0000u, 0xdddd0000u, 0x70d30000u, 0x390f0000u},
     {0x00070000u, 0x99990000u, 0x30270000u, 0xf50b0000u}, {0x000f0000u, 0x11110000u, 0xb04f0000u, 0x8d030000u}},
    {{0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u}, {0x00008000u, 0x80008000u, 0xe8808000u, 0x208f8000u},
     {0x00004000u, 0xc000c000u, 0x5cc0c000u, 0x51474000u}, {0x0000c000u, 0x40004000u, 0xb4404000u, 0x71c8c000u},
     {0x00002000u, 0xa000a000u, 0x8e606000u, 0xfbea2000u}, {0x0000a000u, 0x20002000u, 0x66e0e000u, 0xdb65a000u},
     {0x00006000u, 0x60006000u, 0xd2a0a000u, 0xaaad6000u}, {0x0000e000u, 0xe000e000u, 0x3a202000u, 0x8a22e000u},
     {0x00001000u, 0xf000f000u, 0xc5909000u, 0x75d93000u}, {0x00009000u, 0x70007000u, 0x2d101000u, 0x5556b000u},
     {0x00005000u, 0x30003000u, 0x99505000u, 0x249e7000u}, {0x0000d000u, 0xb000b000u, 0x71d0d000u, 0x0411f000u},
     {0x00003000u, 0x50005000u, 0x4bf0f000u, 0x8e331000u}, {0x0000b000u, 0xd000d000u, 0xa3707000u, 0xaebc9000u},
     {0x00007000u, 0x90009000u, 0x17303000u, 0xdf745000u}, {0x0000f000u, 0x10001000u, 0xffb0b000u, 0xfffbd000u}},
    {{0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u}, {0x00000800u, 0x88008800u, 0x6868e800u, 0xa0858800u},
     {0x00000400u, 0xcc00cc00u, 0x9c9c5c00u, 0x914e5400u}, {0x00000c00u, 0x44004400u, 0xf4f4b400u, 0x31cbdc00u},
     {0x00000200u, 0xaa00aa00u, 0xeeee8e00u, 0xdbe79e00u}, {0x00000a00u, 0x22002200u, 0x86866600u, 0x7b621600u},
     {0x00000600u, 0x66006600u, 0x7272d200u, 0x4aa9ca00u}, {0x00000e00u, 0xee00ee00u, 0x1a1a3a00u, 0xea2c4200u},
     {0x00000100u, 0xff00ff00u, 0x5555c500u, 0x25db6d00u}, {0x00000900u, 0x77007700u, 0x3d3d2d00u, 0x855ee500u},
     {0x00000500u, 0x33003300u, 0xc9c99900u, 0xb4953900u}, {0x00000d00u, 0xbb00bb00u, 0xa1a17100u, 0x1410b100u},
     {0x00000300u, 0x55005500u, 0xbbbb4b00u, 0xfe3cf300u}, {0x00000b00u, 0xdd00dd00u, 0xd3d3a300u, 0x5eb97b00u},
     {0x00000700u, 0x99009900u, 0x27271700u, 0x6f72a700u}, {0x00000f00u, 0x11001100u, 0x4f4fff00u, 0xcff72f00u}},
    {{0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u}, {0x00000080u, 0x80808080u, 0x8000e880u, 0x58800080u},
     {0x00000040u, 0xc0c0c0c0u, 0xc0005cc0u, 0xe54000c0u}, {0x000000c0u, 0x40404040u, 0x4000b440u, 0xbdc00040u},
     {0x00000020u, 0xa0a0a0a0u, 0x60008e60u, 0x79e00020u}, {0x000000a0u, 0x20202020u, 0xe00066e0u, 0x216000a0u},
     {0x00000060u, 0x60606060u, 0xa000d2a0u, 0x9ca000e0u}, {0x000000e0u, 0xe0e0e0e0u, 0x20003a20u, 0xc4200060u},
     {0x00000010u, 0xf0f0f0f0u, 0x9000c590u, 0xb6d00050u}, {0x00000090u, 0x70707070u, 0x10002d10u, 0xee5000d0u},
     {0x00000050u, 0x30303030u, 0x50009950u, 0x53900090u}, {0x000000d0u, 0xb0b0b0b0u, 0xd00071d0u, 0x0b100010u},
     {0x00000030u, 0x50505050u, 0xf0004bf0u, 0xcf300070u}, {0x000000b0u, 0xd0d0d0d0u, 0x7000a370u, 0x97b000f0u},
     {0x00000070u, 0x90909090u, 0x30001730u, 0x2a7000b0u}, {0x000000f0u, 0x10101010u, 0xb000ffb0u, 0x72f00030u}},
    {{0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u}, {0x00000008u, 0x88888888u, 0xe8006868u, 0x800800f8u},
     {0x00000004u, 0xccccccccu, 0x5c009c9cu, 0xc00c0074u}, {0x0000000cu, 0x44444444u, 0xb400f4f4u, 0x4004008cu},
     {0x00000002u, 0xaaaaaaaau, 0x8e00eeeeu, 0x200200a2u}, {0x0000000au, 0x22222222u, 0x66008686u, 0xa00a005au},
     {0x00000006u, 0x66666666u, 0xd2007272u, 0xe00e00d6u}, {0x0000000eu, 0xeeeeeeeeu, 0x3a001a1au, 0x6006002eu},
     {0x00000001u, 0xffffffffu, 0xc5005555u, 0x50050093u}, {0x00000009u, 0x77777777u, 0x2d003d3du, 0xd00d006bu},
     {0x00000005u, 0x33333333u, 0x9900c9c9u, 0x900900e7u}, {0x0000000du, 0xbbbbbbbbu, 0x7100a1a1u, 0x1001001fu},
     {0x00000003u, 0x55555555u, 0x4b00bbbbu, 0x70070031u}, {0x0000000bu, 0xddddddddu, 0xa300d3d3u, 0xf00f00c9u},
     {0x00000007u, 0x99999999u, 0x17002727u, 0xb00b0045u}, {0x0000000fu, 0x11111111u, 0xff004f4fu, 0x300300bdu}},
};

inline uint4 sobol4(uint index) {
    uint4 x = (uint4)(0u);
    for (int nibble = 0; index != 0u; index >>= 4, ++nibble) x ^= vload4(0, kSobolNibbles[nibble][index & 15u]);
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
