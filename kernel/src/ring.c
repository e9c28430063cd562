/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file ring.c
 * @brief SPSC byte ring (see mt/ring.h for the operating rules).
 */
#include "mt/ring.h"

#include "mt_atomic.h"
#include "mt_copy.h"
#include "mt_ring_idx.h"

mt_status_t mt_bring_init(mt_bring_t *r, uint8_t *storage, uint32_t cap)
{
    r->tail = 0u;
    r->head_cache = 0u;
    r->reserved = 0u;
    r->head = 0u;
    r->tail_cache = 0u;
    r->unused_ = 0u;
    r->buf = storage;
    if ((cap < 1u) || (cap > MT_BRING_CAP_MAX)) {
        r->cap = 0u;
        return MT_E_INVALID;
    }
    r->cap = cap;
    return MT_OK;
}

/* Producer: free bytes seen with the cached head; reload head only when the
 * cached view has fewer than `want` free bytes. */
/*@ requires MtBRingInv(r);
    assigns r->head_cache;
    ensures MtBRingInv(r);
    ensures \result == r->cap - MtIdxCount(r->tail, r->head_cache, r->cap);
    ensures \result >= \min(want, r->cap - MtBRingCount(r));
    ensures \result <= r->cap - MtBRingCount(r);
*/
static uint32_t bring_producer_free(mt_bring_t *r, uint32_t want)
{
    uint32_t free_now = r->cap - mt_idx_count(r->tail, r->head_cache, r->cap);
    if (free_now < want) {
        r->head_cache = mt_load_acquire_u32(&r->head);
        free_now = r->cap - mt_idx_count(r->tail, r->head_cache, r->cap);
    }
    return free_now;
}

/* Consumer: readable bytes seen with the cached tail, reloaded when short. */
/*@ requires MtBRingInv(r);
    assigns r->tail_cache;
    ensures MtBRingInv(r);
    ensures \result == MtIdxCount(r->tail_cache, r->head, r->cap);
    ensures \result >= \min(want, MtBRingCount(r));
    ensures \result <= MtBRingCount(r);
*/
static uint32_t consumer_avail(mt_bring_t *r, uint32_t want)
{
    uint32_t avail = mt_idx_count(r->tail_cache, r->head, r->cap);
    if (avail < want) {
        r->tail_cache = mt_load_acquire_u32(&r->tail);
        avail = mt_idx_count(r->tail_cache, r->head, r->cap);
    }
    return avail;
}

uint32_t mt_bring_space(mt_bring_t *r)
{
    r->head_cache = mt_load_acquire_u32(&r->head);
    return (r->cap - mt_idx_count(r->tail, r->head_cache, r->cap)) - r->reserved;
}

/* Consumer: reload the cached tail; returns the readable bytes. */
/*@ requires MtBRingInv(r);
    assigns r->tail_cache;
    ensures MtBRingInv(r);
    ensures r->tail_cache == r->tail;
    ensures \result == MtBRingCount(r);
*/
static uint32_t bring_consumer_sync(mt_bring_t *r)
{
    r->tail_cache = mt_load_acquire_u32(&r->tail);
    return mt_idx_count(r->tail_cache, r->head, r->cap);
}

uint32_t mt_bring_available(mt_bring_t *r)
{
    return bring_consumer_sync(r);
}

/* Producer: src[0 .. first - 1] into buf[slot ..], src[first .. n - 1] into buf[0 ..]. */
/*@ requires first <= n && n - first <= slot;
    requires \valid(buf + (0 .. slot + first - 1)) && \valid_read(src + (0 .. n - 1));
    requires \separated(buf + (0 .. slot + first - 1), src + (0 .. n - 1));
    assigns buf[slot .. slot + first - 1], buf[0 .. n - first - 1];
    ensures lo: \forall integer j; 0 <= j < first ==> buf[slot + j] == src[j];
    ensures hi: \forall integer j; first <= j < n ==> buf[j - first] == src[j];
*/
static void put_bytes(uint8_t *buf, uint32_t slot, uint32_t first, const uint8_t *src, uint32_t n)
{
    mt_copy_bytes(buf + slot, src, first);
    if (n > first) {
        mt_copy_bytes(buf, src + first, n - first);
    }
}

