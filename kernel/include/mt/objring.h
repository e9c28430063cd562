/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/objring.h
 * @brief Lock-free SPSC ring of fixed-size objects, with a drop-oldest push
 *        that keeps the single-writer rule.
 *
 * Operating rules (as mt/ring.h, plus):
 * - Storage holds cap + 1 slots of elem bytes (MT_ORING_STORAGE_BYTES); the
 *   ring holds cap objects. Indices are mirror indices over S = cap + 1 slots.
 * - mt_oring_push() never overwrites: MT_E_FULL when cap objects are unread.
 * - mt_oring_push_drop_oldest() on a full ring writes the new object into the
 *   spare slot (never an unread one) and publishes it, leaving cap + 1 objects
 *   published. The producer never writes the consumer's index: the consumer,
 *   on its next operation, sees more than cap objects and discards the oldest
 *   itself, counting it in `lost`. Unlike ArduPilot's push_force, the oldest
 *   object is dropped by its owner. If the consumer has not caught up since the
 *   previous drop (cap + 1 published), the push fails with MT_E_FULL and the
 *   producer counts it in `rejected`: no object is ever lost uncounted.
 * - update_front overwrites the oldest retained object in place (consumer).
 */
#ifndef MT_OBJRING_H
#define MT_OBJRING_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/config.h"
#include "mt/ring.h"
#include "mt/status.h"
#include "mt_spec_ring.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest storage in bytes ((cap + 1) * elem). */
#define MT_ORING_BYTES_MAX 0x40000000u

/** Storage bytes needed for cap objects of elem bytes. */
#define MT_ORING_STORAGE_BYTES(elem, cap) ((uint32_t)(elem) * ((uint32_t)(cap) + 1u))

typedef struct {
    /* producer half */
    uint32_t tail;       /**< write index, [0, 2*(cap+1)) */
    uint32_t head_cache; /**< producer's last view of head */
    uint32_t rejected;   /**< pushes refused with MT_E_FULL (saturating) */
    MT_RING_PAD_(p)
    /* consumer half */
    uint32_t head;       /**< read index, [0, 2*(cap+1)) */
    uint32_t tail_cache; /**< consumer's last view of tail */
    uint32_t lost;       /**< oldest objects discarded after drop-oldest pushes (saturating) */
    MT_RING_PAD_(c)
    /* constant after init */
    uint8_t *buf;
    uint32_t cap;        /**< objects */
    uint32_t slots;      /**< cap + 1 */
    uint32_t elem;       /**< bytes per object */
} mt_oring_t;

/*@ predicate MtORingInv(mt_oring_t *r) =
        \valid(r) && 1 <= r->cap && r->slots == r->cap + 1 && 1 <= r->elem &&
        r->slots * r->elem <= MT_ORING_BYTES_MAX &&
        \valid(r->buf + (0 .. r->slots * r->elem - 1)) &&
        \separated(r, r->buf + (0 .. r->slots * r->elem - 1)) &&
        MtIdxOk(r->head, r->slots) && MtIdxOk(r->tail, r->slots) &&
        MtIdxOk(r->head_cache, r->slots) && MtIdxOk(r->tail_cache, r->slots) &&
        MtIdxCount(r->tail, r->head, r->slots) <= r->slots &&
        MtIdxCount(r->head, r->head_cache, r->slots) <= MtIdxCount(r->tail, r->head_cache, r->slots) &&
        MtIdxCount(r->tail, r->head_cache, r->slots) <= r->slots &&
        MtIdxCount(r->tail_cache, r->head, r->slots) <= MtIdxCount(r->tail, r->head, r->slots);

    logic integer MtORingCount(mt_oring_t *r) = MtIdxCount(r->tail, r->head, r->slots);
*/

/* Slot contents (buf, elem and slots are constant after init):
 * - MtORingSame: the object in slot `slot` equals the elem bytes at p;
 * - MtORingOthersKept: between L1 and L2 every byte outside slot `slot` is unchanged (a push
 *   writes the free slot only: the unread objects stay, in order);
 * - MtORingBufKept: between L1 and L2 no byte of the storage changed. */
/*@ predicate MtORingSame(mt_oring_t *r, integer slot, uint8_t *p) =
        \forall integer k; 0 <= k < r->elem ==> r->buf[slot * r->elem + k] == p[k];

    predicate MtORingOthersKept{L1, L2}(mt_oring_t *r, integer slot) =
        \forall integer b; 0 <= b < \at(r->slots * r->elem, L1) ==>
            (b < slot * \at(r->elem, L1) || slot * \at(r->elem, L1) + \at(r->elem, L1) <= b) ==>
            \at(r->buf[b], L2) == \at(r->buf[b], L1);

    predicate MtORingBufKept{L1, L2}(mt_oring_t *r) =
        \forall integer b; 0 <= b < \at(r->slots * r->elem, L1) ==>
            \at(r->buf[b], L2) == \at(r->buf[b], L1);
*/

