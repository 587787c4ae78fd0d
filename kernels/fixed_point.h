/* 64-bit fixed-point sums with 32-bit integer atomics (OpenCL 1.2 has no 64-bit ones): the
 * low word takes the addend and any wrap-around carries into the high word. Integer addition
 * is associative, so the total is exact and independent of the order of the additions; the
 * two words are read only after the kernel has finished. Sums are two's complement: a negative
 * addend (an overshooting solve's correction) is added as its 64-bit pattern, modulo 2^64. */
#ifndef RADIOSITY_FIXED_POINT_H
#define RADIOSITY_FIXED_POINT_H

inline void atomic_add64(volatile __global uint* word, uint lo, uint hi) {
    const uint old = atomic_add(word, lo);
    const uint carry = old + lo < old ? 1u : 0u;
    if (hi + carry != 0u) atomic_add(word + 1, hi + carry);
}

/* The value of a signed 64-bit sum times `quantum`, in float, computed the same way everywhere:
 * a negative sum as minus its magnitude, so small ones lose nothing to cancellation. */
inline float fixed_to_float(uint lo, uint hi, float quantum) {
    if ((int)hi >= 0) return (float)hi * (4294967296.0f * quantum) + (float)lo * quantum;
    const uint magnitudeLo = ~lo + 1u;
    const uint magnitudeHi = ~hi + (magnitudeLo == 0u ? 1u : 0u);
    return -((float)magnitudeHi * (4294967296.0f * quantum) + (float)magnitudeLo * quantum);
}

#endif