uint32_t mt_bring_write(mt_bring_t *r, const uint8_t *src, uint32_t len)
{
    uint32_t free_now = bring_producer_free(r, len);
    uint32_t n = (len < free_now) ? len : free_now;
    uint32_t slot = mt_idx_slot(r->tail, r->cap);
    uint32_t first = r->cap - slot;

    if (first > n) {
        first = n;
    }
    /* two segments: up to the end of the storage, then from its start (n - first <= slot) */
    //@ assert apart: n - first <= slot;
    //@ ghost mt_idx_slot_add_lemma(r->tail, r->cap);
    /*@ assert lo: \forall integer j; 0 <= j < first ==>
            MtIdxSlot(MtIdxAdd(r->tail, j, r->cap), r->cap) == slot + j; */
    /*@ assert hi: \forall integer j; first <= j < n ==>
            MtIdxSlot(MtIdxAdd(r->tail, j, r->cap), r->cap) == j - first; */
    put_bytes(r->buf, slot, first, src, n);
    /*@ assert data_lo: \forall integer j; 0 <= j < first ==>
            r->buf[MtIdxSlot(MtIdxAdd(r->tail, j, r->cap), r->cap)] == src[j]; */
    /*@ assert data_hi: \forall integer j; first <= j < n ==>
            r->buf[MtIdxSlot(MtIdxAdd(r->tail, j, r->cap), r->cap)] == src[j]; */
    /* Data before index: the release store publishes the bytes above. */
    mt_store_release_u32(&r->tail, mt_idx_add(r->tail, n, r->cap));
    return n;
}

uint32_t mt_bring_reserve(mt_bring_t *r, mt_iovec_t vec[2], uint32_t len)
{
    uint32_t free_now = bring_producer_free(r, len);
    uint32_t n = (len < free_now) ? len : free_now;
    uint32_t slot = mt_idx_slot(r->tail, r->cap);
    uint32_t first = r->cap - slot;
    uint32_t segs;

    r->reserved = n;
    //@ assert fits: n <= r->cap - MtIdxCount(r->tail, r->head_cache, r->cap) && n <= r->cap - MtBRingCount(r);
    //@ assert inv_kept: MtBRingInv(r);
    vec[1].base = r->buf;
    vec[1].len = 0u;
    if (n == 0u) {
        vec[0].base = r->buf + slot;
        vec[0].len = 0u;
        segs = 0u;
    } else if (first >= n) {
        vec[0].base = r->buf + slot;
        vec[0].len = n;
        segs = 1u;
    } else {
        vec[0].base = r->buf + slot;
        vec[0].len = first;
        vec[1].len = n - first;
        segs = 2u;
    }
    return segs;
}

mt_status_t mt_bring_commit(mt_bring_t *r, uint32_t n)
{
    if (n > r->reserved) {
        return MT_E_RANGE;
    }
    r->reserved = 0u;
    mt_store_release_u32(&r->tail, mt_idx_add(r->tail, n, r->cap));
    return MT_OK;
}

/* Copy n readable bytes starting at the read index into dst (no consume). */
/*@ requires MtBRingInv(r);
    requires n <= MtBRingCount(r);
    requires \valid(dst + (0 .. n - 1));
    requires \separated(dst + (0 .. n - 1), r, r->buf + (0 .. r->cap - 1));
    assigns dst[0 .. n - 1];
    ensures \forall integer k; 0 <= k < n ==> dst[k] == MtBRingByte(r, k);
*/
static void copy_out(const mt_bring_t *r, uint8_t *dst, uint32_t n)
{
    uint32_t slot = mt_idx_slot(r->head, r->cap);
    uint32_t first = r->cap - slot;

    if (first > n) {
        first = n;
    }
    mt_copy_bytes(dst, r->buf + slot, first);
    if (n > first) {
        mt_copy_bytes(dst + first, r->buf, n - first);
    }
    //@ assert seg_lo: \forall integer j; 0 <= j < first ==> dst[j] == r->buf[slot + j];
    //@ assert seg_hi: \forall integer j; first <= j < n ==> dst[j] == r->buf[j - first];
    //@ ghost mt_idx_slot_add_lemma(r->head, r->cap);
    /*@ assert lo: \forall integer j; 0 <= j < first ==>
            MtIdxSlot(MtIdxAdd(r->head, j, r->cap), r->cap) == slot + j; */
    /*@ assert hi: \forall integer j; first <= j < n ==>
            MtIdxSlot(MtIdxAdd(r->head, j, r->cap), r->cap) == j - first; */
    //@ assert e1: \forall integer j; 0 <= j < first ==> dst[j] == MtBRingByte(r, j);
    //@ assert e2: \forall integer j; first <= j < n ==> dst[j] == MtBRingByte(r, j);
}

