/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file wq.c
 * @brief Work queues (see mt/wq.h for the operating rules).
 *
 * Every store group goes through a small helper whose contract carries the
 * invariant across it, so no frame goal sees more than a few stores.
 */
#include "mt/wq.h"

#include <stddef.h>

#include "mt_invoke.h"

#define WQ_CAP MT_CFG_WQ_MAX_ITEMS
#define U32_MAX_ 0xFFFFFFFFu

/* ---- arithmetic ---------------------------------------------------------------------------- */

/*@ assigns \nothing;
    ensures \result == (v > 0xFFFFFFFF ? 0xFFFFFFFF : v);
*/
// cppcheck-suppress misra-c2012-5.9 ; D-106 module-local helper, one per translation unit
static uint32_t clamp_u32(uint64_t v)
{
    return (v > U32_MAX_) ? U32_MAX_ : (uint32_t)v;
}

/*@ assigns \nothing;
    ensures \result == (a + b <= 0xFFFFFFFFFFFFFFFF ? a + b : 0xFFFFFFFFFFFFFFFF);
*/
// cppcheck-suppress misra-c2012-5.9 ; D-106 module-local helper, one per translation unit
static uint64_t sat_add_u64(uint64_t a, uint64_t b)
{
    // cppcheck-suppress misra-c2012-12.1 ; D-102 fully parenthesised; addon false positive
    return (a <= (UINT64_MAX - b)) ? (a + b) : UINT64_MAX;
}

/* a - b, or 0 when b is later (times from other contexts are not ordered for the proof). */
/*@ assigns \nothing;
    ensures \result == (a >= b ? a - b : 0);
*/
static uint64_t sub_sat_u64(uint64_t a, uint64_t b)
{
    uint64_t d = 0u;

    if (a >= b) {
        d = a - b;
    }
    return d;
}

/*@ assigns \nothing;
    ensures \result == (a < 0xFFFFFFFF ? a + 1 : 0xFFFFFFFF);
*/
static uint32_t inc_sat_u32(uint32_t a)
{
    uint32_t v = U32_MAX_;

    if (a < U32_MAX_) {
        v = a + 1u;
    }
    return v;
}

/*@ assigns \nothing;
    ensures \result == (a + b <= 0xFFFFFFFF ? a + b : 0xFFFFFFFF);
*/
static uint32_t add_sat_u32(uint32_t a, uint32_t b)
{
    uint32_t v = U32_MAX_;

    if (a <= (U32_MAX_ - b)) {
        v = a + b;
    }
    return v;
}

/* ---- FIFO ---------------------------------------------------------------------------------- */

/* Distance of position p from the head (by cases, no wrap). */
/*@ requires valid: \valid_read(q);
    requires head: q->head < MT_CFG_WQ_MAX_ITEMS;
    requires pos: p < MT_CFG_WQ_MAX_ITEMS;
    assigns \nothing;
    ensures rel: \result == MtWqRel(q, p);
    ensures bounded: \result < MT_CFG_WQ_MAX_ITEMS;
*/
static uint32_t rel_pos(const mt_wq_t *q, uint32_t p)
{
    return (p >= q->head) ? (p - q->head) : ((p + WQ_CAP) - q->head);
}

/*@ requires inv: \valid_read(q) && MtWqFifo(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    assigns \nothing;
    ensures bool: \result == 0 || \result == 1;
    ensures queued: \result == 1 <==> MtWqQueued(q, s);
*/
static uint32_t is_queued(const mt_wq_t *q, uint32_t s)
{
    return (rel_pos(q, q->where[s]) < q->count) ? 1u : 0u;
}

