/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_ring_idx.h
 * @brief Mirror-index arithmetic shared by the byte ring and the object ring
 *        (kernel-private). See mt_spec_ring.h for the logic twins.
 */
#ifndef MT_RING_IDX_H
#define MT_RING_IDX_H

#include <stdbool.h>
#include <stdint.h>

#include "mt_spec_ring.h"

/** Largest ring size in slots: 2*S must fit in 32 bits with room to spare. */
#define MT_RING_SLOTS_MAX 0x40000000u

/** Index i is a mirror index of a ring of s slots (2 * s fits in 32 bits). */
/*@ requires 1 <= s <= MT_RING_SLOTS_MAX;
    assigns \nothing;
    ensures \result != 0 <==> MtIdxOk(i, s);
*/
static inline bool mt_idx_ok(uint32_t i, uint32_t s)
{
    return i < (2u * s);
}

/** Number of items between read index r and write index w. */
/*@ requires 1 <= s <= MT_RING_SLOTS_MAX;
    requires MtIdxOk(w, s) && MtIdxOk(r, s);
    assigns \nothing;
    ensures \result == MtIdxCount(w, r, s);
*/
static inline uint32_t mt_idx_count(uint32_t w, uint32_t r, uint32_t s)
{
    // cppcheck-suppress misra-c2012-12.1 ; D-102 fully parenthesised; addon false positive
    return (w >= r) ? (w - r) : ((w + (2u * s)) - r);
}

/** Index i moved forward by n (n <= s). */
/*@ requires 1 <= s <= MT_RING_SLOTS_MAX;
    requires MtIdxOk(i, s);
    requires n <= s;
    assigns \nothing;
    ensures \result == MtIdxAdd(i, n, s);
    ensures MtIdxOk(\result, s);
*/
static inline uint32_t mt_idx_add(uint32_t i, uint32_t n, uint32_t s)
{
    uint32_t j = i + n;
    return (j < (2u * s)) ? j : (j - (2u * s));
}

/** Storage slot of index i. */
/*@ requires 1 <= s <= MT_RING_SLOTS_MAX;
    requires MtIdxOk(i, s);
    assigns \nothing;
    ensures \result == MtIdxSlot(i, s);
    ensures 0 <= \result < s;
*/
static inline uint32_t mt_idx_slot(uint32_t i, uint32_t s)
{
    return (i < s) ? i : (i - s);
}

/* Lemma (ghost function, proved by WP, called only from annotations): the k-th
 * index after i lies k slots after i's slot while that stays below s, and at
 * slot k - (s - slot(i)) after the wrap. A ghost call scopes the fact to the
 * goals that need it, instead of a global lemma in every goal's context. */
/*@ ghost
  /@ requires 1 <= s <= MT_RING_SLOTS_MAX;
     requires MtIdxOk(i, s);
     assigns \nothing;
     ensures lo: \forall integer k; 0 <= k < s - MtIdxSlot(i, s) ==>
         MtIdxSlot(MtIdxAdd(i, k, s), s) == MtIdxSlot(i, s) + k;
     ensures hi: \forall integer k; s - MtIdxSlot(i, s) <= k < s ==>
         MtIdxSlot(MtIdxAdd(i, k, s), s) == k - (s - MtIdxSlot(i, s));
  @/
  static void mt_idx_slot_add_lemma(uint32_t i, uint32_t s) { }
*/

#endif /* MT_RING_IDX_H */
