/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/ring.h
 * @brief Lock-free single-producer single-consumer byte ring.
 *
 * Operating rules
 * - Exactly one producer context and one consumer context (a thread, the
 *   timer thread or an ISR each). Functions are tagged [producer] or
 *   [consumer]; mt_bring_init runs before either side starts.
 * - Each side writes only its own half of the struct: the producer writes
 *   tail, head_cache and reserved; the consumer writes head and tail_cache.
 * - Data is written before the producer publishes tail (release store) and
 *   read after the consumer loads tail (acquire load); symmetrically the
 *   consumer finishes reading before it publishes head, so freed space is
 *   reused only after the reader is done. The TLA+ model tla/Ring.tla
 *   checks this ordering at the granularity of single memory operations.
 * - Each side keeps a cached copy of the other side's index and reloads it
 *   only when the cached view says full (producer) or empty (consumer).
 * - Full capacity: a ring of cap bytes holds cap bytes (mirror indices in
 *   [0, 2*cap), see mt_spec_ring.h); any cap in [1, MT_RING_SLOTS_MAX] works.
 */
#ifndef MT_RING_H
#define MT_RING_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/config.h"
#include "mt/status.h"
#include "mt_spec.h"
#include "mt_spec_ring.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest capacity of a byte ring, in bytes. */
#define MT_BRING_CAP_MAX 0x40000000u

/** One contiguous piece of a ring's storage. */
typedef struct {
    uint8_t *base;
    uint32_t len;
} mt_iovec_t;

#if MT_CFG_CACHE_LINE > 0u
#define MT_RING_PAD_(n) uint8_t pad_##n[MT_CFG_CACHE_LINE - (3u * sizeof(uint32_t))];
#else
#define MT_RING_PAD_(n)
#endif

typedef struct {
    /* producer half */
    uint32_t tail;       /**< write index, [0, 2*cap) (published with release) */
    uint32_t head_cache; /**< producer's last view of head */
    uint32_t reserved;   /**< bytes handed out by mt_bring_reserve, not committed */
    MT_RING_PAD_(p)
    /* consumer half */
    uint32_t head;       /**< read index, [0, 2*cap) (published with release) */
    uint32_t tail_cache; /**< consumer's last view of tail */
    uint32_t unused_;    /**< keeps the halves the same shape */
    MT_RING_PAD_(c)
    /* constant after init */
    uint8_t *buf;
    uint32_t cap;
} mt_bring_t;

/*@ predicate MtBRingShape(mt_bring_t *r) =
        \valid(r) && 1 <= r->cap <= MT_BRING_CAP_MAX &&
        \valid(r->buf + (0 .. r->cap - 1)) &&
        \separated(r, r->buf + (0 .. r->cap - 1));

    predicate MtBRingInv(mt_bring_t *r) =
        MtBRingShape(r) &&
        MtIdxOk(r->head, r->cap) && MtIdxOk(r->tail, r->cap) &&
        MtIdxCount(r->tail, r->head, r->cap) <= r->cap &&
        MtIdxOk(r->head_cache, r->cap) && MtIdxOk(r->tail_cache, r->cap) &&
        MtIdxCount(r->head, r->head_cache, r->cap) <= MtIdxCount(r->tail, r->head_cache, r->cap) &&
        MtIdxCount(r->tail, r->head_cache, r->cap) <= r->cap &&
        MtIdxCount(r->tail_cache, r->head, r->cap) <= MtIdxCount(r->tail, r->head, r->cap) &&
        r->reserved <= r->cap - MtIdxCount(r->tail, r->head, r->cap) &&
        r->reserved <= r->cap - MtIdxCount(r->tail, r->head_cache, r->cap);

    logic integer MtBRingCount(mt_bring_t *r) = MtIdxCount(r->tail, r->head, r->cap);

    logic integer MtBRingByte(mt_bring_t *r, integer k) =
        r->buf[MtIdxSlot(MtIdxAdd(r->head, k, r->cap), r->cap)];
*/

/** Initialise a ring over caller storage of cap bytes. [init]
 *  @retval MT_OK
 *  @retval MT_E_INVALID cap is 0 or above MT_BRING_CAP_MAX (the ring is left
 *          with cap 0 and every operation on it is a contract violation). */
