/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/wq_timer.h
 * @brief Work queues, the timers (kernel/src/wq_timer.c): delayed and interval activations,
 *        cancel, and the timer tick that a 1 kHz timer proc runs. The operating rules, the
 *        types and the immediate activations are in mt/wq.h.
 */
#ifndef MT_WQ_TIMER_H
#define MT_WQ_TIMER_H

#include <stdint.h>

#include "mt/wq.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What the I-class and task forms of the timer calls state alike: the item's deadline is
 * delay_us after the clock reading the call took (MtWorkDeadline); an interval timer runs
 * every period_us (MtWorkEvery). */
/*@ predicate MtWorkDeadline(mt_work_t *w, integer delay_us) =
        w->wq->slot[w->slot].deadline_us == MtWqAfter(MtPortNow, delay_us);

    predicate MtWorkEvery(mt_work_t *w, integer period_us) =
        MtWorkTimer(w, MT_WQ_TIMER_EVERY) && w->wq->slot[w->slot].period_us == period_us;
*/

/** Activate the item once, delay_us from now (0: at the next timer tick),
 *  replacing any timer it had. I-class. */
/*@ requires held: MtLocked == 1;
    requires item: MtWorkAttached(w);
    assigns w->wq->slot[w->slot].timer, w->wq->slot[w->slot].deadline_us, MtPortNow;
    ensures item: MtWorkAttached(w);
    ensures armed: MtWorkTimer(w, MT_WQ_TIMER_ONCE);
    ensures deadline: MtWorkDeadline(w, delay_us);
    ensures time: MtPortNow >= \old(MtPortNow);
*/
void mt_work_schedule_delayed_i(mt_work_t *w, uint32_t delay_us);

/** mt_work_schedule_delayed_i() from task context. */
/*@ requires not_held: MtLocked == 0;
    requires item: MtWorkAttached(w);
    assigns w->wq->slot[w->slot].timer, w->wq->slot[w->slot].deadline_us, MtPortNow, MtLocked;
    ensures released: MtLocked == 0;
    ensures item: MtWorkAttached(w);
    ensures armed: MtWorkTimer(w, MT_WQ_TIMER_ONCE);
    ensures deadline: MtWorkDeadline(w, delay_us);
    ensures time: MtPortNow >= \old(MtPortNow);
*/
void mt_work_schedule_delayed(mt_work_t *w, uint32_t delay_us);

/** Activate the item every period_us, the first time delay_us from now, on
 *  absolute deadlines; replaces any timer it had. I-class.
 *  @retval MT_OK armed.
 *  @retval MT_E_INVALID period_us is 0 (nothing changed). */
/*@ requires held: MtLocked == 1;
    requires item: MtWorkAttached(w);
    assigns w->wq->slot[w->slot].timer, w->wq->slot[w->slot].deadline_us,
            w->wq->slot[w->slot].period_us, MtPortNow;
    ensures item: MtWorkAttached(w);
    behavior invalid:
      assumes period_us == 0;
      ensures status: \result == MT_E_INVALID;
      ensures unchanged: MtWorkTimerKept{Pre, Post}(w);
    behavior ok:
      assumes period_us >= 1;
      ensures status: \result == MT_OK;
      ensures armed: MtWorkEvery(w, period_us);
      ensures deadline: MtWorkDeadline(w, delay_us);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_work_schedule_interval_i(mt_work_t *w, uint32_t period_us, uint32_t delay_us);

/** mt_work_schedule_interval_i() from task context. */
/*@ requires not_held: MtLocked == 0;
    requires item: MtWorkAttached(w);
    assigns w->wq->slot[w->slot].timer, w->wq->slot[w->slot].deadline_us,
            w->wq->slot[w->slot].period_us, MtPortNow, MtLocked;
    ensures released: MtLocked == 0;
    ensures item: MtWorkAttached(w);
    behavior invalid:
      assumes period_us == 0;
      ensures status: \result == MT_E_INVALID;
      ensures unchanged: MtWorkTimerKept{Pre, Post}(w);
    behavior ok:
      assumes period_us >= 1;
      ensures status: \result == MT_OK;
      ensures armed: MtWorkEvery(w, period_us);
      ensures deadline: MtWorkDeadline(w, delay_us);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_work_schedule_interval(mt_work_t *w, uint32_t period_us, uint32_t delay_us);

/** Stop the item's timer. An activation already queued still runs. I-class.
 *  @retval MT_OK the timer was armed and is stopped.
 *  @retval MT_E_STATE no timer was armed. */