/** Initialise over storage of MT_ORING_STORAGE_BYTES(elem, cap) bytes. [init]
 *  @retval MT_OK
 *  @retval MT_E_INVALID elem or cap is 0, or the storage would exceed
 *          MT_ORING_BYTES_MAX (the ring is left unusable, cap 0). */
/*@ requires valid: \valid(r);
    requires storage: elem >= 1 ==> cap >= 1 ==> (cap + 1) * elem <= MT_ORING_BYTES_MAX ==>
        \valid((uint8_t *)storage + (0 .. (cap + 1) * elem - 1)) &&
        \separated(r, (uint8_t *)storage + (0 .. (cap + 1) * elem - 1));
    assigns *r;
    behavior ok:
      assumes elem >= 1 && cap >= 1 && (cap + 1) * elem <= MT_ORING_BYTES_MAX;
      ensures status: \result == MT_OK;
      ensures inv: MtORingInv(r);
      ensures empty: MtORingCount(r) == 0 && r->cap == cap && r->elem == elem && r->lost == 0 && r->rejected == 0;
      ensures storage: r->buf == (uint8_t *)storage;
    behavior bad:
      assumes elem < 1 || cap < 1 || (cap + 1) * elem > MT_ORING_BYTES_MAX;
      ensures status: \result == MT_E_INVALID;
      ensures unusable: r->cap == 0;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_oring_init(mt_oring_t *r, void *storage, uint32_t elem, uint32_t cap);

/** Append a copy of obj. [producer]
 *  @retval MT_OK
 *  @retval MT_E_FULL cap objects are unread (nothing written; counted in rejected). */
/*@ requires inv: MtORingInv(r);
    requires obj: \valid_read((uint8_t *)obj + (0 .. r->elem - 1));
    requires sep: \separated((uint8_t *)obj + (0 .. r->elem - 1), r, r->buf + (0 .. r->slots * r->elem - 1));
    assigns r->tail, r->head_cache, r->rejected, r->buf[0 .. r->slots * r->elem - 1];
    ensures inv: MtORingInv(r);
    behavior room:
      assumes MtIdxCount(r->tail, r->head, r->slots) < r->cap;
      ensures status: \result == MT_OK;
      ensures published: r->tail == MtIdxAdd(\old(r->tail), 1, r->slots);
      ensures data: \forall integer k; 0 <= k < r->elem ==>
          r->buf[MtIdxSlot(\old(r->tail), r->slots) * r->elem + k] == ((uint8_t *)obj)[k];
      ensures others: MtORingOthersKept{Pre, Post}(r, MtIdxSlot(\old(r->tail), r->slots));
      ensures not_counted: r->rejected == \old(r->rejected);
    behavior full:
      assumes MtIdxCount(r->tail, r->head, r->slots) >= r->cap;
      ensures status: \result == MT_E_FULL;
      ensures unchanged: r->tail == \old(r->tail);
      ensures kept: MtORingBufKept{Pre, Post}(r);
      ensures counted: r->rejected == (\old(r->rejected) < 0xFFFFFFFF ? \old(r->rejected) + 1 : \old(r->rejected));
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_oring_push(mt_oring_t *r, const void *obj);

/** Append a copy of obj; on a full ring the oldest object will be dropped by
 *  the consumer. [producer]
 *  @retval MT_OK                stored, nothing dropped.
 *  @retval MT_W_DROPPED_OLDEST  the ring was full when the push looked: stored in
 *                               the spare slot, and the consumer discards the oldest
 *                               object unless it consumed it meanwhile (a concurrent
 *                               pop can make the drop unnecessary; tla/Ring.tla,
 *                               config Ring_drop_report). The status is therefore
 *                               an upper bound; `lost` counts the actual drops.
 *  @retval MT_E_FULL            the consumer has not caught up since the last
 *                               drop; nothing written (counted in rejected). */