/*@ requires valid: \valid(r);
    requires storage: cap >= 1 ==> cap <= MT_BRING_CAP_MAX ==> \valid(storage + (0 .. cap - 1));
    requires sep: cap >= 1 ==> cap <= MT_BRING_CAP_MAX ==> \separated(r, storage + (0 .. cap - 1));
    assigns *r;
    behavior ok:
      assumes 1 <= cap <= MT_BRING_CAP_MAX;
      ensures status: \result == MT_OK;
      ensures inv: MtBRingInv(r);
      ensures empty: MtBRingCount(r) == 0 && r->cap == cap && r->buf == storage;
      ensures unreserved: r->reserved == 0;
    behavior bad_cap:
      assumes cap < 1 || cap > MT_BRING_CAP_MAX;
      ensures status: \result == MT_E_INVALID;
      ensures unusable: r->cap == 0;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_bring_init(mt_bring_t *r, uint8_t *storage, uint32_t cap);

/** Free bytes. [producer] */
/*@ requires inv: MtBRingInv(r);
    assigns r->head_cache;
    ensures inv: MtBRingInv(r);
    ensures space: \result == r->cap - MtBRingCount(r) - r->reserved;
*/
uint32_t mt_bring_space(mt_bring_t *r);

/** Copy up to len bytes in; returns the number written, min(len, space).
 *  Never overwrites unread data. [producer] */
/*@ requires inv: MtBRingInv(r);
    requires no_reservation: r->reserved == 0;
    requires src: \valid_read(src + (0 .. len - 1));
    requires sep: \separated(src + (0 .. len - 1), r, r->buf + (0 .. r->cap - 1));
    assigns r->tail, r->head_cache, r->buf[0 .. r->cap - 1];
    ensures inv: MtBRingInv(r);
    ensures written: \result == \min(len, r->cap - MtIdxCount(\old(r->tail), r->head, r->cap));
    ensures published: r->tail == MtIdxAdd(\old(r->tail), \result, r->cap);
    ensures data: \forall integer k; 0 <= k < \result ==>
        r->buf[MtIdxSlot(MtIdxAdd(\old(r->tail), k, r->cap), r->cap)] == src[k];
    ensures no_overwrite: \forall integer k; 0 <= k < MtIdxCount(\old(r->tail), r->head, r->cap) ==>
        MtBRingByte(r, k) == \old(MtBRingByte(r, k));
*/
uint32_t mt_bring_write(mt_bring_t *r, const uint8_t *src, uint32_t len);

/** Hand out up to len free bytes as at most two segments for zero-copy
 *  writing; returns the number of segments (0, 1 or 2) and records the total
 *  as the reservation. [producer] */
/*@ requires inv: MtBRingInv(r);
    requires vec: \valid(vec + (0 .. 1));
    requires sep: \separated(vec + (0 .. 1), r);
    assigns r->head_cache, r->reserved, vec[0 .. 1];
    ensures inv: MtBRingInv(r);
    ensures reserved: r->reserved == \min(len, r->cap - MtBRingCount(r));
    ensures segs: 0 <= \result <= 2;
    ensures total: (\result == 0 ==> r->reserved == 0) &&
                   (\result == 1 ==> vec[0].len == r->reserved && vec[1].len == 0) &&
                   (\result == 2 ==> vec[0].len + vec[1].len == r->reserved && vec[0].len > 0 && vec[1].len > 0);
    ensures first: \result >= 1 ==> vec[0].base == r->buf + MtIdxSlot(r->tail, r->cap);
    ensures second: \result == 2 ==> vec[1].base == r->buf;
    ensures split: vec[0].len == \min(r->reserved, r->cap - MtIdxSlot(r->tail, r->cap)) &&
                   vec[1].len == r->reserved - vec[0].len;
    ensures count: \result == (r->reserved == 0 ? 0 : vec[1].len == 0 ? 1 : 2);
*/
uint32_t mt_bring_reserve(mt_bring_t *r, mt_iovec_t vec[2], uint32_t len);

/** Publish n bytes of the current reservation. [producer]
 *  @retval MT_OK
 *  @retval MT_E_RANGE n exceeds the reservation (nothing is published). */
/*@ requires inv: MtBRingInv(r);
    assigns r->tail, r->reserved;
    ensures inv: MtBRingInv(r);
    behavior ok:
      assumes n <= r->reserved;
      ensures status: \result == MT_OK;
      ensures published: r->tail == MtIdxAdd(\old(r->tail), n, r->cap);
      ensures released: r->reserved == 0;
    behavior too_many:
      assumes n > r->reserved;
      ensures status: \result == MT_E_RANGE;
      ensures unchanged: r->tail == \old(r->tail) && r->reserved == \old(r->reserved);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_bring_commit(mt_bring_t *r, uint32_t n);

/** Readable bytes. [consumer] */
/*@ requires inv: MtBRingInv(r);
    assigns r->tail_cache;
    ensures inv: MtBRingInv(r);
    ensures count: \result == MtBRingCount(r);
*/
uint32_t mt_bring_available(mt_bring_t *r);

