/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/wordring.h
 * @brief Lock-free SPSC ring of 32-bit words with a compile-time capacity: the fast path of
 *        the object ring (mt/objring.h) for word-sized objects (indices, handles, packed
 *        samples), as boost's spsc_queue with a compile-time capacity is for its users.
 *
 * Operating rules (as mt/ring.h, plus):
 * - Every word ring holds MT_CFG_WRING_CAP words (config, default 256) in
 *   MT_CFG_WRING_CAP + 1 slots inside the structure: no storage to pass, and the index
 *   arithmetic folds to constants. Indices are slot numbers in [0, MT_WRING_SLOTS); one
 *   slot stays free, so the ring is full when the next write slot is the read slot.
 * - push, pop and available are inline (static inline here, proved in kernel/src/wordring.c,
 *   where WP and the CBMC harnesses see them as every caller does). A push on a full ring
 *   returns MT_E_FULL and counts it in `rejected`; nothing is overwritten.
 * - Producer: push only; consumer: pop and available. Each side writes only its own index and
 *   caches the other's, re-reading it (acquire) only when the cached view says full or empty.
 *   The word is stored before the index is published (release), and read before the slot is
 *   released. This is the protocol tla/Ring.tla checks for ring and objring, there with
 *   mirror indices; the slot-index form here is checked by WP and CBMC against sequential
 *   contracts (assumption C2), not by a model of its own.
 */
#ifndef MT_WORDRING_H
#define MT_WORDRING_H

#include <stdint.h>

#include "mt/config.h"
#include "mt/ring.h"
#include "mt/status.h"
#include "mt_atomic.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Slots of a word ring: the capacity plus the free slot. */
#define MT_WRING_SLOTS (MT_CFG_WRING_CAP + 1u)

typedef struct {
    /* producer half */
    uint32_t tail;       /**< next slot to write, [0, MT_WRING_SLOTS) */
    uint32_t head_cache; /**< producer's last view of head */
    uint32_t rejected;   /**< pushes refused with MT_E_FULL (saturating) */
    MT_RING_PAD_(p)
    /* consumer half */
    uint32_t head;       /**< next slot to read, [0, MT_WRING_SLOTS) */
    uint32_t tail_cache; /**< consumer's last view of tail */
    uint32_t unused_;    /**< keeps the halves the same shape */
    MT_RING_PAD_(c)
    uint32_t buf[MT_WRING_SLOTS];
} mt_wring_t;

/* Slot arithmetic: MtWNext is the slot after i; MtWCount the words from read slot h to write
 * slot t. The cached indices lag the real ones: head_cache lies between the slot after the
 * last one written and head (so the producer's view of the free room never exceeds the real
 * one), tail_cache between head and tail. */
/*@ logic integer MtWNext(integer i) = i + 1 < MT_WRING_SLOTS ? i + 1 : 0;

    logic integer MtWCount(integer t, integer h) = t >= h ? t - h : t + MT_WRING_SLOTS - h;

    predicate MtWRingInv(mt_wring_t *r) =
        \valid(r) &&
        r->tail < MT_WRING_SLOTS && r->head < MT_WRING_SLOTS &&
        r->head_cache < MT_WRING_SLOTS && r->tail_cache < MT_WRING_SLOTS &&
        MtWCount(r->head, r->head_cache) <= MtWCount(r->tail, r->head_cache) &&
        MtWCount(r->tail_cache, r->head) <= MtWCount(r->tail, r->head);

    logic integer MtWRingCount(mt_wring_t *r) = MtWCount(r->tail, r->head);
*/

/** Empty the ring and clear its counter. [init] */
/*@ requires valid: \valid(r);
    assigns r->tail, r->head_cache, r->rejected, r->head, r->tail_cache, r->unused_;
    ensures inv: MtWRingInv(r);
    ensures empty: MtWRingCount(r) == 0 && r->rejected == 0;
*/
void mt_wring_init(mt_wring_t *r);

/** Append v. [producer]
 *  @retval MT_OK
 *  @retval MT_E_FULL MT_CFG_WRING_CAP words are unread (nothing written; counted in rejected). */
