/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file wq_run.c
 * @brief Work queues, the runner's side: the oldest item out of the FIFO, the run statistics,
 *        one run, the queue's thread, the stop request and the single shot (see mt/wq.h; the
 *        queue core is in wq.c).
 */
#include "mt/wq.h"

#include "mt_invoke.h"
#include "mt_sat.h"
#include "mt_wq_int.h"

#define WQ_CAP MT_CFG_WQ_MAX_ITEMS

/* ---- the runner's end of the FIFO ---------------------------------------------------------- */

/* Remove the oldest queued slot and return it. */
/*@ requires inv: \valid(q) && MtWqFifo(q);
    requires nonempty: q->count > 0;
    assigns q->head, q->count;
    ensures inv: MtWqFifo(q);
    ensures oldest: \result == \old(q->order[q->head]) && \result < q->nitems;
    ensures popped: !MtWqQueued(q, \result) && q->count == \old(q->count) - 1;
    ensures kept: \forall integer t; 0 <= t < MT_CFG_WQ_MAX_ITEMS ==> t != \result ==>
        (MtWqQueued(q, t) <==> \old(MtWqQueued(q, t)));
    ensures moved_up: \forall integer t; 0 <= t < MT_CFG_WQ_MAX_ITEMS ==> t != \result ==>
        \old(MtWqQueued(q, t)) ==> MtWqRel(q, q->where[t]) == \old(MtWqRel(q, q->where[t])) - 1;
*/
static uint32_t fifo_pop(mt_wq_t *q)
{
    uint32_t s = q->order[q->head];

    q->head = (q->head == (WQ_CAP - 1u)) ? 0u : (q->head + 1u);
    q->count--;
    return s;
}

/* ---- run statistics ------------------------------------------------------------------------ */

/* A start at t0, latency lat after the first pending activation. */
/*@ requires valid: \valid(st);
    assigns st->starts, st->first_start_us, st->last_start_us, st->min_interval_us,
            st->max_interval_us, st->max_latency_us;
    ensures started: st->starts == (\old(st->starts) < 0xFFFFFFFFFFFFFFFF ? \old(st->starts) + 1
                                                                           : 0xFFFFFFFFFFFFFFFF);
    ensures last: st->last_start_us == t0;
    ensures first: \old(st->starts) == 0 ==> st->first_start_us == t0;
*/
static void note_start(mt_wq_stats_t *st, uint64_t t0, uint64_t lat)
{
    uint32_t l = mt_clamp_u32(lat);

    if (st->starts == 0u) {
        st->first_start_us = t0;
    } else {
        uint32_t iv = mt_clamp_u32(mt_sub_sat_u64(t0, st->last_start_us));
        if ((st->starts == 1u) || (iv < st->min_interval_us)) {
            st->min_interval_us = iv;
        }
        if (iv > st->max_interval_us) {
            st->max_interval_us = iv;
        }
    }
    if (l > st->max_latency_us) {
        st->max_latency_us = l;
    }
    st->last_start_us = t0;
    st->starts = (st->starts < UINT64_MAX) ? (st->starts + 1u) : UINT64_MAX;
}

/* A run that took dt. */
/*@ requires valid: \valid(st);
    assigns st->runs, st->total_run_us, st->max_run_us;
    ensures ran: st->runs == (\old(st->runs) < 0xFFFFFFFFFFFFFFFF ? \old(st->runs) + 1
                                                                  : 0xFFFFFFFFFFFFFFFF);
*/
static void note_finish(mt_wq_stats_t *st, uint64_t dt)
{
    uint32_t d = mt_clamp_u32(dt);

    if (d > st->max_run_us) {
        st->max_run_us = d;
    }
    st->total_run_us = mt_add_sat_u64(st->total_run_us, dt);
    st->runs = (st->runs < UINT64_MAX) ? (st->runs + 1u) : UINT64_MAX;
}

