/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_spec_ring.h
 * @brief ACSL logic for the SPSC rings (byte ring and object ring).
 *
 * Indices are "mirror" indices in [0, 2*S) for a ring of S slots: the slot of
 * index i is i or i - S, the count is (w - r) read modulo 2*S, and no C
 * expression ever wraps (verification.md §2.1, variant M, without a division).
 * The byte ring has S == cap; the object ring has S == cap + 1 (one spare slot
 * that makes a drop-oldest push possible without the producer touching the
 * consumer's index).
 */
#ifndef MT_SPEC_RING_H
#define MT_SPEC_RING_H

/*@ predicate MtIdxOk(integer i, integer s) = 0 <= i < 2 * s;

    logic integer MtIdxCount(integer w, integer r, integer s) =
        w >= r ? w - r : w + 2 * s - r;

    logic integer MtIdxAdd(integer i, integer n, integer s) =
        i + n < 2 * s ? i + n : i + n - 2 * s;

    logic integer MtIdxSlot(integer i, integer s) = i < s ? i : i - s;
*/

#endif /* MT_SPEC_RING_H */
