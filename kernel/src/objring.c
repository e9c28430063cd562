/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file objring.c
 * @brief SPSC object ring with a consumer-performed drop-oldest (see mt/objring.h).
 */
#include "mt/objring.h"

#include "mt_atomic.h"
#include "mt_copy.h"
#include "mt_ring_idx.h"

/* Lemma (ghost function, proved by WP): the invariant from its parts. Lets the
 * solvers prove MtORingInv once, in a small context, while each part is
 * discharged at the call site (by Qed, after a chain of field stores). */
/*@ ghost
  /@ requires \valid(r) && 1 <= r->cap && r->slots == r->cap + 1 && 1 <= r->elem;
     requires r->slots * r->elem <= MT_ORING_BYTES_MAX;
     requires \valid(r->buf + (0 .. r->slots * r->elem - 1));
     requires \separated(r, r->buf + (0 .. r->slots * r->elem - 1));
     requires r->head == 0 && r->tail == 0 && r->head_cache == 0 && r->tail_cache == 0;
     assigns \nothing;
     ensures MtORingInv(r);
  @/
  static void oring_inv_intro(mt_oring_t *r) { }
*/

mt_status_t mt_oring_init(mt_oring_t *r, void *storage, uint32_t elem, uint32_t cap)
{
    r->tail = 0u;
    r->head_cache = 0u;
    r->rejected = 0u;
    r->head = 0u;
    r->tail_cache = 0u;
    r->lost = 0u;
    r->buf = (uint8_t *)storage;
    r->cap = 0u;
    r->slots = 1u;
    r->elem = 1u;
    /*@ assert fits: elem >= 1 ==> cap >= 1 ==> (cap + 1) * elem <= MT_ORING_BYTES_MAX ==>
            cap + 1 <= MT_ORING_BYTES_MAX; */
    if ((elem < 1u) || (cap < 1u) || (cap >= MT_ORING_BYTES_MAX) ||
        ((uint64_t)elem * ((uint64_t)cap + 1u) > MT_ORING_BYTES_MAX)) {
        return MT_E_INVALID;
    }
    r->cap = cap;
    r->slots = cap + 1u;
    r->elem = elem;
    //@ assert bytes: r->slots * r->elem == (cap + 1) * elem;
    //@ ghost oring_inv_intro(r);
    return MT_OK;
}

/* Lemma (ghost function, proved by WP, called only from annotations):
 * multiplication by a positive number is monotonic. */
/*@ ghost
  /@ requires 0 <= a <= b;
     requires h >= 1;
     assigns \nothing;
     ensures a * h <= b * h;
  @/
  static void mul_mono_lemma(uint32_t a, uint32_t b, uint32_t h) { }
*/

/* Byte address of slot `slot`. */
/*@ requires MtORingInv(r);
    requires 0 <= slot < r->slots;
    assigns \nothing;
    ensures \result == r->buf + slot * r->elem;
    ensures in_storage: 0 <= slot * r->elem && slot * r->elem + r->elem <= r->slots * r->elem;
    ensures \valid(\result + (0 .. r->elem - 1));
*/
// cppcheck-suppress misra-c2012-5.9 ; D-106 module-local helper, one per translation unit
static uint8_t *slot_ptr(const mt_oring_t *r, uint32_t slot)
{
    //@ ghost mul_mono_lemma(slot + 1u, r->slots, r->elem);
    return r->buf + ((uint64_t)slot * r->elem);
}

/* Producer's count, with a fresh head when the cached one says >= cap. */
/*@ requires MtORingInv(r);
    assigns r->head_cache;
    ensures MtORingInv(r);
    ensures \result == MtIdxCount(r->tail, r->head_cache, r->slots);
    ensures \result < r->cap ==> MtIdxCount(r->tail, r->head, r->slots) <= \result;
    ensures \result >= r->cap ==> \result == MtIdxCount(r->tail, r->head, r->slots);
*/
static uint32_t producer_count(mt_oring_t *r)
{
    uint32_t n = mt_idx_count(r->tail, r->head_cache, r->slots);
    if (n >= r->cap) {
        r->head_cache = mt_load_acquire_u32(&r->head);
        n = mt_idx_count(r->tail, r->head_cache, r->slots);
    }
    return n;
}