/* Append idle slot s at the tail: swap it with the slot at the tail position. */
/*@ requires inv: \valid(q) && MtWqFifo(q);
    requires slot: s < q->nitems && !MtWqQueued(q, s);
    assigns q->order[0 .. MT_CFG_WQ_MAX_ITEMS - 1], q->where[0 .. MT_CFG_WQ_MAX_ITEMS - 1], q->count;
    ensures inv: MtWqFifo(q);
    ensures count: q->count == \old(q->count) + 1;
    ensures tail: MtWqQueued(q, s) && MtWqRel(q, q->where[s]) == \old(q->count);
    ensures kept: MtWqFifoKept{Pre, Post}(q);
    ensures idle: MtWqIdleKept{Pre, Post}(q, s);
*/
static void fifo_push(mt_wq_t *q, uint32_t s)
{
    uint32_t b = q->head + q->count;
    uint32_t a = q->where[s];
    uint32_t t;

    if (b >= WQ_CAP) {
        b -= WQ_CAP;
    }
    //@ assert tail_rel: MtWqRel(q, b) == q->count;
    t = q->order[b];
    q->order[a] = (uint8_t)t;
    q->order[b] = (uint8_t)s;
    q->where[t] = (uint8_t)a;
    q->where[s] = (uint8_t)b;
    q->count++;
}

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

/* ---- slot records -------------------------------------------------------------------------- */

/* Statistics start from zero. */
/*@ requires valid: \valid(st);
    assigns *st;
    ensures zero: st->starts == 0 && st->runs == 0 && st->total_run_us == 0 &&
                  st->first_start_us == 0 && st->last_start_us == 0 && st->max_run_us == 0 &&
                  st->min_interval_us == 0 && st->max_interval_us == 0 && st->max_latency_us == 0 &&
                  st->merged == 0 && st->missed == 0;
*/
static void stats_clear(mt_wq_stats_t *st)
{
    st->starts = 0u;
    st->runs = 0u;
    st->total_run_us = 0u;
    st->first_start_us = 0u;
    st->last_start_us = 0u;
    st->max_run_us = 0u;
    st->min_interval_us = 0u;
    st->max_interval_us = 0u;
    st->max_latency_us = 0u;
    st->merged = 0u;
    st->missed = 0u;
}