/* The start of a run of slot s at t0, in the item's and the queue's statistics. */
/*@ requires inv: MtWqInv(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    assigns q->slot[s].stats.starts, q->slot[s].stats.first_start_us, q->slot[s].stats.last_start_us,
            q->slot[s].stats.min_interval_us, q->slot[s].stats.max_interval_us,
            q->slot[s].stats.max_latency_us, q->stats.starts, q->stats.first_start_us,
            q->stats.last_start_us, q->stats.min_interval_us, q->stats.max_interval_us,
            q->stats.max_latency_us;
    ensures inv: MtWqInv(q);
    ensures started: q->slot[s].stats.starts == (\old(q->slot[s].stats.starts) < 0xFFFFFFFFFFFFFFFF ?
                                                 \old(q->slot[s].stats.starts) + 1 : 0xFFFFFFFFFFFFFFFF);
    ensures runs_kept: q->stats.runs == \old(q->stats.runs) &&
        \forall integer t; 0 <= t < MT_CFG_WQ_MAX_ITEMS ==>
            q->slot[t].stats.runs == \old(q->slot[t].stats.runs) && q->slot[t].fn == \old(q->slot[t].fn) &&
            q->slot[t].arg == \old(q->slot[t].arg);
*/
static void note_start_slot(mt_wq_t *q, uint32_t s, uint64_t t0, uint64_t lat)
{
    note_start(&q->slot[s].stats, t0, lat);
    note_start(&q->stats, t0, lat);
}

/* A run of slot s that took dt, in the item's and the queue's statistics. */
/*@ requires inv: MtWqInv(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    assigns q->slot[s].stats.runs, q->slot[s].stats.total_run_us, q->slot[s].stats.max_run_us,
            q->stats.runs, q->stats.total_run_us, q->stats.max_run_us;
    ensures inv: MtWqInv(q);
    ensures ran: q->slot[s].stats.runs == (\old(q->slot[s].stats.runs) < 0xFFFFFFFFFFFFFFFF ?
                                           \old(q->slot[s].stats.runs) + 1 : 0xFFFFFFFFFFFFFFFF);
    ensures ran_wq: q->stats.runs == (\old(q->stats.runs) < 0xFFFFFFFFFFFFFFFF ?
                                      \old(q->stats.runs) + 1 : 0xFFFFFFFFFFFFFFFF);
    ensures kept: \forall integer t; 0 <= t < MT_CFG_WQ_MAX_ITEMS ==>
        q->slot[t].stats.starts == \old(q->slot[t].stats.starts) && q->slot[t].fn == \old(q->slot[t].fn) &&
        q->slot[t].arg == \old(q->slot[t].arg);
*/
static void note_finish_slot(mt_wq_t *q, uint32_t s, uint64_t dt)
{
    note_finish(&q->slot[s].stats, dt);
    note_finish(&q->stats, dt);
}

/* ---- running ------------------------------------------------------------------------------- */

/*@ requires inv: MtWqInv(q);
    assigns q->refused;
    ensures inv: MtWqInv(q);
    ensures counted: q->refused == (\old(q->refused) < 0xFFFFFFFF ? \old(q->refused) + 1 : 0xFFFFFFFF);
*/
static void note_refused(mt_wq_t *q)
{
    q->refused = mt_inc_sat_u32(q->refused);
}

/*@ requires inv: MtWqInv(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    requires state: v <= MT_WQ_SHOT_DONE;
    assigns q->slot[s].shot;
    ensures inv: MtWqInv(q);
    ensures set: q->slot[s].shot == v;
*/
static void set_shot(mt_wq_t *q, uint32_t s, uint32_t v)
{
    q->slot[s].shot = v;
}

/*@ requires inv: MtWqInv(q);
    requires slot: s == MT_WQ_NONE || s < q->nitems;
    assigns q->running, q->run_start_us;
    ensures inv: MtWqInv(q);
    ensures set: q->running == s && q->run_start_us == t0;
*/
static void set_running(mt_wq_t *q, uint32_t s, uint64_t t0)
{
    q->running = s;
    q->run_start_us = t0;
}

/* Start the oldest queued item (lock held, no run in progress): pop it, stamp
 * its start, mark it running. Returns the slot. */