/* Copy min(len, readable) bytes out without consuming them (peek and read). */
/*@ requires MtBRingInv(r);
    requires \valid(dst + (0 .. len - 1));
    requires \separated(dst + (0 .. len - 1), r, r->buf + (0 .. r->cap - 1));
    assigns r->tail_cache, dst[0 .. len - 1];
    ensures MtBRingInv(r);
    ensures \result == \min(len, MtBRingCount(r));
    ensures \result <= MtIdxCount(r->tail_cache, r->head, r->cap);
    ensures \forall integer k; 0 <= k < \result ==> dst[k] == MtBRingByte(r, k);
*/
static uint32_t copy_readable(mt_bring_t *r, uint8_t *dst, uint32_t len)
{
    uint32_t avail = consumer_avail(r, len);
    uint32_t n = (len < avail) ? len : avail;
    copy_out(r, dst, n);
    return n;
}

uint32_t mt_bring_peek(mt_bring_t *r, uint8_t *dst, uint32_t len)
{
    return copy_readable(r, dst, len);
}

uint32_t mt_bring_read(mt_bring_t *r, uint8_t *dst, uint32_t len)
{
    uint32_t n = copy_readable(r, dst, len);
    /* Reading done before the index moves: the release store frees the space. */
    mt_store_release_u32(&r->head, mt_idx_add(r->head, n, r->cap));
    return n;
}

mt_status_t mt_bring_advance(mt_bring_t *r, uint32_t n)
{
    uint32_t avail = consumer_avail(r, n);
    if (n > avail) {
        return MT_E_RANGE;
    }
    mt_store_release_u32(&r->head, mt_idx_add(r->head, n, r->cap));
    return MT_OK;
}

uint32_t mt_bring_peek_vec(mt_bring_t *r, mt_iovec_t vec[2])
{
    uint32_t n = bring_consumer_sync(r);
    uint32_t slot = mt_idx_slot(r->head, r->cap);
    uint32_t first = r->cap - slot;
    uint32_t segs;

    vec[0].base = r->buf + slot;
    vec[1].base = r->buf;
    vec[1].len = 0u;
    if (n == 0u) {
        vec[0].len = 0u;
        segs = 0u;
    } else if (first >= n) {
        vec[0].len = n;
        segs = 1u;
    } else {
        vec[0].len = first;
        vec[1].len = n - first;
        segs = 2u;
    }
    return segs;
}

uint32_t mt_bring_flush(mt_bring_t *r)
{
    uint32_t n = bring_consumer_sync(r);
    mt_store_release_u32(&r->head, r->tail_cache);
    return n;
}

bool mt_bring_valid(const mt_bring_t *r)
{
    uint32_t cap = r->cap;
    uint32_t count;
    uint32_t filled;

    if ((cap < 1u) || (cap > MT_BRING_CAP_MAX) || !mt_idx_ok(r->head, cap) || !mt_idx_ok(r->tail, cap) ||
        !mt_idx_ok(r->head_cache, cap) || !mt_idx_ok(r->tail_cache, cap)) {
        return false;
    }
    count = mt_idx_count(r->tail, r->head, cap);
    filled = mt_idx_count(r->tail, r->head_cache, cap);
    return (count <= cap) && (mt_idx_count(r->head, r->head_cache, cap) <= filled) &&
           (filled <= cap) && (mt_idx_count(r->tail_cache, r->head, cap) <= count) &&
           (r->reserved <= (cap - count)) && (r->reserved <= (cap - filled));
}