/* Slot s holds fn(arg), idle, without timer or waiter. */
/*@ requires valid: \valid(e);
    assigns *e;
    ensures fn: e->fn == fn && e->arg == arg;
    ensures idle: e->timer == MT_WQ_TIMER_OFF && e->shot == MT_WQ_SHOT_NONE && MtSemInv(&e->done) &&
                  e->done.token == 0 && e->done.waiter == \null;
    ensures zero: e->stats.starts == 0 && e->stats.runs == 0 && e->stats.merged == 0 &&
                  e->stats.missed == 0;
*/
static void slot_set(mt_wq_slot_t *e, mt_work_fn_t fn, void *arg)
{
    e->fn = fn;
    e->arg = arg;
    e->queued_us = 0u;
    e->deadline_us = 0u;
    e->period_us = 0u;
    e->timer = MT_WQ_TIMER_OFF;
    e->shot = MT_WQ_SHOT_NONE;
    mt_sem_init(&e->done, false);
    stats_clear(&e->stats);
}

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
    uint32_t l = clamp_u32(lat);

    if (st->starts == 0u) {
        st->first_start_us = t0;
    } else {
        uint32_t iv = clamp_u32(sub_sat_u64(t0, st->last_start_us));
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
    uint32_t d = clamp_u32(dt);

    if (d > st->max_run_us) {
        st->max_run_us = d;
    }
    st->total_run_us = sat_add_u64(st->total_run_us, dt);
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

/* Wake the queue's thread (lock held). */
/*@ requires held: MtLocked == 1;
    requires inv: MtWqInv(q);
    assigns q->wake;
    ensures inv: MtWqInv(q);
*/
static void wake_i(mt_wq_t *q)
{
    mt_sem_signal_i(&q->wake);
}

/* An activation of slot s merged into its pending run. */
/*@ requires inv: MtWqInv(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    assigns q->slot[s].stats.merged, q->stats.merged;
    ensures inv: MtWqInv(q);
    ensures counted: q->slot[s].stats.merged == (\old(q->slot[s].stats.merged) < 0xFFFFFFFF ?
                                                 \old(q->slot[s].stats.merged) + 1 : 0xFFFFFFFF);
    ensures counted_wq: q->stats.merged == (\old(q->stats.merged) < 0xFFFFFFFF ?
                                            \old(q->stats.merged) + 1 : 0xFFFFFFFF);
*/
static void note_merge(mt_wq_t *q, uint32_t s)
{
    q->slot[s].stats.merged = inc_sat_u32(q->slot[s].stats.merged);
    q->stats.merged = inc_sat_u32(q->stats.merged);
}

/* Slot s was queued at now. */
/*@ requires inv: MtWqInv(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    assigns q->slot[s].queued_us, q->max_depth;
    ensures inv: MtWqInv(q);
    ensures stamped: q->slot[s].queued_us == now;
*/
static void note_queued(mt_wq_t *q, uint32_t s, uint64_t now)
{
    q->slot[s].queued_us = now;
    if (q->count > q->max_depth) {
        q->max_depth = q->count;
    }
}

/* Activate slot s at time now (the core of every scheduling path). */
/*@ requires held: MtLocked == 1;
    requires inv: MtWqInv(q);
    requires slot: s < q->nitems;
    assigns q->order[0 .. MT_CFG_WQ_MAX_ITEMS - 1], q->where[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
            q->count, q->max_depth, q->slot[s].queued_us, q->slot[s].stats.merged,
            q->stats.merged, q->wake;
    ensures inv: MtWqInv(q);
    ensures queued: MtWqQueued(q, s);
    ensures fifo_kept: MtWqFifoKept{Pre, Post}(q);
    ensures others_idle: MtWqIdleKept{Pre, Post}(q, s);
    behavior queue:
      assumes !MtWqQueued(q, s);
      ensures status: \result == MT_OK;
      ensures tail: q->count == \old(q->count) + 1 && MtWqRel(q, q->where[s]) == \old(q->count);
      ensures stamped: q->slot[s].queued_us == now;
    behavior merge:
      assumes MtWqQueued(q, s);
      ensures status: \result == MT_W_WQ_MERGED;
      ensures same: q->count == \old(q->count);
      ensures counted: q->slot[s].stats.merged == (\old(q->slot[s].stats.merged) < 0xFFFFFFFF ?
                                                   \old(q->slot[s].stats.merged) + 1 : 0xFFFFFFFF);
      ensures counted_wq: q->stats.merged == (\old(q->stats.merged) < 0xFFFFFFFF ?
                                              \old(q->stats.merged) + 1 : 0xFFFFFFFF);
    complete behaviors;
    disjoint behaviors;
*/
static mt_status_t schedule_slot_i(mt_wq_t *q, uint32_t s, uint64_t now)
{
    if (is_queued(q, s) != 0u) {
        note_merge(q, s);
        //@ assert inv: MtWqInv(q);
        //@ assert kept: MtWqFifoKept{Pre, Here}(q);
        //@ assert idle: MtWqIdleKept{Pre, Here}(q, s);
        return MT_W_WQ_MERGED;
    }
    fifo_push(q, s);
    note_queued(q, s, now);
    wake_i(q);
    //@ assert inv: MtWqInv(q);
    //@ assert kept: MtWqFifoKept{Pre, Here}(q);
    //@ assert idle: MtWqIdleKept{Pre, Here}(q, s);
    return MT_OK;
}

/* ---- init, attach -------------------------------------------------------------------------- */

/* Position i of the identity permutation; slot i without function, timer or waiter (the
 * other fields of a slot are set when an item is attached to it). */
/*@ requires valid: \valid(q);
    requires index: i < MT_CFG_WQ_MAX_ITEMS;
    assigns q->order[i], q->where[i], q->slot[i].fn, q->slot[i].timer, q->slot[i].shot,
            q->slot[i].done.token, q->slot[i].done.waiter, q->slot[i].done.merged;
    ensures identity: q->order[i] == i && q->where[i] == i;
    ensures empty: q->slot[i].timer == MT_WQ_TIMER_OFF && q->slot[i].shot == MT_WQ_SHOT_NONE &&
                   q->slot[i].done.token == 0 && q->slot[i].done.waiter == \null;
*/
static void init_position(mt_wq_t *q, uint32_t i)
{
    q->order[i] = (uint8_t)i;
    q->where[i] = (uint8_t)i;
    q->slot[i].fn = (mt_work_fn_t)0;
    q->slot[i].timer = MT_WQ_TIMER_OFF;
    q->slot[i].shot = MT_WQ_SHOT_NONE;
    q->slot[i].done.token = 0u;
    q->slot[i].done.waiter = (mt_port_tref_t)0;
    q->slot[i].done.merged = 0u;
}

/* Every position and slot as init_position leaves it. */
/*@ requires valid: \valid(q);
    assigns q->order[0 .. MT_CFG_WQ_MAX_ITEMS - 1], q->where[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
            q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1];
    ensures identity: \forall integer j; 0 <= j < MT_CFG_WQ_MAX_ITEMS ==> q->order[j] == j && q->where[j] == j;
    ensures slots: \forall integer j; 0 <= j < MT_CFG_WQ_MAX_ITEMS ==>
        MtSemInv(&q->slot[j].done) && q->slot[j].shot <= MT_WQ_SHOT_DONE &&
        q->slot[j].timer <= MT_WQ_TIMER_EVERY &&
        (q->slot[j].timer == MT_WQ_TIMER_EVERY ==> q->slot[j].period_us >= 1);
*/
static void init_positions(mt_wq_t *q)
{
    uint32_t i;

    /*@ loop invariant 0 <= i <= MT_CFG_WQ_MAX_ITEMS;
        loop invariant \forall integer j; 0 <= j < i ==> q->order[j] == j && q->where[j] == j;
        loop invariant \forall integer j; 0 <= j < i ==>
            q->slot[j].timer == MT_WQ_TIMER_OFF && q->slot[j].shot == MT_WQ_SHOT_NONE;
        loop invariant \forall integer j; 0 <= j < i ==>
            q->slot[j].done.token == 0 && q->slot[j].done.waiter == \null;
        loop assigns i, q->order[0 .. MT_CFG_WQ_MAX_ITEMS - 1], q->where[0 .. MT_CFG_WQ_MAX_ITEMS - 1],
                     q->slot[0 .. MT_CFG_WQ_MAX_ITEMS - 1];
        loop variant MT_CFG_WQ_MAX_ITEMS - i;
    */
    for (i = 0u; i < WQ_CAP; i++) {
        init_position(q, i);
    }
}

void mt_wq_init(mt_wq_t *q, const char *name, mt_prio_base_t base, int8_t offset)
{
    q->name = name;
    q->prio_base = base;
    q->prio_offset = offset;
    q->nitems = 0u;
    q->head = 0u;
    q->count = 0u;
    q->running = MT_WQ_NONE;
    q->stop = 0u;
    q->max_depth = 0u;
    q->refused = 0u;
    q->run_start_us = 0u;
    mt_sem_init(&q->wake, false);
    stats_clear(&q->stats);
    init_positions(q);
    //@ assert fifo: MtWqFifo(q);
    //@ assert slots: MtWqSlots(q);
    //@ assert runner: MtWqRunner(q);
}

void mt_work_init(mt_work_t *w, mt_work_fn_t fn, void *arg)
{
    w->fn = fn;
    w->arg = arg;
    w->wq = NULL;
    w->slot = 0u;
}

/* Slot nitems takes fn(arg) and becomes attached. */
/*@ requires inv: MtWqInv(q);
    requires room: q->nitems < MT_CFG_WQ_MAX_ITEMS;
    requires fn: fn != \null;
    assigns q->slot[q->nitems], q->nitems;
    ensures inv: MtWqInv(q);
    ensures grown: q->nitems == \old(q->nitems) + 1;
    ensures entry: q->slot[\old(q->nitems)].fn == fn && q->slot[\old(q->nitems)].arg == arg;
    ensures idle: !MtWqQueued(q, \old(q->nitems)) && q->slot[\old(q->nitems)].timer == MT_WQ_TIMER_OFF &&
                  q->slot[\old(q->nitems)].shot == MT_WQ_SHOT_NONE;
    ensures fresh: q->slot[\old(q->nitems)].stats.starts == 0 && q->slot[\old(q->nitems)].stats.runs == 0 &&
                   q->slot[\old(q->nitems)].stats.merged == 0 && q->slot[\old(q->nitems)].stats.missed == 0;
*/
static void attach_slot(mt_wq_t *q, mt_work_fn_t fn, void *arg)
{
    uint32_t s = q->nitems;

    //@ assert idle: !MtWqQueued(q, s);
    slot_set(&q->slot[s], fn, arg);
    //@ assert fifo: MtWqFifo(q);
    //@ assert slots: MtWqSlots(q);
    //@ assert runner: MtWqRunner(q);
    q->nitems = s + 1u;
}

mt_status_t mt_wq_attach_i(mt_wq_t *q, mt_work_t *w)
{
    uint32_t s = q->nitems;

    if (w->fn == (mt_work_fn_t)0) {
        return MT_E_INVALID;
    }
    if (w->wq != NULL) {
        return MT_E_DUPLICATE;
    }
    if (s >= WQ_CAP) {
        return MT_E_FULL;
    }
    w->wq = q;
    w->slot = s;
    attach_slot(q, w->fn, w->arg);
    //@ assert inv: MtWqInv(q);
    return MT_OK;
}

mt_status_t mt_wq_attach(mt_wq_t *q, mt_work_t *w)
{
    mt_status_t st;

    mt_port_lock();
    st = mt_wq_attach_i(q, w);
    mt_port_unlock();
    return st;
}

/* ---- scheduling ---------------------------------------------------------------------------- */

mt_status_t mt_work_schedule_i(mt_work_t *w)
{
    return schedule_slot_i(w->wq, w->slot, mt_port_now_us());
}

mt_status_t mt_work_schedule(mt_work_t *w)
{
    mt_status_t st;

    mt_port_lock();
    st = mt_work_schedule_i(w);
    mt_port_unlock();
    return st;
}

mt_status_t mt_work_schedule_isr(mt_work_t *w)
{
    mt_status_t st;

    mt_port_lock_isr();
    st = mt_work_schedule_i(w);
    mt_port_unlock_isr();
    return st;
}

void mt_work_notify_i(void *item)
{
    (void)mt_work_schedule_i((mt_work_t *)item);
}

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

    timer_arm_once(w->wq, w->slot, sat_add_u64(now, delay_us));
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
    timer_arm_every(w->wq, w->slot, sat_add_u64(now, delay_us), period_us);
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
    q->slot[s].stats.missed = add_sat_u32(q->slot[s].stats.missed, missed);
    q->stats.missed = add_sat_u32(q->stats.missed, missed);
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
            q->stats.merged, q->stats.missed, q->wake;
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
    (void)schedule_slot_i(q, s, now);
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
            q->wake;
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

/* ---- running ------------------------------------------------------------------------------- */

/*@ requires inv: MtWqInv(q);
    assigns q->refused;
    ensures inv: MtWqInv(q);
    ensures counted: q->refused == (\old(q->refused) < 0xFFFFFFFF ? \old(q->refused) + 1 : 0xFFFFFFFF);
*/
static void note_refused(mt_wq_t *q)
{
    q->refused = inc_sat_u32(q->refused);
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
    uint64_t lat = sub_sat_u64(t0, q->slot[s].queued_us);

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
    assigns q->slot[s].shot, q->slot[s].done;
    ensures inv: MtWqInv(q);
    ensures done: q->slot[s].shot == MT_WQ_SHOT_DONE;
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
            q->stats.runs, q->stats.total_run_us, q->stats.max_run_us, q->wake, MtPortNow;
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
    uint64_t dt = sub_sat_u64(mt_port_now_us(), q->run_start_us);

    note_finish_slot(q, s, dt);
    if (q->slot[s].shot == MT_WQ_SHOT_RUN) {
        shot_done_i(q, s);
    }
    set_running(q, MT_WQ_NONE, q->run_start_us);
    if (q->count > 0u) {
        wake_i(q);
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
    mt_invoke(fn, arg);
    relock_after_run(q);
    /*@ ghost Relocked: ; */
    //@ assert items: MtWqItemsKept{Pre, Here}(q);
    finish_i(q);
    mt_port_unlock();
    //@ assert items: MtWqItemsKept{Relocked, Here}(q);
    return MT_OK;
}

uint32_t mt_wq_run_pending(mt_wq_t *q, uint32_t max)
{
    uint32_t n = 0u;

    /*@ loop invariant bound: 0 <= n <= max;
        loop invariant inv: MtWqInv(q) && MtLocked == 0;
        loop assigns n, *q, MtPortNow, MtLocked;
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
    assigns q->wake, MtPortNow, MtLocked;
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
        loop assigns *q, MtPortNow, MtLocked;
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
    wake_i(q);
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
    assigns *q, MtPortNow;
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
    (void)schedule_slot_i(q, s, mt_port_now_us());
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

/* ---- reports ------------------------------------------------------------------------------- */

/*@ requires valid: \valid_read(st);
    assigns \nothing;
    ensures guarded: st->runs == 0 ==> \result == 0;
*/
static uint32_t mean_run_us(const mt_wq_stats_t *st)
{
    return (st->runs == 0u) ? 0u : clamp_u32(st->total_run_us / st->runs);
}

/*@ requires valid: \valid_read(st);
    assigns \nothing;
    ensures guarded: st->starts < 2 ==> \result == 0;
*/
static uint32_t mean_interval_us(const mt_wq_stats_t *st)
{
    return (st->starts < 2u)
               ? 0u
               : clamp_u32(sub_sat_u64(st->last_start_us, st->first_start_us) / (st->starts - 1u));
}

/* The statistics and timer part of an item's report. */
/*@ requires valid: \valid_read(e) && \valid(r) && \separated(r, e);
    assigns r->starts, r->runs, r->mean_run_us, r->max_run_us, r->mean_interval_us,
            r->min_interval_us, r->max_interval_us, r->rate_mhz, r->max_latency_us, r->merged,
            r->missed, r->timer, r->period_us;
    ensures runs: r->runs == e->stats.runs && r->starts == e->stats.starts;
    ensures counts: r->merged == e->stats.merged && r->missed == e->stats.missed;
    ensures mean_guarded: e->stats.runs == 0 ==> r->mean_run_us == 0;
    ensures interval_guarded: e->stats.starts < 2 ==> r->mean_interval_us == 0 && r->rate_mhz == 0;
*/
static void fill_work_report(const mt_wq_slot_t *e, mt_work_report_t *r)
{
    uint32_t iv = mean_interval_us(&e->stats);

    r->starts = e->stats.starts;
    r->runs = e->stats.runs;
    r->mean_run_us = mean_run_us(&e->stats);
    r->max_run_us = e->stats.max_run_us;
    r->mean_interval_us = iv;
    r->min_interval_us = e->stats.min_interval_us;
    r->max_interval_us = e->stats.max_interval_us;
    r->rate_mhz = (iv == 0u) ? 0u : (1000000000u / iv);
    r->max_latency_us = e->stats.max_latency_us;
    r->merged = e->stats.merged;
    r->missed = e->stats.missed;
    r->timer = e->timer;
    r->period_us = (e->timer == MT_WQ_TIMER_EVERY) ? e->period_us : 0u;
}

void mt_work_report(const mt_work_t *w, mt_work_report_t *r)
{
    const mt_wq_t *q = w->wq;

    uint32_t queued;
    uint32_t running = 0u;

    mt_port_lock();
    queued = is_queued(q, w->slot);
    if (q->running == w->slot) {
        running = 1u;
    }
    fill_work_report(&q->slot[w->slot], r);
    r->queued = queued;
    r->running = running;
    mt_port_unlock();
}

void mt_wq_report(const mt_wq_t *q, mt_wq_report_t *r)
{
    mt_port_lock();
    r->name = q->name;
    r->starts = q->stats.starts;
    r->runs = q->stats.runs;
    r->mean_run_us = mean_run_us(&q->stats);
    r->max_run_us = q->stats.max_run_us;
    r->mean_interval_us = mean_interval_us(&q->stats);
    r->min_interval_us = q->stats.min_interval_us;
    r->max_interval_us = q->stats.max_interval_us;
    r->max_latency_us = q->stats.max_latency_us;
    r->merged = q->stats.merged;
    r->missed = q->stats.missed;
    r->items = q->nitems;
    r->depth = q->count;
    r->max_depth = q->max_depth;
    r->refused = q->refused;
    mt_port_unlock();
}