/*@ requires held: MtLocked == 1;
    requires inv: MtWqInv(q);
    requires idle: q->running == MT_WQ_NONE;
    requires nonempty: q->count > 0;
    assigns q->head, q->count, q->running, q->run_start_us,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].stats.starts,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].stats.first_start_us,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].stats.last_start_us,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].stats.min_interval_us,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].stats.max_interval_us,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].stats.max_latency_us,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].shot,
            q->stats.starts, q->stats.first_start_us, q->stats.last_start_us,
            q->stats.min_interval_us, q->stats.max_interval_us, q->stats.max_latency_us, MtPortNow;
    ensures inv: MtWqInv(q);
    ensures slot: \result == \old(q->order[q->head]) && \result < q->nitems;
    ensures running: q->running == \result;
    ensures started: q->slot[\result].stats.starts ==
        (\old(q->slot[q->order[q->head]].stats.starts) < 0xFFFFFFFFFFFFFFFF ?
         \old(q->slot[q->order[q->head]].stats.starts) + 1 : 0xFFFFFFFFFFFFFFFF);
    ensures runs_kept: q->stats.runs == \old(q->stats.runs) && q->nitems == \old(q->nitems) &&
        \forall integer t; 0 <= t < MT_CFG_WQ_MAX_ITEMS ==>
            q->slot[t].stats.runs == \old(q->slot[t].stats.runs) && q->slot[t].fn == \old(q->slot[t].fn) &&
            q->slot[t].arg == \old(q->slot[t].arg);
    ensures time: MtPortNow >= \old(MtPortNow);
*/
static uint32_t start_i(mt_wq_t *q)
{
    uint32_t s = fifo_pop(q);
    uint64_t t0 = mt_port_now_us();
    uint64_t lat = mt_sub_sat_u64(t0, q->slot[s].queued_us);

    note_start_slot(q, s, t0, lat);
    if (q->slot[s].shot == MT_WQ_SHOT_ARMED) {
        set_shot(q, s, MT_WQ_SHOT_RUN);
    }
    set_running(q, s, t0);
    return s;
}

/* Re-take the lock after a run. While it was released, other contexts may have
 * attached items, scheduled (FIFO, merges, activation times), armed or stopped
 * timers, waited for single shots, asked for a stop and been refused a run; the
 * runner's own fields (head, running, run statistics, run_start_us) and the
 * attached items' functions are theirs to keep. The contract says exactly that;
 * the body only takes the lock. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtWqInv(q);
    requires running: q->running != MT_WQ_NONE;
    assigns MtLocked, q->order[0 .. MT_CFG_WQ_MAX_ITEMS - 1], q->where[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
            q->count, q->nitems, q->slot[q->nitems .. MT_CFG_WQ_MAX_ITEMS - 1],
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].queued_us,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].deadline_us,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].period_us,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].timer,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].shot,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].done,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].stats.merged,
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1].stats.missed,
            q->stats.merged, q->stats.missed, q->max_depth, q->refused, q->stop, q->wake;
    ensures held: MtLocked == 1;
    ensures inv: MtWqInv(q);
    ensures grown: q->nitems >= \old(q->nitems);
    ensures runner_kept: q->running == \old(q->running) && q->run_start_us == \old(q->run_start_us) &&
        q->stats.runs == \old(q->stats.runs);
    ensures items_kept: \forall integer t; 0 <= t < \old(q->nitems) ==>
        q->slot[t].fn == \old(q->slot[t].fn) && q->slot[t].arg == \old(q->slot[t].arg);
    ensures stats_kept: \forall integer t; 0 <= t < MT_CFG_WQ_MAX_ITEMS ==>
        q->slot[t].stats.runs == \old(q->slot[t].stats.runs) &&
        q->slot[t].stats.starts == \old(q->slot[t].stats.starts);
*/
static void relock_after_run(mt_wq_t *q)
{
    (void)q;
    mt_port_lock();
}

/* The single-shot run of slot s has ended: DONE, and the waiter released (lock held). */
/*@ requires held: MtLocked == 1;
    requires inv: MtWqInv(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    assigns q->slot[s].shot, q->slot[s].done, MtPortWakes;
    ensures inv: MtWqInv(q);
    ensures done: q->slot[s].shot == MT_WQ_SHOT_DONE;
    ensures released: MtSemSignalled{Pre, Post}(&q->slot[s].done);
*/
static void shot_done_i(mt_wq_t *q, uint32_t s)
{
    q->slot[s].shot = MT_WQ_SHOT_DONE;
    mt_sem_signal_i(&q->slot[s].done);
}

/* End the run in progress (lock held): statistics, single-shot completion, and
 * a wake-up when items are left (a thread refused meanwhile takes them). */
