/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_copy.h
 * @brief Byte copy between non-overlapping ranges (kernel-internal): the one home of the copy
 *        the rings use.
 *
 * The contract's \separated is what `restrict` tells the compiler, so the proved loop below
 * compiles to a block copy (gcc -O2 and -Os emit a call to memcpy; a freestanding gcc target
 * must supply memcpy in any case). Without `restrict` the compiler must assume that every
 * byte store may change the source or the ring's own fields, and copies one byte at a time
 * (deviation D-108, MISRA C:2012 rule 8.14).
 */
#ifndef MT_COPY_H
#define MT_COPY_H

#include <stdint.h>

/** dst[0 .. n - 1] = src[0 .. n - 1]. */
/*@ requires \valid(dst + (0 .. n - 1)) && \valid_read(src + (0 .. n - 1));
    requires \separated(dst + (0 .. n - 1), src + (0 .. n - 1));
    assigns dst[0 .. n - 1];
    ensures copied: \forall integer k; 0 <= k < n ==> dst[k] == src[k];
*/
// cppcheck-suppress misra-c2012-8.14 ; D-108 restrict states the contract's \separated
static inline void mt_copy_bytes(uint8_t *restrict dst, const uint8_t *restrict src, uint32_t n)
{
    uint32_t k;

    /*@ loop invariant 0 <= k <= n;
        loop invariant \forall integer j; 0 <= j < k ==> dst[j] == src[j];
        loop assigns k, dst[0 .. n - 1];
        loop variant n - k;
    */
    for (k = 0u; k < n; k++) {
        dst[k] = src[k];
    }
}

#endif /* MT_COPY_H */
