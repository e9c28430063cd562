/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_spec_div.h
 * @brief ACSL lemmas on quotients and remainders whose instances the CBMC harnesses of
 *        mt_proc_period_next and mt_time_ticks_to_us assume (assumption B12). Each lemma
 *        is proved by WP (goal `lemma_<name>`, in the proc module, the one that includes
 *        this header); none is assumed by WP.
 *
 * Kept apart from mt_spec_arith.h so that these facts do not enter the provers' context
 * of the modules that do not need them. Only ACSL lives here: to a C compiler this header
 * is empty.
 */
#ifndef MT_SPEC_DIV_H
#define MT_SPEC_DIV_H

/*@ lemma MtMulDiv: \forall integer k, p; k >= 0 ==> p > 0 ==> (k * p) / p == k;

    lemma MtMulMod: \forall integer k, p; k >= 0 ==> p > 0 ==> (k * p) % p == 0;

    lemma MtModSplit: \forall integer n, p; n >= 0 ==> p > 0 ==> n - n % p + p == (n / p + 1) * p;

    // the late deadline of mt_proc_period_next is on the period grid
    lemma MtModStep: \forall integer n, p;
        n >= 0 ==> p > 0 ==> (n - n % p + p) % p == 0;

    // mt_time_ticks_to_us saturates when whole * 10^6 alone exceeds 64 bits
    lemma MtUsAbove: \forall integer w;
        w > 0xFFFFFFFFFFFFFFFF / 1000000 ==> w * 1000000 > 0xFFFFFFFFFFFFFFFF;
*/

#endif /* MT_SPEC_DIV_H */