/*@ requires held: MtLocked == 1;
    requires inv: MtWqInv(q);
    requires running: q->running != MT_WQ_NONE;
    assigns q->running, q->run_start_us, q->slot[q->running].stats.runs,
            q->slot[q->running].stats.total_run_us, q->slot[q->running].stats.max_run_us,
            q->slot[q->running].shot, q->slot[q->running].done,
            q->stats.runs, q->stats.total_run_us, q->stats.max_run_us, q->wake, MtPortNow, MtPortWakes;
    ensures inv: MtWqInv(q);
    ensures idle: q->running == MT_WQ_NONE;
    ensures ran: q->slot[\old(q->running)].stats.runs ==
        (\old(q->slot[q->running].stats.runs) < 0xFFFFFFFFFFFFFFFF ?
         \old(q->slot[q->running].stats.runs) + 1 : 0xFFFFFFFFFFFFFFFF);
    ensures ran_wq: q->stats.runs ==
        (\old(q->stats.runs) < 0xFFFFFFFFFFFFFFFF ? \old(q->stats.runs) + 1 : 0xFFFFFFFFFFFFFFFF);
    ensures kept: q->nitems == \old(q->nitems) && \forall integer t; 0 <= t < MT_CFG_WQ_MAX_ITEMS ==>
        q->slot[t].stats.starts == \old(q->slot[t].stats.starts) && q->slot[t].fn == \old(q->slot[t].fn) &&
        q->slot[t].arg == \old(q->slot[t].arg);
    ensures items: MtWqItemsKept{Pre, Post}(q);
*/
static void finish_i(mt_wq_t *q)
{
    uint32_t s = q->running;
    uint64_t dt = mt_sub_sat_u64(mt_port_now_us(), q->run_start_us);

    note_finish_slot(q, s, dt);
    if (q->slot[s].shot == MT_WQ_SHOT_RUN) {
        shot_done_i(q, s);
    }
    set_running(q, MT_WQ_NONE, q->run_start_us);
    if (q->count > 0u) {
        mt_wq_wake_i(q);
    }
}

mt_status_t mt_wq_run_once(mt_wq_t *q)
{
    uint32_t s;
    mt_work_fn_t fn;
    void *arg;

    mt_port_lock();
    if (q->running != MT_WQ_NONE) {
        note_refused(q);
        mt_port_unlock();
        //@ assert items: MtWqItemsKept{Pre, Here}(q);
        return MT_E_BUSY;
    }
    if (q->count == 0u) {
        mt_port_unlock();
        return MT_E_EMPTY;
    }
    s = start_i(q);
    fn = q->slot[s].fn;
    arg = q->slot[s].arg;
    mt_port_unlock();
    //@ assert items: MtWqItemsKept{Pre, Here}(q);
    mt_invoke(fn, arg, MT_CALL_WORK(s));
    //@ assert called: s == \at(q->order[q->head], Pre) && MtWqCalledOnly{Pre, Here}(s);
    relock_after_run(q);
    /*@ ghost Relocked: ; */
    //@ assert items: MtWqItemsKept{Pre, Here}(q);
    finish_i(q);
    mt_port_unlock();
    //@ assert items: MtWqItemsKept{Relocked, Here}(q);
    //@ assert called_kept: MtWqCalledOnly{Pre, Here}(s);
    return MT_OK;
}

uint32_t mt_wq_run_pending(mt_wq_t *q, uint32_t max)
{
    uint32_t n = 0u;

    /*@ loop invariant bound: 0 <= n <= max;
        loop invariant inv: MtWqInv(q) && MtLocked == 0;
        loop invariant items: MtWqItemsKept{Pre, Here}(q);
        loop invariant first: n == 0 ==> q->running == \at(q->running, Pre) &&
            q->refused == \at(q->refused, Pre) && q->stats.runs == \at(q->stats.runs, Pre) &&
            MtWqNoneCalled{Pre, Here};
        loop invariant after: n > 0 ==> q->running == MT_WQ_NONE;
        loop invariant refused: \at(q->running, Pre) != MT_WQ_NONE ==> n == 0;
        loop invariant ran: q->stats.runs == MtWqAdd64(\at(q->stats.runs, Pre), n);
        loop assigns n, *q, MtPortNow, MtPortWakes, MtLocked,
                     MtCalls[MT_CALL_WORK(0) .. MT_CALL_WORK(MT_CFG_WQ_MAX_ITEMS - 1)];
        loop variant max - n;
    */
    while (n < max) {
        if (mt_wq_run_once(q) != MT_OK) {
            break;
        }
        n++;
    }
    return n;
}

/* The stop request, read under the lock. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtWqInv(q);
    assigns MtLocked;
    ensures released: MtLocked == 0;
    ensures value: \result == q->stop;
*/
static uint32_t stop_requested(const mt_wq_t *q)
{
    uint32_t v;

    mt_port_lock();
    v = q->stop;
    mt_port_unlock();
    return v;
}

/* Sleep on `wake` until the next activation (task context).
 * @retval MT_OK woken. @retval MT_E_BUSY another thread already waits on the queue. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtWqInv(q);
    assigns q->wake, MtPortNow, MtPortHandoffs, MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtWqInv(q);
    ensures status: \result == MT_OK || \result == MT_E_BUSY;
*/
static mt_status_t wait_wake(mt_wq_t *q)
{
    mt_status_t st = MT_OK;

    if (mt_sem_wait(&q->wake, MT_WAIT_FOREVER) == MT_E_BUSY) {
        st = MT_E_BUSY;
    }
    return st;
}

