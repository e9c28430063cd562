/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mtc_objects.c
 * @brief Nondeterministic kernel objects (see mtc_objects.h).
 */
#include "mtc_objects.h"

/* Stand-ins for a parked thread and for callback code: distinct objects, so a reference to
 * one is a valid non-NULL pointer that no kernel object aliases. */
static char mtc_thread;
static char mtc_code;

int mtc_cap_ok(uint32_t cap, uint32_t top)
{
#if defined(MTC_BIG)
    return cap >= top - 1u && cap <= top;
#else
    (void)top;
    return cap >= 1u && cap <= MTC_CAP_SMALL;
#endif
}

mt_bring_t *mtc_bring(void)
{
    mt_bring_t *r = MTC_NEW(mt_bring_t, 1u);
    __CPROVER_assume(mtc_cap_ok(r->cap, MTC_CAP_TOP));
    r->buf = (uint8_t *)mtc_alloc(1u, r->cap, MTC_K_BYTES);
    return r;
}

mt_oring_t *mtc_oring(uint32_t elem_max)
{
    mt_oring_t *r = MTC_NEW(mt_oring_t, 1u);
    __CPROVER_assume(r->elem >= 1u && r->elem <= elem_max);
    __CPROVER_assume(mtc_cap_ok(r->cap, MTC_ORING_CAP_TOP(r->elem)));
    r->buf = (uint8_t *)mtc_alloc(1u, ((__CPROVER_size_t)r->cap + 1u) * r->elem, MTC_K_BYTES);
    return r;
}

mt_task_t *mtc_tasks(uint32_t n)
{
    return (mt_task_t *)mtc_alloc(sizeof(mt_task_t), n, MTC_K_mt_task_t);
}

uint32_t mtc_loop_rate(int invalid)
{
    static const uint32_t valid[] = {MT_SCHED_RATE_MIN, 400u, MT_SCHED_RATE_MAX};
    static const uint32_t any[] = {0u, MT_SCHED_RATE_MIN - 1u, MT_SCHED_RATE_MIN, 400u,
                                   MT_SCHED_RATE_MAX, MT_SCHED_RATE_MAX + 1u, 0xFFFFFFFFu};
    return invalid ? MTC_PICK(any) : MTC_PICK(valid);
}

void mtc_task_rates(mt_task_t *tasks, uint32_t n, uint32_t loop_rate_hz)
{
    uint64_t top = (uint64_t)loop_rate_hz * 1000u;
    uint32_t max_mhz = top > 0xFFFFFFFEu ? 0xFFFFFFFEu : (uint32_t)top;
    uint32_t rates[7];
    uint32_t i;

    rates[0] = 0u;
    rates[1] = 1u;
    rates[2] = 1000u;
    rates[3] = max_mhz / 3u;
    rates[4] = max_mhz;
    rates[5] = max_mhz + 1u;
    rates[6] = 0xFFFFFFFFu;
    for (i = 0u; i < n; i++) {
        tasks[i].rate_mhz = MTC_PICK(rates);
    }
}

mt_sched_t *mtc_sched(uint32_t nmax)
{
    mt_sched_t *s = MTC_NEW(mt_sched_t, 1u);
    mt_task_t *tasks;
    __CPROVER_assume(s->ntasks >= 1u && s->ntasks <= nmax);
    s->loop_rate_hz = mtc_loop_rate(0);
    tasks = mtc_tasks(s->ntasks);
    mtc_task_rates(tasks, s->ntasks, s->loop_rate_hz);
    s->tasks = tasks;
    return s;
}

mt_proc_set_t *mtc_proc_set(void)
{
    return MTC_NEW(mt_proc_set_t, 1u);
}

mt_sem_t *mtc_sem(void)
{
    mt_sem_t *s = MTC_NEW(mt_sem_t, 1u);
    s->waiter = mtc_nondet_bool() ? (mt_port_tref_t)0 : (mt_port_tref_t)&mtc_thread;
    return s;
}

mt_time_ext_t *mtc_time_ext(void)
{
    return MTC_NEW(mt_time_ext_t, 1u);
}

uint8_t *mtc_bytes(uint32_t n)
{
    return (uint8_t *)mtc_alloc(1u, n, MTC_K_BYTES);
}

void *mtc_callback(void)
{
    return (void *)&mtc_code;
}

