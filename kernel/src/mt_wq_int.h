/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_wq_int.h
 * @brief The work queue's internal functions (kernel-private): the helpers of the queue core
 *        (wq.c) that the other files of the module (wq_timer.c, wq_run.c, wq_report.c) call.
 *
 * Each is defined in wq.c, proved there against the contract below, and used through this
 * contract by the callers in the other files.
 */
#ifndef MT_WQ_INT_H
#define MT_WQ_INT_H

#include <stdint.h>

#include "mt/wq.h"

/** 1 when slot s is queued, else 0. */
/*@ requires inv: \valid_read(q) && MtWqFifo(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    assigns \nothing;
    ensures bool: \result == 0 || \result == 1;
    ensures queued: \result == 1 <==> MtWqQueued(q, s);
*/
uint32_t mt_wq_is_queued(const mt_wq_t *q, uint32_t s);

/** Wake the queue's thread (lock held). */
/*@ requires held: MtLocked == 1;
    requires inv: MtWqInv(q);
    assigns q->wake, MtPortWakes;
    ensures inv: MtWqInv(q);
    ensures woken: MtWqWoken{Pre, Post}(q);
*/
void mt_wq_wake_i(mt_wq_t *q);

/** Activate slot s at time now (the core of every scheduling path). */
/*@ requires held: MtLocked == 1;
    requires inv: MtWqInv(q);
    requires slot: s < q->nitems;
    assigns q->order[0 .. MT_CFG_WQ_MAX_ITEMS - 1], q->where[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
            q->count, q->max_depth, q->slot[s].queued_us, q->slot[s].stats.merged,
            q->stats.merged, q->wake, MtPortWakes;
    ensures inv: MtWqInv(q);
    ensures queued: MtWqQueued(q, s);
    ensures fifo_kept: MtWqFifoKept{Pre, Post}(q);
    ensures others_idle: MtWqIdleKept{Pre, Post}(q, s);
    behavior queue:
      assumes !MtWqQueued(q, s);
      ensures status: \result == MT_OK;
      ensures tail: q->count == \old(q->count) + 1 && MtWqRel(q, q->where[s]) == \old(q->count);
      ensures stamped: q->slot[s].queued_us == now;
      ensures depth: MtWqDepth{Pre, Post}(q);
      ensures not_merged: MtWqMergesKept{Pre, Post}(q, s);
      ensures woken: MtWqWoken{Pre, Post}(q);
    behavior merge:
      assumes MtWqQueued(q, s);
      ensures status: \result == MT_W_WQ_MERGED;
      ensures same: q->count == \old(q->count);
      ensures stamp_kept: q->slot[s].queued_us == \old(q->slot[s].queued_us);
      ensures depth_kept: q->max_depth == \old(q->max_depth);
      ensures not_woken: MtWqNotWoken{Pre, Post}(q);
      ensures counted: q->slot[s].stats.merged == (\old(q->slot[s].stats.merged) < 0xFFFFFFFF ?
                                                   \old(q->slot[s].stats.merged) + 1 : 0xFFFFFFFF);
      ensures counted_wq: q->stats.merged == (\old(q->stats.merged) < 0xFFFFFFFF ?
                                              \old(q->stats.merged) + 1 : 0xFFFFFFFF);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_wq_schedule_slot_i(mt_wq_t *q, uint32_t s, uint64_t now);

#endif /* MT_WQ_INT_H */