/** Copy up to len bytes out without consuming them; returns min(len, available). [consumer] */
/*@ requires inv: MtBRingInv(r);
    requires dst: \valid(dst + (0 .. len - 1));
    requires sep: \separated(dst + (0 .. len - 1), r, r->buf + (0 .. r->cap - 1));
    assigns r->tail_cache, dst[0 .. len - 1];
    ensures inv: MtBRingInv(r);
    ensures copied: \result == \min(len, MtBRingCount(r));
    ensures head: r->head == \old(r->head);
    ensures fifo: \forall integer k; 0 <= k < \result ==> dst[k] == MtBRingByte(r, k);
*/
uint32_t mt_bring_peek(mt_bring_t *r, uint8_t *dst, uint32_t len);

/** Copy up to len bytes out and consume them; returns min(len, available). [consumer] */
/*@ requires inv: MtBRingInv(r);
    requires dst: \valid(dst + (0 .. len - 1));
    requires sep: \separated(dst + (0 .. len - 1), r, r->buf + (0 .. r->cap - 1));
    assigns r->tail_cache, r->head, dst[0 .. len - 1];
    ensures inv: MtBRingInv(r);
    ensures copied: \result == \min(len, MtIdxCount(r->tail, \old(r->head), r->cap));
    ensures consumed: r->head == MtIdxAdd(\old(r->head), \result, r->cap);
    ensures fifo: \forall integer k; 0 <= k < \result ==>
        dst[k] == r->buf[MtIdxSlot(MtIdxAdd(\old(r->head), k, r->cap), r->cap)];
*/
uint32_t mt_bring_read(mt_bring_t *r, uint8_t *dst, uint32_t len);

/** Drop n readable bytes. [consumer]
 *  @retval MT_OK
 *  @retval MT_E_RANGE n exceeds the readable bytes (nothing is dropped). */
/*@ requires inv: MtBRingInv(r);
    assigns r->tail_cache, r->head;
    ensures inv: MtBRingInv(r);
    behavior ok:
      assumes n <= MtBRingCount(r);
      ensures status: \result == MT_OK;
      ensures consumed: r->head == MtIdxAdd(\old(r->head), n, r->cap);
    behavior too_many:
      assumes n > MtBRingCount(r);
      ensures status: \result == MT_E_RANGE;
      ensures unchanged: r->head == \old(r->head);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_bring_advance(mt_bring_t *r, uint32_t n);

/** Describe the readable bytes as at most two segments (zero-copy read; follow
 *  with mt_bring_advance). Returns the number of segments. [consumer] */
/*@ requires inv: MtBRingInv(r);
    requires vec: \valid(vec + (0 .. 1));
    requires sep: \separated(vec + (0 .. 1), r);
    assigns r->tail_cache, vec[0 .. 1];
    ensures inv: MtBRingInv(r);
    ensures segs: 0 <= \result <= 2;
    ensures total: (\result == 0 ==> MtBRingCount(r) == 0) &&
                   (\result == 1 ==> vec[0].len == MtBRingCount(r) && vec[1].len == 0) &&
                   (\result == 2 ==> vec[0].len + vec[1].len == MtBRingCount(r) && vec[0].len > 0 && vec[1].len > 0);
    ensures first: \result >= 1 ==> vec[0].base == r->buf + MtIdxSlot(r->head, r->cap);
    ensures second: \result == 2 ==> vec[1].base == r->buf;
    ensures split: vec[0].len == \min(MtBRingCount(r), r->cap - MtIdxSlot(r->head, r->cap)) &&
                   vec[1].len == MtBRingCount(r) - vec[0].len;
    ensures count: \result == (MtBRingCount(r) == 0 ? 0 : vec[1].len == 0 ? 1 : 2);
*/
uint32_t mt_bring_peek_vec(mt_bring_t *r, mt_iovec_t vec[2]);

/** Drop everything readable now (the consumer's own clear; the producer's
 *  index is never written). Returns the number of bytes dropped. [consumer] */
/*@ requires inv: MtBRingInv(r);
    assigns r->tail_cache, r->head;
    ensures inv: MtBRingInv(r);
    ensures dropped: \result == MtIdxCount(r->tail, \old(r->head), r->cap);
    ensures empty: MtBRingCount(r) == 0;
*/
uint32_t mt_bring_flush(mt_bring_t *r);

/** Constant-time validity check, the C twin of MtBRingInv: capacity bound and every index
 *  relation of the invariant. What C cannot check (the buffer is valid memory, separated
 *  from the ring object) is its precondition. For debug assertions and tests; it reads both
 *  sides' indices, so call it while neither side runs. [any context, pure] */
/*@ requires obj: \valid(r);
    requires mem: 1 <= r->cap <= MT_BRING_CAP_MAX ==>
        \valid(r->buf + (0 .. r->cap - 1)) && \separated(r, r->buf + (0 .. r->cap - 1));
    assigns \nothing;
    ensures twin: \result != 0 <==> MtBRingInv(r);
*/
bool mt_bring_valid(const mt_bring_t *r);

#ifdef __cplusplus
}
#endif

#endif /* MT_RING_H */