/*@ requires inv: MtORingInv(r);
    requires obj: \valid_read((uint8_t *)obj + (0 .. r->elem - 1));
    requires sep: \separated((uint8_t *)obj + (0 .. r->elem - 1), r, r->buf + (0 .. r->slots * r->elem - 1));
    assigns r->tail, r->head_cache, r->rejected, r->buf[0 .. r->slots * r->elem - 1];
    ensures inv: MtORingInv(r);
    ensures data: \result != MT_E_FULL ==>
        MtORingSame(r, MtIdxSlot(\old(r->tail), r->slots), (uint8_t *)obj);
    ensures others: \result != MT_E_FULL ==>
        MtORingOthersKept{Pre, Post}(r, MtIdxSlot(\old(r->tail), r->slots));
    ensures not_counted: \result != MT_E_FULL ==> r->rejected == \old(r->rejected);
    behavior room:
      assumes MtIdxCount(r->tail, r->head, r->slots) < r->cap;
      ensures status: \result == MT_OK;
      ensures published: r->tail == MtIdxAdd(\old(r->tail), 1, r->slots);
    behavior drop:
      assumes MtIdxCount(r->tail, r->head, r->slots) == r->cap;
      ensures status: \result == MT_W_DROPPED_OLDEST;
      ensures published: r->tail == MtIdxAdd(\old(r->tail), 1, r->slots);
    behavior full:
      assumes MtIdxCount(r->tail, r->head, r->slots) > r->cap;
      ensures status: \result == MT_E_FULL;
      ensures unchanged: r->tail == \old(r->tail);
      ensures kept: MtORingBufKept{Pre, Post}(r);
      ensures counted: r->rejected == (\old(r->rejected) < 0xFFFFFFFF ? \old(r->rejected) + 1 : \old(r->rejected));
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_oring_push_drop_oldest(mt_oring_t *r, const void *obj);

/** Objects a push can still add without dropping. [producer] */
/*@ requires inv: MtORingInv(r);
    assigns r->head_cache;
    ensures inv: MtORingInv(r);
    ensures space: \result == (MtORingCount(r) >= r->cap ? 0 : r->cap - MtORingCount(r));
*/
uint32_t mt_oring_space(mt_oring_t *r);

/** Objects readable (at most cap). [consumer] */
/*@ requires inv: MtORingInv(r);
    assigns r->tail_cache;
    ensures inv: MtORingInv(r);
    ensures count: \result == (MtORingCount(r) > r->cap ? r->cap : MtORingCount(r));
*/
uint32_t mt_oring_available(mt_oring_t *r);

/** Remove the oldest object into out. [consumer]
 *  @retval MT_OK
 *  @retval MT_E_EMPTY nothing to read (out untouched). */
/*@ requires inv: MtORingInv(r);
    requires out: \valid((uint8_t *)out + (0 .. r->elem - 1));
    requires sep: \separated((uint8_t *)out + (0 .. r->elem - 1), r, r->buf + (0 .. r->slots * r->elem - 1));
    assigns r->head, r->tail_cache, r->lost, ((uint8_t *)out)[0 .. r->elem - 1];
    ensures inv: MtORingInv(r);
    ensures retained: MtORingCount(r) <= r->cap;
    behavior empty:
      assumes MtIdxCount(r->tail, r->head, r->slots) == 0;
      ensures status: \result == MT_E_EMPTY;
      ensures unchanged: r->head == \old(r->head);
      ensures untouched: r->lost == \old(r->lost) &&
          \forall integer k; 0 <= k < r->elem ==> ((uint8_t *)out)[k] == \old(((uint8_t *)out)[k]);
    behavior one:
      assumes 1 <= MtIdxCount(r->tail, r->head, r->slots) <= r->cap;
      ensures status: \result == MT_OK;
      ensures consumed: r->head == MtIdxAdd(\old(r->head), 1, r->slots);
      ensures not_lost: r->lost == \old(r->lost);
      ensures fifo: \forall integer k; 0 <= k < r->elem ==>
          ((uint8_t *)out)[k] == r->buf[MtIdxSlot(\old(r->head), r->slots) * r->elem + k];
    behavior drop_then_one:
      assumes MtIdxCount(r->tail, r->head, r->slots) > r->cap;
      ensures status: \result == MT_OK;
      ensures consumed: r->head == MtIdxAdd(\old(r->head), 2, r->slots);
      ensures lost: r->lost == (\old(r->lost) < 0xFFFFFFFF ? \old(r->lost) + 1 : \old(r->lost));
      ensures fifo: MtORingSame(r, MtIdxSlot(MtIdxAdd(\old(r->head), 1, r->slots), r->slots),
                                (uint8_t *)out);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_oring_pop(mt_oring_t *r, void *out);

/** Copy the oldest retained object into out without removing it. [consumer]
 *  @retval MT_OK, MT_E_EMPTY */
