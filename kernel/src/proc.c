/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file proc.c
 * @brief Timer and IO proc sets (see mt/proc.h).
 */
#include "mt/proc.h"
#include "mt_arith.h"

#include "mt_atomic.h"
#include "mt_invoke.h"
#include "mt_spec_arith.h"
#include "mt_spec_div.h"

void mt_proc_set_init(mt_proc_set_t *p)
{
    uint32_t i;

    /*@ loop invariant 0 <= i <= MT_CFG_PROC_MAX;
        loop assigns i, p->procs[0 .. MT_CFG_PROC_MAX - 1];
        loop variant MT_CFG_PROC_MAX - i;
    */
    for (i = 0u; i < MT_CFG_PROC_MAX; i++) {
        p->procs[i].fn = (mt_proc_fn_t)0;
        p->procs[i].arg = (void *)0;
        p->procs[i].calls = 0u;
        p->procs[i].max_us = 0u;
        p->procs[i].total_us = 0u;
    }
    p->count = 0u;
    p->running = 0u;
    p->refused = 0u;
    p->periods_missed = 0u;
    p->dispatches = 0u;
    p->max_round_us = 0u;
}

/*@ requires MtProcSetInv(p);
    assigns \nothing;
    ensures \result == 1 <==> MtProcRegistered(p, fn, arg);
    ensures \result == 0 || \result == 1;
*/
static int is_registered(const mt_proc_set_t *p, mt_proc_fn_t fn, const void *arg)
{
    uint32_t i;

    /*@ loop invariant 0 <= i <= p->count;
        loop invariant \forall integer j; 0 <= j < i ==> !(p->procs[j].fn == fn && p->procs[j].arg == arg);
        loop assigns i;
        loop variant p->count - i;
    */
    for (i = 0u; i < p->count; i++) {
        if ((p->procs[i].fn == fn) && (p->procs[i].arg == arg)) {
            return 1;
        }
    }
    return 0;
}

mt_status_t mt_proc_register_i(mt_proc_set_t *p, mt_proc_fn_t fn, void *arg)
{
    uint32_t n = p->count;

    if (fn == (mt_proc_fn_t)0) {
        return MT_E_INVALID;
    }
    if (is_registered(p, fn, arg) != 0) {
        return MT_E_DUPLICATE;
    }
    if (n >= MT_CFG_PROC_MAX) {
        return MT_E_FULL;
    }
    p->procs[n].fn = fn;
    p->procs[n].arg = arg;
    p->procs[n].calls = 0u;
    p->procs[n].max_us = 0u;
    p->procs[n].total_us = 0u;
    /* Entry before count: the dispatcher's acquire load of count sees it whole. */
    mt_store_release_u32(&p->count, n + 1u);
    return MT_OK;
}

mt_status_t mt_proc_register(mt_proc_set_t *p, mt_proc_fn_t fn, void *arg)
{
    mt_status_t st;

    mt_port_lock();
    st = mt_proc_register_i(p, fn, arg);
    mt_port_unlock();
    return st;
}

/* Call and count entry i, timed from t0 (the end of the previous call, or the start of the
 * round) to the clock reading after it, which it returns: one reading per proc. */
/*@ requires MtProcSetInv(p);
    requires 0 <= i < p->count;
    requires t0 <= MtPortNow;
    assigns p->procs[i].calls, p->procs[i].max_us, p->procs[i].total_us, MtPortNow, MtPortWakes,
            MtCalls[MT_CALL_PROC(i)];
    ensures MtProcSetInv(p);
    ensures MtPortNow >= \old(MtPortNow);
    ensures read: \result == MtPortNow;
    ensures called: MtCalls[MT_CALL_PROC(i)] == MtCount64(\old(MtCalls[MT_CALL_PROC(i)]), 1);
    ensures p->procs[i].calls == (\old(p->procs[i].calls) < 0xFFFFFFFF ? \old(p->procs[i].calls) + 1 : \old(p->procs[i].calls));
*/
static uint64_t call_one(mt_proc_set_t *p, uint32_t i, uint64_t t0)
{
    mt_proc_t *e = &p->procs[i];
    uint64_t t1;
    uint64_t dt;

    mt_invoke(e->fn, e->arg, MT_CALL_PROC(i));
    t1 = mt_port_now_us();
    dt = t1 - t0;
    if (e->calls < 0xFFFFFFFFu) {
        e->calls++;
    }
    if (dt > (uint64_t)e->max_us) {
        e->max_us = (dt > 0xFFFFFFFFu) ? 0xFFFFFFFFu : (uint32_t)dt;
    }
    e->total_us = (e->total_us <= (UINT64_MAX - dt)) ? (e->total_us + dt) : UINT64_MAX;
    return t1;
}

