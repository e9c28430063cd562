/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_spec_arith.h
 * @brief ACSL arithmetic lemmas (non-linear facts the SMT solvers do not find
 *        on their own inside a large goal). Each lemma is proved by WP (goal
 *        `lemma_<name>`); none is assumed.
 *
 * Only ACSL lives here: to a C compiler this header is empty.
 */
#ifndef MT_SPEC_ARITH_H
#define MT_SPEC_ARITH_H

/*@ lemma MtMulMono: \forall integer a, b, h; h > 0 ==> a <= b ==> a * h <= b * h;

    lemma MtDivUnique: \forall integer x, h, q;
        x >= 0 ==> h > 0 ==> q * h <= x < (q + 1) * h ==> x / h == q;

    lemma MtMulDiv: \forall integer k, p; k >= 0 ==> p > 0 ==> (k * p) / p == k;

    lemma MtMulMod: \forall integer k, p; k >= 0 ==> p > 0 ==> (k * p) % p == 0;

    lemma MtModSplit: \forall integer n, p; n >= 0 ==> p > 0 ==> n - n % p + p == (n / p + 1) * p;

    lemma MtModStep: \forall integer n, p;
        n >= 0 ==> p > 0 ==> (n - n % p + p) % p == 0;
*/

#endif /* MT_SPEC_ARITH_H */