/*@ requires held: MtLocked == 1;
    requires item: MtWorkAttached(w);
    assigns w->wq->slot[w->slot].timer;
    ensures item: MtWorkAttached(w);
    ensures off: MtWorkTimer(w, MT_WQ_TIMER_OFF);
    behavior stopped:
      assumes w->wq->slot[w->slot].timer != MT_WQ_TIMER_OFF;
      ensures status: \result == MT_OK;
    behavior none:
      assumes w->wq->slot[w->slot].timer == MT_WQ_TIMER_OFF;
      ensures status: \result == MT_E_STATE;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_work_cancel_i(mt_work_t *w);

/** mt_work_cancel_i() from task context. */
/*@ requires not_held: MtLocked == 0;
    requires item: MtWorkAttached(w);
    assigns w->wq->slot[w->slot].timer, MtLocked;
    ensures released: MtLocked == 0;
    ensures item: MtWorkAttached(w);
    ensures off: MtWorkTimer(w, MT_WQ_TIMER_OFF);
    behavior stopped:
      assumes w->wq->slot[w->slot].timer != MT_WQ_TIMER_OFF;
      ensures status: \result == MT_OK;
    behavior none:
      assumes w->wq->slot[w->slot].timer == MT_WQ_TIMER_OFF;
      ensures status: \result == MT_E_STATE;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_work_cancel(mt_work_t *w);

/** The queue's timers at time now: every attached item whose timer is due
 *  (deadline <= now) is activated; a ONCE timer stops, an EVERY timer moves
 *  to the first deadline after now on its grid, counting the periods it
 *  skipped in `missed`. Returns the number of items activated. I-class. */
/*@ requires held: MtLocked == 1;
    requires inv: MtWqInv(q);
    assigns q->order[0 .. MT_CFG_WQ_MAX_ITEMS - 1], q->where[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
            q->count, q->max_depth, q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].queued_us,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].stats.merged,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].stats.missed,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].timer,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].deadline_us,
            q->stats.merged, q->stats.missed, q->wake, MtPortNow, MtPortWakes;
    ensures inv: MtWqInv(q);
    ensures bounded: \result <= q->nitems;
    ensures due_queued: MtWqTickDueQueued{Pre, Post}(q, now);
    ensures queued_kept: MtWqQueuedKept{Pre, Post}(q);
    ensures not_due: MtWqTickNotDue{Pre, Post}(q, now);
    ensures once_stops: MtWqTickOnceStops{Pre, Post}(q, now);
    ensures every_ahead: MtWqEveryAhead(q, now);
*/
uint32_t mt_wq_timer_tick_i(mt_wq_t *q, uint64_t now);

/** Timer proc (an mt_proc_fn_t; the argument is the queue): takes the lock,
 *  reads the time and calls mt_wq_timer_tick_i(). Register it in the 1 kHz
 *  timer proc set, once per queue that has delayed or interval items. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtWqInv((mt_wq_t *)arg);
    assigns ((mt_wq_t *)arg)->order[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
            ((mt_wq_t *)arg)->where[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
            ((mt_wq_t *)arg)->count, ((mt_wq_t *)arg)->max_depth,
            ((mt_wq_t *)arg)->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].queued_us,
            ((mt_wq_t *)arg)->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].stats.merged,
            ((mt_wq_t *)arg)->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].stats.missed,
            ((mt_wq_t *)arg)->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].timer,
            ((mt_wq_t *)arg)->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].deadline_us,
            ((mt_wq_t *)arg)->stats.merged, ((mt_wq_t *)arg)->stats.missed,
            ((mt_wq_t *)arg)->wake, MtPortNow, MtPortWakes, MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtWqInv((mt_wq_t *)arg);
*/
void mt_wq_timer_proc(void *arg);

#ifdef __cplusplus
}
#endif

#endif /* MT_WQ_TIMER_H */