mt_status_t mt_proc_dispatch(mt_proc_set_t *p)
{
    uint32_t n;
    uint32_t i;
    uint64_t t0;
    uint64_t t;
    uint64_t dt;

    if (p->running != 0u) {
        if (p->refused < 0xFFFFFFFFu) {
            p->refused++;
        }
        return MT_E_BUSY;
    }
    p->running = 1u;
    n = mt_load_acquire_u32(&p->count);
    t0 = mt_port_now_us();
    t = t0;
    /*@ loop invariant 0 <= i <= n;
        loop invariant MtProcSetInv(p) && p->running == 1 && p->count == n;
        loop invariant time: t0 <= t <= MtPortNow;
        loop invariant \forall integer j; 0 <= j < i ==>
            p->procs[j].calls == (\at(p->procs[j].calls, LoopEntry) < 0xFFFFFFFF ? \at(p->procs[j].calls, LoopEntry) + 1 : \at(p->procs[j].calls, LoopEntry));
        loop invariant \forall integer j; i <= j < MT_CFG_PROC_MAX ==>
            p->procs[j].calls == \at(p->procs[j].calls, LoopEntry);
        loop invariant called: \forall integer j; 0 <= j < i ==>
            MtCalls[MT_CALL_PROC(j)] == MtCount64(\at(MtCalls[MT_CALL_PROC(j)], LoopEntry), 1);
        loop invariant uncalled: \forall integer j; i <= j < MT_CFG_PROC_MAX ==>
            MtCalls[MT_CALL_PROC(j)] == \at(MtCalls[MT_CALL_PROC(j)], LoopEntry);
        loop assigns i, t, p->procs[0 .. MT_CFG_PROC_MAX - 1].calls, p->procs[0 .. MT_CFG_PROC_MAX - 1].max_us,
                     p->procs[0 .. MT_CFG_PROC_MAX - 1].total_us, MtPortNow, MtPortWakes,
                     MtCalls[MT_CALL_PROC(0) .. MT_CALL_PROC(MT_CFG_PROC_MAX - 1)];
        loop variant n - i;
    */
    for (i = 0u; i < n; i++) {
        t = call_one(p, i, t);
    }
    /* the round: from the first reading to the last (the end of the last proc) */
    dt = t - t0;
    if (dt > (uint64_t)p->max_round_us) {
        p->max_round_us = (dt > 0xFFFFFFFFu) ? 0xFFFFFFFFu : (uint32_t)dt;
    }
    if (p->dispatches < UINT64_MAX) {
        p->dispatches++;
    }
    p->running = 0u;
    return MT_OK;
}

uint32_t mt_proc_period_next(uint64_t *deadline, uint64_t now, uint32_t period_us)
{
    uint64_t next = *deadline + period_us;
    uint64_t late;
    uint64_t missed;

    if (next > now) {
        *deadline = next;
        return 0u;
    }
    /* late periods: the next boundary after now is now + (period - late % period), which
     * equals old + (missed + 1) * period (lemma MtModStep: it is on the grid) and needs no
     * product that could overflow */
    late = now - *deadline;
    missed = mt_udiv_u64(late, period_us);
    *deadline = now + (period_us - mt_umod_u64(late, period_us));
    return (missed > 0xFFFFFFFFu) ? 0xFFFFFFFFu : (uint32_t)missed;
}

void mt_proc_note_missed(mt_proc_set_t *p, uint32_t missed)
{
    uint64_t sum = (uint64_t)p->periods_missed + missed;
    p->periods_missed = (sum > 0xFFFFFFFFu) ? 0xFFFFFFFFu : (uint32_t)sum;
}