/* Write obj at the tail slot and publish it (data before index). */
/*@ requires MtORingInv(r);
    requires MtIdxCount(r->tail, r->head, r->slots) <= r->cap;
    requires MtIdxCount(r->tail, r->head_cache, r->slots) <= r->cap;
    requires \valid_read(obj + (0 .. r->elem - 1));
    requires \separated(obj + (0 .. r->elem - 1), r, r->buf + (0 .. r->slots * r->elem - 1));
    assigns r->tail, r->buf[0 .. r->slots * r->elem - 1];
    ensures MtORingInv(r);
    ensures r->tail == MtIdxAdd(\old(r->tail), 1, r->slots);
    ensures \forall integer k; 0 <= k < r->elem ==>
        r->buf[MtIdxSlot(\old(r->tail), r->slots) * r->elem + k] == obj[k];
    ensures MtORingOthersKept{Pre, Post}(r, MtIdxSlot(\old(r->tail), r->slots));
*/
// cppcheck-suppress misra-c2012-5.9 ; D-106 module-local helper, one per translation unit
static void put(mt_oring_t *r, const uint8_t *obj)
{
    mt_copy_bytes(slot_ptr(r, mt_idx_slot(r->tail, r->slots)), obj, r->elem);
    mt_store_release_u32(&r->tail, mt_idx_add(r->tail, 1u, r->slots));
}

/*@ requires MtORingInv(r);
    assigns r->rejected;
    ensures MtORingInv(r);
    ensures r->rejected == (\old(r->rejected) < 0xFFFFFFFF ? \old(r->rejected) + 1 : \old(r->rejected));
*/
// cppcheck-suppress misra-c2012-5.9 ; D-106 module-local helper, one per translation unit
static void note_rejected(mt_oring_t *r)
{
    if (r->rejected < 0xFFFFFFFFu) {
        r->rejected++;
    }
}

mt_status_t mt_oring_push(mt_oring_t *r, const void *obj)
{
    if (producer_count(r) >= r->cap) {
        //@ assert full: MtIdxCount(r->tail, r->head, r->slots) >= r->cap;
        note_rejected(r);
        return MT_E_FULL;
    }
    put(r, (const uint8_t *)obj);
    /*@ assert data: \forall integer k; 0 <= k < r->elem ==>
            r->buf[MtIdxSlot(\at(r->tail, Pre), r->slots) * r->elem + k] == ((uint8_t *)obj)[k]; */
    return MT_OK;
}

mt_status_t mt_oring_push_drop_oldest(mt_oring_t *r, const void *obj)
{
    uint32_t n = producer_count(r);

    if (n > r->cap) {
        note_rejected(r); /* the consumer has not taken the previous drop yet */
        return MT_E_FULL;
    }
    /* n == cap: the spare slot is free (storage has cap + 1 slots) */
    put(r, (const uint8_t *)obj);
    return (n == r->cap) ? MT_W_DROPPED_OLDEST : MT_OK;
}

uint32_t mt_oring_space(mt_oring_t *r)
{
    uint32_t n;

    r->head_cache = mt_load_acquire_u32(&r->head);
    n = mt_idx_count(r->tail, r->head_cache, r->slots);
    return (n >= r->cap) ? 0u : (r->cap - n);
}

/* Consumer: load tail; if more than cap objects are published, discard the
 * oldest (the drop requested by a drop-oldest push) and count it. Returns the
 * number of retained objects. */