uint32_t mtc_pick_u32(const uint32_t *vals, uint32_t n)
{
    uint32_t k = mtc_nondet_u32();
    __CPROVER_assume(k < n);
    return vals[k];
}

mt_mission_t *mtc_mission(void)
{
    return MTC_NEW(mt_mission_t, 1u);
}

mt_mission_cmd_t *mtc_mission_cmds(uint32_t n)
{
    return MTC_NEW(mt_mission_cmd_t, n);
}

static mt_port_tref_t mtc_waiter(void)
{
    return mtc_nondet_bool() ? (mt_port_tref_t)0 : (mt_port_tref_t)&mtc_thread;
}

mt_wq_t *mtc_wq(void)
{
    mt_wq_t *q = MTC_NEW(mt_wq_t, 1u);
    uint32_t i;

    q->wake.waiter = mtc_waiter();
    for (i = 0u; i < MT_CFG_WQ_MAX_ITEMS; i++) {
        q->slot[i].fn = mtc_nondet_bool() ? (mt_work_fn_t)0 : (mt_work_fn_t)mtc_callback();
        q->slot[i].arg = mtc_nondet_bool() ? (void *)0 : (void *)&mtc_thread;
        q->slot[i].done.waiter = mtc_waiter();
    }
    q->name = (const char *)0;
    return q;
}

void mtc_wq_periods(mt_wq_t *q)
{
    static const uint32_t periods[] = {1u, 3u, 1000u, 0xFFFFFFFFu};
    uint32_t i;

    for (i = 0u; i < MT_CFG_WQ_MAX_ITEMS; i++) {
        q->slot[i].period_us = MTC_PICK(periods);
    }
}

mt_work_t *mtc_work(mt_wq_t *q)
{
    mt_work_t *w = MTC_NEW(mt_work_t, 1u);

    w->wq = q;
    w->fn = (mt_work_fn_t)mtc_callback();
    w->arg = (void *)0;
    return w;
}

mt_topic_t *mtc_topic(void)
{
    mt_topic_t *t = MTC_NEW(mt_topic_t, 1u);
    uint32_t i;

    __CPROVER_assume(t->size >= 1u && t->size <= MT_CFG_BUS_MAX_MSG);
    __CPROVER_assume(t->qlen >= 1u && t->qlen <= MT_CFG_BUS_MAX_QUEUE);
    t->buf = (uint8_t *)mtc_alloc(1u, (__CPROVER_size_t)t->size * t->qlen, MTC_K_BYTES);
    for (i = 0u; i < MT_CFG_BUS_MAX_NOTIFY; i++) {
        t->notify_fn[i] = mtc_nondet_bool() ? (mt_bus_notify_fn_t)0
                                            : (mt_bus_notify_fn_t)mtc_callback();
        t->notify_arg[i] = mtc_nondet_bool() ? (void *)0 : (void *)&mtc_thread;
    }
    return t;
}

mt_sub_t *mtc_sub(mt_topic_t *t)
{
    mt_sub_t *s = MTC_NEW(mt_sub_t, 1u);
    s->topic = t;
    s->sem.waiter = mtc_nondet_bool() ? (mt_port_tref_t)0 : (mt_port_tref_t)&mtc_thread;
    return s;
}

void mtc_wq_time_window(const mt_wq_t *q, uint64_t now)
{
    const uint64_t w = (uint64_t)1u << 20;
    uint32_t i;

    if (now < w) {
        for (i = 0u; i < MT_CFG_WQ_MAX_ITEMS; i++) {
            __CPROVER_assume(q->slot[i].deadline_us < 2u * w);
        }
    } else {
        __CPROVER_assume(now >= UINT64_MAX - w);
        for (i = 0u; i < MT_CFG_WQ_MAX_ITEMS; i++) {
            __CPROVER_assume(q->slot[i].deadline_us >= UINT64_MAX - 2u * w);
        }
    }
}

uint64_t mtc_now_in_window(void)
{
    const uint64_t w = (uint64_t)1u << 20;
    uint64_t t = mtc_nondet_u64();

    /* the port contract (monotonic, recorded in MtPortNow), advancing by at most w */
    __CPROVER_assume(t >= MtPortNow && (t - MtPortNow) <= w);
    MtPortNow = t;
    return t;
}
