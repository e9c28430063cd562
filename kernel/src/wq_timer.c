/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file wq_timer.c
 * @brief Work queues, the timers: delayed and interval items, cancel, and the timer tick that
 *        activates the due items (see mt/wq.h; the queue core is in wq.c).
 */
#include "mt/wq_timer.h"

#include "mt_sat.h"
#include "mt_wq_int.h"

/* ---- timers -------------------------------------------------------------------------------- */

/* Arm slot s for one activation at deadline. */
/*@ requires inv: MtWqInv(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    assigns q->slot[s].timer, q->slot[s].deadline_us;
    ensures inv: MtWqInv(q);
    ensures armed: q->slot[s].timer == MT_WQ_TIMER_ONCE && q->slot[s].deadline_us == deadline;
*/
static void timer_arm_once(mt_wq_t *q, uint32_t s, uint64_t deadline)
{
    q->slot[s].deadline_us = deadline;
    q->slot[s].timer = MT_WQ_TIMER_ONCE;
}

/* Arm slot s for activations every period_us from deadline. */
/*@ requires inv: MtWqInv(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    requires period: period_us >= 1;
    assigns q->slot[s].timer, q->slot[s].deadline_us, q->slot[s].period_us;
    ensures inv: MtWqInv(q);
    ensures armed: q->slot[s].timer == MT_WQ_TIMER_EVERY && q->slot[s].deadline_us == deadline &&
                   q->slot[s].period_us == period_us;
*/
static void timer_arm_every(mt_wq_t *q, uint32_t s, uint64_t deadline, uint32_t period_us)
{
    q->slot[s].period_us = period_us;
    q->slot[s].deadline_us = deadline;
    q->slot[s].timer = MT_WQ_TIMER_EVERY;
}

void mt_work_schedule_delayed_i(mt_work_t *w, uint32_t delay_us)
{
    uint64_t now = mt_port_now_us();

    timer_arm_once(w->wq, w->slot, mt_add_sat_u64(now, delay_us));
}

void mt_work_schedule_delayed(mt_work_t *w, uint32_t delay_us)
{
    mt_port_lock();
    mt_work_schedule_delayed_i(w, delay_us);
    mt_port_unlock();
}

mt_status_t mt_work_schedule_interval_i(mt_work_t *w, uint32_t period_us, uint32_t delay_us)
{
    uint64_t now;

    if (period_us == 0u) {
        return MT_E_INVALID;
    }
    now = mt_port_now_us();
    timer_arm_every(w->wq, w->slot, mt_add_sat_u64(now, delay_us), period_us);
    return MT_OK;
}

mt_status_t mt_work_schedule_interval(mt_work_t *w, uint32_t period_us, uint32_t delay_us)
{
    mt_status_t st;

    mt_port_lock();
    st = mt_work_schedule_interval_i(w, period_us, delay_us);
    mt_port_unlock();
    return st;
}

/*@ requires inv: MtWqInv(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    assigns q->slot[s].timer;
    ensures inv: MtWqInv(q);
    ensures off: q->slot[s].timer == MT_WQ_TIMER_OFF;
*/
static void timer_off(mt_wq_t *q, uint32_t s)
{
    q->slot[s].timer = MT_WQ_TIMER_OFF;
}

mt_status_t mt_work_cancel_i(mt_work_t *w)
{
    mt_status_t st = (w->wq->slot[w->slot].timer != MT_WQ_TIMER_OFF) ? MT_OK : MT_E_STATE;

    timer_off(w->wq, w->slot);
    return st;
}

mt_status_t mt_work_cancel(mt_work_t *w)
{
    mt_status_t st;

    mt_port_lock();
    st = mt_work_cancel_i(w);
    mt_port_unlock();
    return st;
}

/* Periods an EVERY timer skipped, added to the item's and the queue's counts. */
/*@ requires inv: MtWqInv(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    assigns q->slot[s].stats.missed, q->stats.missed;
    ensures inv: MtWqInv(q);
    ensures counted: q->slot[s].stats.missed == (\old(q->slot[s].stats.missed) + missed <= 0xFFFFFFFF ?
                                                 \old(q->slot[s].stats.missed) + missed : 0xFFFFFFFF);
*/
static void note_missed(mt_wq_t *q, uint32_t s, uint32_t missed)
{
    q->slot[s].stats.missed = mt_add_sat_u32(q->slot[s].stats.missed, missed);
    q->stats.missed = mt_add_sat_u32(q->stats.missed, missed);
}

/* After a due timer of slot s fired at now: ONCE stops; EVERY moves to its
 * first grid deadline after now (or stops when 64-bit time runs out). */
/*@ requires inv: MtWqInv(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    requires due: q->slot[s].timer != MT_WQ_TIMER_OFF && q->slot[s].deadline_us <= now;
    assigns q->slot[s].timer, q->slot[s].deadline_us, q->slot[s].stats.missed, q->stats.missed;
    ensures inv: MtWqInv(q);
    ensures once_stops: \old(q->slot[s].timer) == MT_WQ_TIMER_ONCE ==> q->slot[s].timer == MT_WQ_TIMER_OFF;
    ensures every_ahead: q->slot[s].timer == MT_WQ_TIMER_EVERY ==> q->slot[s].deadline_us > now;
*/
static void timer_next(mt_wq_t *q, uint32_t s, uint64_t now)
{
    mt_wq_slot_t *e = &q->slot[s];
    uint64_t p = e->period_us;

    if ((e->timer == MT_WQ_TIMER_EVERY) && (now <= (UINT64_MAX - (2u * p))) &&
        (e->deadline_us <= (UINT64_MAX - p))) {
        uint32_t missed = mt_proc_period_next(&e->deadline_us, now, e->period_us);
        note_missed(q, s, missed);
    } else {
        /* a delayed item fired; or 64-bit time is running out (after 584,000 years) */
        timer_off(q, s);
    }
}