/*@ requires MtORingInv(r);
    assigns r->head, r->tail_cache, r->lost;
    ensures MtORingInv(r);
    ensures \result == MtORingCount(r) && \result <= r->cap;
    ensures r->tail_cache == r->tail;
    ensures MtIdxCount(r->tail, \old(r->head), r->slots) <= r->cap ==>
        r->head == \old(r->head) && r->lost == \old(r->lost);
    ensures MtIdxCount(r->tail, \old(r->head), r->slots) > r->cap ==>
        r->head == MtIdxAdd(\old(r->head), 1, r->slots) &&
        r->lost == (\old(r->lost) < 0xFFFFFFFF ? \old(r->lost) + 1 : \old(r->lost));
*/
static uint32_t consumer_sync(mt_oring_t *r)
{
    uint32_t n;

    r->tail_cache = mt_load_acquire_u32(&r->tail);
    n = mt_idx_count(r->tail_cache, r->head, r->slots);
    if (n > r->cap) {
        /* the slot of the oldest object is free again once head moves */
        mt_store_release_u32(&r->head, mt_idx_add(r->head, 1u, r->slots));
        if (r->lost < 0xFFFFFFFFu) {
            r->lost++;
        }
        n--;
    }
    return n;
}

uint32_t mt_oring_available(mt_oring_t *r)
{
    uint32_t n;

    r->tail_cache = mt_load_acquire_u32(&r->tail);
    n = mt_idx_count(r->tail_cache, r->head, r->slots);
    return (n > r->cap) ? r->cap : n;
}

mt_status_t mt_oring_pop(mt_oring_t *r, void *out)
{
    if (consumer_sync(r) == 0u) {
        //@ assert was_empty: MtIdxCount(r->tail, \at(r->head, Pre), r->slots) == 0;
        return MT_E_EMPTY;
    }
    mt_copy_bytes((uint8_t *)out, slot_ptr(r, mt_idx_slot(r->head, r->slots)), r->elem);
    /*@ assert copied: \forall integer k; 0 <= k < r->elem ==>
            ((uint8_t *)out)[k] == r->buf[MtIdxSlot(r->head, r->slots) * r->elem + k]; */
    /* copy done before the slot is released */
    mt_store_release_u32(&r->head, mt_idx_add(r->head, 1u, r->slots));
    return MT_OK;
}

mt_status_t mt_oring_peek(mt_oring_t *r, void *out)
{
    if (consumer_sync(r) == 0u) {
        return MT_E_EMPTY;
    }
    mt_copy_bytes((uint8_t *)out, slot_ptr(r, mt_idx_slot(r->head, r->slots)), r->elem);
    return MT_OK;
}

mt_status_t mt_oring_update_front(mt_oring_t *r, const void *obj)
{
    if (consumer_sync(r) == 0u) {
        return MT_E_EMPTY;
    }
    mt_copy_bytes(slot_ptr(r, mt_idx_slot(r->head, r->slots)), (const uint8_t *)obj, r->elem);
    return MT_OK;
}

uint32_t mt_oring_flush(mt_oring_t *r)
{
    uint32_t n = consumer_sync(r);
    mt_store_release_u32(&r->head, r->tail_cache);
    return n;
}

bool mt_oring_valid(const mt_oring_t *r)
{
    uint32_t s = r->slots;
    uint32_t count;
    uint32_t filled;

    /* cap < MT_ORING_BYTES_MAX keeps cap + 1 from wrapping; s * elem <= MT_ORING_BYTES_MAX with
     * elem >= 1 bounds s by MT_RING_SLOTS_MAX, which the index checks need */
    if ((r->cap < 1u) || (r->cap >= MT_ORING_BYTES_MAX) || (s != (r->cap + 1u)) || (r->elem < 1u) ||
        (((uint64_t)s * (uint64_t)r->elem) > (uint64_t)MT_ORING_BYTES_MAX)) {
        return false;
    }
    if (!mt_idx_ok(r->head, s) || !mt_idx_ok(r->tail, s) || !mt_idx_ok(r->head_cache, s) ||
        !mt_idx_ok(r->tail_cache, s)) {
        return false;
    }
    count = mt_idx_count(r->tail, r->head, s);
    filled = mt_idx_count(r->tail, r->head_cache, s);
    return (count <= s) && (mt_idx_count(r->head, r->head_cache, s) <= filled) && (filled <= s) &&
           (mt_idx_count(r->tail_cache, r->head, s) <= count);
}
