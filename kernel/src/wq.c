/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file wq.c
 * @brief Work queues, the queue core: the FIFO, the slot records, init, attach and
 *        scheduling (see mt/wq.h for the operating rules; the timers are in wq_timer.c, the
 *        runner and the single shot in wq_run.c, the reports in wq_report.c).
 *
 * Every store group goes through a small helper whose contract carries the invariant across
 * it, so no frame goal sees more than a few stores. The helpers the other files of the module
 * call are declared, with their contracts, in mt_wq_int.h.
 */
#include "mt/wq.h"

#include <stddef.h>

#include "mt_sat.h"
#include "mt_wq_int.h"

#define WQ_CAP MT_CFG_WQ_MAX_ITEMS

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

/* 1 when slot s is queued (contract: mt_wq_int.h). */
uint32_t mt_wq_is_queued(const mt_wq_t *q, uint32_t s)
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
                  e->stats.missed == 0 && e->stats.total_run_us == 0 && e->stats.first_start_us == 0 &&
                  e->stats.last_start_us == 0 && e->stats.max_run_us == 0 &&
                  e->stats.min_interval_us == 0 && e->stats.max_interval_us == 0 &&
                  e->stats.max_latency_us == 0;
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

/* Wake the queue's thread (lock held; contract: mt_wq_int.h). */
void mt_wq_wake_i(mt_wq_t *q)
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
    q->slot[s].stats.merged = mt_inc_sat_u32(q->slot[s].stats.merged);
    q->stats.merged = mt_inc_sat_u32(q->stats.merged);
}

/* Slot s was queued at now. */
/*@ requires inv: MtWqInv(q);
    requires slot: s < MT_CFG_WQ_MAX_ITEMS;
    assigns q->slot[s].queued_us, q->max_depth;
    ensures inv: MtWqInv(q);
    ensures stamped: q->slot[s].queued_us == now;
    ensures depth: MtWqDepth{Pre, Post}(q);
*/
static void note_queued(mt_wq_t *q, uint32_t s, uint64_t now)
{
    q->slot[s].queued_us = now;
    if (q->count > q->max_depth) {
        q->max_depth = q->count;
    }
}

/* Activate slot s at time now (the core of every scheduling path; contract: mt_wq_int.h). */
mt_status_t mt_wq_schedule_slot_i(mt_wq_t *q, uint32_t s, uint64_t now)
{
    if (mt_wq_is_queued(q, s) != 0u) {
        note_merge(q, s);
        //@ assert inv: MtWqInv(q);
        //@ assert kept: MtWqFifoKept{Pre, Here}(q);
        //@ assert idle: MtWqIdleKept{Pre, Here}(q, s);
        return MT_W_WQ_MERGED;
    }
    fifo_push(q, s);
    note_queued(q, s, now);
    mt_wq_wake_i(q);
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
    ensures fresh: MtWqStatsFresh(&q->slot[\old(q->nitems)].stats) && MtSemInv(&q->slot[\old(q->nitems)].done) &&
                   q->slot[\old(q->nitems)].done.token == 0 && q->slot[\old(q->nitems)].done.waiter == \null;
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
    return mt_wq_schedule_slot_i(w->wq, w->slot, mt_port_now_us());
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