/*@ requires inv: MtWqInv(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    assigns \nothing;
    ensures due: \result == 1 <==> (q->slot[s].timer != MT_WQ_TIMER_OFF && q->slot[s].deadline_us <= now);
    ensures bool: \result == 0 || \result == 1;
*/
static uint32_t timer_due(const mt_wq_t *q, uint32_t s, uint64_t now)
{
    return ((q->slot[s].timer != MT_WQ_TIMER_OFF) && (q->slot[s].deadline_us <= now)) ? 1u : 0u;
}

/* The timer of slot s at time now: activate the item and move the timer on when it is due.
 * Returns 1 when it was due. */
/*@ requires held: MtLocked == 1;
    requires inv: MtWqInv(q);
    requires slot: s < q->nitems;
    assigns q->order[0 .. MT_CFG_WQ_MAX_ITEMS - 1], q->where[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
            q->count, q->max_depth, q->slot[s].queued_us, q->slot[s].stats.merged,
            q->slot[s].stats.missed, q->slot[s].timer, q->slot[s].deadline_us,
            q->stats.merged, q->stats.missed, q->wake, MtPortWakes;
    ensures inv: MtWqInv(q);
    ensures queued_kept: \forall integer t; 0 <= t < MT_CFG_WQ_MAX_ITEMS ==>
        \old(MtWqQueued(q, t)) ==> MtWqQueued(q, t);
    ensures every_ahead: q->slot[s].timer == MT_WQ_TIMER_EVERY ==> q->slot[s].deadline_us > now;
    behavior due:
      assumes q->slot[s].timer != MT_WQ_TIMER_OFF && q->slot[s].deadline_us <= now;
      ensures fired: \result == 1;
      ensures queued: MtWqQueued(q, s);
      ensures once_stops: \old(q->slot[s].timer) == MT_WQ_TIMER_ONCE ==> q->slot[s].timer == MT_WQ_TIMER_OFF;
    behavior not_due:
      assumes q->slot[s].timer == MT_WQ_TIMER_OFF || q->slot[s].deadline_us > now;
      ensures idle: \result == 0;
      ensures unchanged: q->slot[s].timer == \old(q->slot[s].timer) &&
                         q->slot[s].deadline_us == \old(q->slot[s].deadline_us);
    complete behaviors;
    disjoint behaviors;
*/
static uint32_t tick_slot(mt_wq_t *q, uint32_t s, uint64_t now)
{
    if (timer_due(q, s, now) == 0u) {
        return 0u;
    }
    (void)mt_wq_schedule_slot_i(q, s, now);
    timer_next(q, s, now);
    return 1u;
}

uint32_t mt_wq_timer_tick_i(mt_wq_t *q, uint64_t now)
{
    uint32_t s;
    uint32_t fired = 0u;

    /*@ loop invariant index: 0 <= s <= q->nitems && fired <= s;
        loop invariant inv: MtWqInv(q) && q->nitems == \at(q->nitems, LoopEntry);
        loop invariant due_queued: \forall integer j; 0 <= j < s ==>
            \at(q->slot[j].timer, LoopEntry) != MT_WQ_TIMER_OFF ==>
            \at(q->slot[j].deadline_us, LoopEntry) <= now ==> MtWqQueued(q, j);
        loop invariant queued_kept: \forall integer j; 0 <= j < MT_CFG_WQ_MAX_ITEMS ==>
            \at(MtWqQueued(q, j), LoopEntry) ==> MtWqQueued(q, j);
        loop invariant ahead: \forall integer j; s <= j < MT_CFG_WQ_MAX_ITEMS ==>
            q->slot[j].timer == \at(q->slot[j].timer, LoopEntry) &&
            q->slot[j].deadline_us == \at(q->slot[j].deadline_us, LoopEntry);
        loop invariant not_due: \forall integer j; 0 <= j < s ==>
            (\at(q->slot[j].timer, LoopEntry) == MT_WQ_TIMER_OFF ||
             \at(q->slot[j].deadline_us, LoopEntry) > now) ==>
            q->slot[j].timer == \at(q->slot[j].timer, LoopEntry) &&
            q->slot[j].deadline_us == \at(q->slot[j].deadline_us, LoopEntry);
        loop invariant once_stops: \forall integer j; 0 <= j < s ==>
            \at(q->slot[j].timer, LoopEntry) == MT_WQ_TIMER_ONCE ==>
            \at(q->slot[j].deadline_us, LoopEntry) <= now ==> q->slot[j].timer == MT_WQ_TIMER_OFF;
        loop invariant every_ahead: \forall integer j; 0 <= j < s ==>
            q->slot[j].timer == MT_WQ_TIMER_EVERY ==> q->slot[j].deadline_us > now;
        loop assigns s, fired, q->order[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
            q->where[0 .. MT_CFG_WQ_MAX_ITEMS - 1], q->count, q->max_depth,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].queued_us,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].stats.merged,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].stats.missed,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].timer,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].deadline_us, q->stats.merged, q->stats.missed,
            q->wake, MtPortWakes;
        loop variant q->nitems - s;
    */
    for (s = 0u; s < q->nitems; s++) {
        fired += tick_slot(q, s, now);
    }
    return fired;
}

void mt_wq_timer_proc(void *arg)
{
    mt_wq_t *q = (mt_wq_t *)arg;

    mt_port_lock();
    (void)mt_wq_timer_tick_i(q, mt_port_now_us());
    mt_port_unlock();
}
