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
*/

#endif /* MT_SPEC_ARITH_H */