mt_status_t mt_wq_serve_once(mt_wq_t *q)
{
    if (stop_requested(q) != 0u) {
        return MT_E_STATE;
    }
    if (mt_wq_run_once(q) == MT_OK) {
        return MT_OK;
    }
    /* nothing to run (or another runner's turn): sleep until the next activation */
    return wait_wake(q);
}

void mt_wq_thread_body(void *arg)
{
    mt_wq_t *q = (mt_wq_t *)arg;

    /* The queue's thread: no loop variant, it serves until a stop is requested. */
    /*@ loop invariant inv: MtWqInv(q) && MtLocked == 0;
        loop assigns *q, MtPortNow, MtPortWakes, MtPortHandoffs, MtLocked,
                     MtCalls[MT_CALL_WORK(0) .. MT_CALL_WORK(MT_CFG_WQ_MAX_ITEMS - 1)];
    */
    while (mt_wq_serve_once(q) == MT_OK) {
    }
}

/*@ requires inv: MtWqInv(q);
    assigns q->stop;
    ensures inv: MtWqInv(q);
    ensures stopping: q->stop == 1;
*/
static void set_stop(mt_wq_t *q)
{
    q->stop = 1u;
}

void mt_wq_request_stop(mt_wq_t *q)
{
    mt_port_lock();
    set_stop(q);
    mt_wq_wake_i(q);
    mt_port_unlock();
}

/* ---- single shot --------------------------------------------------------------------------- */

/* Arm (or disarm) the single-shot state of slot s with no completion pending. */
/*@ requires inv: MtWqInv(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    requires state: v == MT_WQ_SHOT_ARMED || v == MT_WQ_SHOT_NONE;
    assigns q->slot[s].shot, q->slot[s].done.token;
    ensures inv: MtWqInv(q);
    ensures set: q->slot[s].shot == v && q->slot[s].done.token == 0;
*/
static void shot_reset(mt_wq_t *q, uint32_t s, uint32_t v)
{
    q->slot[s].shot = v;
    q->slot[s].done.token = 0u;
}

/* Wait for the completion of slot s (lock held; released while parked). While
 * parked, the runner moves the single-shot state on and any other context may
 * change the queue (as in relock_after_run, and the runner's fields too); the
 * contract allows for that (assumption W2). Returns the single-shot state found on return. */
/*@ requires held: MtLocked == 1;
    requires inv: MtWqInv(q);
    requires slot: s < q->nitems;
    assigns *q, MtPortNow, MtPortWakes, MtPortHandoffs;
    ensures held: MtLocked == 1;
    ensures inv: MtWqInv(q);
    ensures grown: q->nitems >= \old(q->nitems);
    ensures state: \result == q->slot[s].shot;
*/
static uint32_t wait_done_s(mt_wq_t *q, uint32_t s, uint64_t timeout_us)
{
    (void)mt_sem_wait_s(&q->slot[s].done, timeout_us);
    return q->slot[s].shot;
}

mt_status_t mt_work_run_wait(mt_work_t *w, uint64_t timeout_us)
{
    mt_wq_t *q = w->wq;
    uint32_t s = w->slot;
    mt_status_t st;

    mt_port_lock();
    if (q->slot[s].shot != MT_WQ_SHOT_NONE) {
        mt_port_unlock();
        return MT_E_BUSY;
    }
    (void)mt_wq_schedule_slot_i(q, s, mt_port_now_us());
    //@ assert same: w->wq == q && w->slot == s;
    shot_reset(q, s, MT_WQ_SHOT_ARMED);
    //@ assert same: w->wq == q && w->slot == s;
    st = (wait_done_s(q, s, timeout_us) == MT_WQ_SHOT_DONE) ? MT_OK : MT_E_TIMEOUT;
    //@ assert same: w->wq == q && w->slot == s && s < q->nitems;
    /* Either way nothing is left behind: a completion that raced with the
     * timeout counts as done, and its token is dropped with the state. */
    shot_reset(q, s, MT_WQ_SHOT_NONE);
    //@ assert same: w->wq == q && w->slot == s && s < q->nitems;
    //@ assert disarmed: q->slot[s].shot == MT_WQ_SHOT_NONE && q->slot[s].done.token == 0;
    mt_port_unlock();
    return st;
}
