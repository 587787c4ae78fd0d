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

/* The same without an atomic, for a sum no other work item adds into during the launch. */
inline void add64(__global uint* word, uint lo, uint hi) {
    const uint old = word[0];
    word[0] = old + lo;
    const uint carry = old + lo < old ? 1u : 0u;
    if (hi + carry != 0u) word[1] += hi + carry;
}

/* One sum's words as a 64-bit two's complement number, and back into an atomic sum. */
inline ulong fixed_value(uint lo, uint hi) { return ((ulong)hi << 32) | (ulong)lo; }
inline void atomic_add_fixed(volatile __global uint* word, ulong value) {
    if (value != 0ul) atomic_add64(word, (uint)value, (uint)(value >> 32));
}

/* The part `fraction` (in [0, 1]) of a signed fixed-point amount, its magnitude rounded down:
 * integer arithmetic on the fraction's 32-bit fixed point, so the part and the rest (amount -
 * part) are exact and the same on every device that computes the same fraction. */
inline ulong fixed_part(ulong amount, float fraction) {
    if (!(fraction > 0.0f)) return 0ul;
    if (fraction >= 1.0f) return amount;
    const ulong q = (ulong)(uint)(fraction * 4294967296.0f); /* < 2^32: fraction < 1 */
    const bool negative = (amount >> 63) != 0ul;
    const ulong m = negative ? (ulong)0 - amount : amount;
    const ulong part = (m >> 32) * q + (((m & 0xFFFFFFFFul) * q) >> 32);
    return negative ? (ulong)0 - part : part;
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
