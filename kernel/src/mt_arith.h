/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_arith.h
 * @brief Unsigned 64-bit quotient, remainder and product as functions (kernel-internal).
 *
 * A kernel function whose contract relates its quotients or products to those of the
 * contract (mt_proc_period_next, mt_time_ticks_to_us) computes them through these instead
 * of the `/`, `%` and `*` operators. They compute exactly the operators' values. The reason
 * is the CBMC proof: its proof folder replaces the calls by models of the operations
 * (proofs/cbmc/lib/mtc.c, assumption B11) whose equal operands give equal results, which a
 * bit-level solver cannot see for two separate division or multiplication circuits.
 */
#ifndef MT_ARITH_H
#define MT_ARITH_H

#include <stdint.h>

/** n / d (rounded down). */
/*@ requires divisor: d >= 1;
    assigns \nothing;
    ensures quotient: \result == n / d;
*/
static inline uint64_t mt_udiv_u64(uint64_t n, uint64_t d)
{
    return n / d;
}

/** n % d. */
/*@ requires divisor: d >= 1;
    assigns \nothing;
    ensures remainder: \result == n % d;
*/
static inline uint64_t mt_umod_u64(uint64_t n, uint64_t d)
{
    return n % d;
}

/** n * m, which must fit in 64 bits. */
/*@ requires fits: n * m <= 0xFFFFFFFFFFFFFFFF;
    assigns \nothing;
    ensures product: \result == n * m;
*/
static inline uint64_t mt_umul_u64(uint64_t n, uint64_t m)
{
    return n * m;
}

#endif /* MT_ARITH_H */
