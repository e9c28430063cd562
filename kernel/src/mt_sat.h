/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_sat.h
 * @brief Saturating unsigned arithmetic (kernel-internal): the one home of the helpers the
 *        scheduler, the work queue and the bus share.
 *
 * Counters and time sums saturate at their type's maximum instead of wrapping, so a report
 * never shows a small number after a long run. Each helper's contract states its value
 * exactly; the callers' proofs use nothing else.
 */
#ifndef MT_SAT_H
#define MT_SAT_H

#include <stdint.h>

/** v, or 0xFFFFFFFF when v does not fit in 32 bits. */
/*@ assigns \nothing;
    ensures \result == (v > 0xFFFFFFFF ? 0xFFFFFFFF : v);
*/
static inline uint32_t mt_clamp_u32(uint64_t v)
{
    return (v > 0xFFFFFFFFu) ? 0xFFFFFFFFu : (uint32_t)v;
}

/** a + b, or the maximum when the sum does not fit. */
/*@ assigns \nothing;
    ensures \result == (a + b <= 0xFFFFFFFFFFFFFFFF ? a + b : 0xFFFFFFFFFFFFFFFF);
*/
static inline uint64_t mt_add_sat_u64(uint64_t a, uint64_t b)
{
    // cppcheck-suppress misra-c2012-12.1 ; D-102 fully parenthesised; addon false positive
    return (a <= (UINT64_MAX - b)) ? (a + b) : UINT64_MAX;
}

/** a - b, or 0 when b is later (times from other contexts are not ordered for the proof). */
/*@ assigns \nothing;
    ensures \result == (a >= b ? a - b : 0);
*/
static inline uint64_t mt_sub_sat_u64(uint64_t a, uint64_t b)
{
    uint64_t d = 0u;

    if (a >= b) {
        d = a - b;
    }
    return d;
}

/** a + 1, or the maximum. */
/*@ assigns \nothing;
    ensures \result == (a < 0xFFFFFFFF ? a + 1 : 0xFFFFFFFF);
*/
static inline uint32_t mt_inc_sat_u32(uint32_t a)
{
    uint32_t v = 0xFFFFFFFFu;

    if (a < 0xFFFFFFFFu) {
        v = a + 1u;
    }
    return v;
}

/** a + b, or the maximum when the sum does not fit. */
/*@ assigns \nothing;
    ensures \result == (a + b <= 0xFFFFFFFF ? a + b : 0xFFFFFFFF);
*/
static inline uint32_t mt_add_sat_u32(uint32_t a, uint32_t b)
{
    uint32_t v = 0xFFFFFFFFu;

    if (a <= (0xFFFFFFFFu - b)) {
        v = a + b;
    }
    return v;
}

#endif /* MT_SAT_H */
