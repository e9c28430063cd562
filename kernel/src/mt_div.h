/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_div.h
 * @brief Unsigned 64-bit quotient and remainder as functions (kernel-internal).
 *
 * A kernel function whose contract relates its quotient to a quotient of the contract
 * (mt_proc_period_next) divides through these two instead of the `/` and `%` operators.
 * They compute exactly the operators' values. The reason is the CBMC proof: its proof
 * folder replaces both calls by a model of unsigned division (proofs/cbmc/lib/mtc.c,
 * assumption B11) whose equal operands give equal results, which a bit-level solver
 * cannot see for two separate division circuits.
 */
#ifndef MT_DIV_H
#define MT_DIV_H

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

#endif /* MT_DIV_H */