/*@ requires inv: MtWRingInv(r);
    assigns r->tail, r->head_cache, r->rejected, r->buf[r->tail];
    ensures inv: MtWRingInv(r);
    behavior room:
      assumes MtWRingCount(r) < MT_CFG_WRING_CAP;
      ensures status: \result == MT_OK;
      ensures data: r->buf[\old(r->tail)] == v;
      ensures published: r->tail == MtWNext(\old(r->tail));
      ensures counted: r->rejected == \old(r->rejected);
    behavior full:
      assumes MtWRingCount(r) >= MT_CFG_WRING_CAP;
      ensures status: \result == MT_E_FULL;
      ensures unchanged: r->tail == \old(r->tail) && r->buf[r->tail] == \old(r->buf[r->tail]);
      ensures counted: r->rejected == (\old(r->rejected) < 0xFFFFFFFF ? \old(r->rejected) + 1
                                                                      : \old(r->rejected));
    complete behaviors;
    disjoint behaviors;
*/
static inline mt_status_t mt_wring_push(mt_wring_t *r, uint32_t v)
{
    uint32_t t = r->tail;
    // cppcheck-suppress misra-c2012-12.1 ; D-102 fully parenthesised; addon false positive
    uint32_t next = ((t + 1u) < MT_WRING_SLOTS) ? (t + 1u) : 0u;
    mt_status_t st = MT_OK;

    if (next == r->head_cache) {
        r->head_cache = mt_load_acquire_u32(&r->head);
        if (next == r->head_cache) {
            if (r->rejected < 0xFFFFFFFFu) {
                r->rejected++;
            }
            st = MT_E_FULL;
        }
    }
    if (st == MT_OK) {
        r->buf[t] = v;
        /* word before index: the release store publishes it */
        mt_store_release_u32(&r->tail, next);
    }
    return st;
}

/** Remove the oldest word into *out. [consumer]
 *  @retval MT_OK
 *  @retval MT_E_EMPTY nothing to read (*out untouched). */
/*@ requires inv: MtWRingInv(r);
    requires out: \valid(out) && \separated(out, r);
    assigns r->head, r->tail_cache, *out;
    ensures inv: MtWRingInv(r);
    ensures kept: r->tail == \old(r->tail);
    behavior one:
      assumes MtWRingCount(r) > 0;
      ensures status: \result == MT_OK;
      ensures data: *out == r->buf[\old(r->head)];
      ensures consumed: r->head == MtWNext(\old(r->head));
    behavior empty:
      assumes MtWRingCount(r) == 0;
      ensures status: \result == MT_E_EMPTY;
      ensures unchanged: r->head == \old(r->head) && *out == \old(*out);
    complete behaviors;
    disjoint behaviors;
*/
static inline mt_status_t mt_wring_pop(mt_wring_t *r, uint32_t *out)
{
    uint32_t h = r->head;
    mt_status_t st = MT_OK;

    if (h == r->tail_cache) {
        r->tail_cache = mt_load_acquire_u32(&r->tail);
        if (h == r->tail_cache) {
            st = MT_E_EMPTY;
        }
    }
    if (st == MT_OK) {
        *out = r->buf[h];
        /* word read before the slot is released */
        // cppcheck-suppress misra-c2012-12.1 ; D-102 fully parenthesised; addon false positive
        mt_store_release_u32(&r->head, ((h + 1u) < MT_WRING_SLOTS) ? (h + 1u) : 0u);
    }
    return st;
}

/** Words ready to pop (re-reads the producer's index). [consumer] */
/*@ requires inv: MtWRingInv(r);
    assigns r->tail_cache;
    ensures inv: MtWRingInv(r);
    ensures count: \result == MtWRingCount(r);
    ensures fresh: r->tail_cache == r->tail;
*/
static inline uint32_t mt_wring_available(mt_wring_t *r)
{
    uint32_t t = mt_load_acquire_u32(&r->tail);
    uint32_t h = r->head;

    r->tail_cache = t;
    // cppcheck-suppress misra-c2012-12.1 ; D-102 fully parenthesised; addon false positive
    return (t >= h) ? (t - h) : ((t + MT_WRING_SLOTS) - h);
}

#ifdef __cplusplus
}
#endif

#endif /* MT_WORDRING_H */