/*@ requires inv: MtORingInv(r);
    requires out: \valid((uint8_t *)out + (0 .. r->elem - 1));
    requires sep: \separated((uint8_t *)out + (0 .. r->elem - 1), r, r->buf + (0 .. r->slots * r->elem - 1));
    assigns r->head, r->tail_cache, r->lost, ((uint8_t *)out)[0 .. r->elem - 1];
    ensures inv: MtORingInv(r);
    ensures retained: MtORingCount(r) <= r->cap;
    behavior empty:
      assumes MtIdxCount(r->tail, r->head, r->slots) == 0;
      ensures status: \result == MT_E_EMPTY;
      ensures unchanged: r->head == \old(r->head);
      ensures untouched: r->lost == \old(r->lost) &&
          \forall integer k; 0 <= k < r->elem ==> ((uint8_t *)out)[k] == \old(((uint8_t *)out)[k]);
    behavior one:
      assumes 1 <= MtIdxCount(r->tail, r->head, r->slots) <= r->cap;
      ensures status: \result == MT_OK;
      ensures kept: r->head == \old(r->head) && r->lost == \old(r->lost);
      ensures copied: MtORingSame(r, MtIdxSlot(r->head, r->slots), (uint8_t *)out);
    behavior drop_then_one:
      assumes MtIdxCount(r->tail, r->head, r->slots) > r->cap;
      ensures status: \result == MT_OK;
      ensures dropped: r->head == MtIdxAdd(\old(r->head), 1, r->slots);
      ensures lost: r->lost == (\old(r->lost) < 0xFFFFFFFF ? \old(r->lost) + 1 : \old(r->lost));
      ensures copied: MtORingSame(r, MtIdxSlot(r->head, r->slots), (uint8_t *)out);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_oring_peek(mt_oring_t *r, void *out);

/** Overwrite the oldest retained object in place. [consumer]
 *  @retval MT_OK, MT_E_EMPTY */
/*@ requires inv: MtORingInv(r);
    requires obj: \valid_read((uint8_t *)obj + (0 .. r->elem - 1));
    requires sep: \separated((uint8_t *)obj + (0 .. r->elem - 1), r, r->buf + (0 .. r->slots * r->elem - 1));
    assigns r->head, r->tail_cache, r->lost, r->buf[0 .. r->slots * r->elem - 1];
    ensures inv: MtORingInv(r);
    ensures status: \result == MT_OK || \result == MT_E_EMPTY;
    ensures empty: \result == MT_E_EMPTY <==> MtORingCount(r) == 0;
    ensures dropped: r->head == (MtIdxCount(r->tail, \old(r->head), r->slots) > r->cap ?
                                 MtIdxAdd(\old(r->head), 1, r->slots) : \old(r->head));
    ensures written: \result == MT_OK ==>
        MtORingSame(r, MtIdxSlot(r->head, r->slots), (uint8_t *)obj) &&
        MtORingOthersKept{Pre, Post}(r, MtIdxSlot(r->head, r->slots));
    ensures kept: \result == MT_E_EMPTY ==> MtORingBufKept{Pre, Post}(r);
    ensures lost: r->lost == (\old(MtORingCount(r)) > r->cap && \old(r->lost) < 0xFFFFFFFF ?
                              \old(r->lost) + 1 : \old(r->lost));
*/
mt_status_t mt_oring_update_front(mt_oring_t *r, const void *obj);

/** Drop everything readable (consumer's own clear). Returns the number of
 *  objects dropped (drops pending after a drop-oldest push count as lost). [consumer] */
/*@ requires inv: MtORingInv(r);
    assigns r->head, r->tail_cache, r->lost;
    ensures inv: MtORingInv(r);
    ensures empty: MtORingCount(r) == 0;
    ensures flushed: \result == (\old(MtORingCount(r)) > r->cap ? r->cap : \old(MtORingCount(r)));
    ensures lost: r->lost == (\old(MtORingCount(r)) > r->cap && \old(r->lost) < 0xFFFFFFFF ?
                              \old(r->lost) + 1 : \old(r->lost));
*/
uint32_t mt_oring_flush(mt_oring_t *r);

/** Constant-time validity check, the C twin of MtORingInv: sizes, the storage bound and
 *  every index relation of the invariant. What C cannot check (the storage is valid memory,
 *  separated from the ring object) is its precondition. For debug assertions and tests; it
 *  reads both sides' indices, so call it while neither side runs. [any context, pure] */
/*@ requires obj: \valid(r);
    requires mem: 1 <= r->elem && 1 <= r->slots && r->slots * r->elem <= MT_ORING_BYTES_MAX ==>
        \valid(r->buf + (0 .. r->slots * r->elem - 1)) &&
        \separated(r, r->buf + (0 .. r->slots * r->elem - 1));
    assigns \nothing;
    ensures twin: \result != 0 <==> MtORingInv(r);
*/
bool mt_oring_valid(const mt_oring_t *r);

#ifdef __cplusplus
}
#endif

#endif /* MT_OBJRING_H */
