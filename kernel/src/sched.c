/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file sched.c
 * @brief Tick scheduler: table validation, set-up, the tick and the run of the due tasks
 *        (see mt/sched.h for the semantics; the loop's side is in sched_loop.c).
 */
#include "mt/sched.h"

#include "mt_invoke.h"
#include "mt_sat.h"
#include "mt_spec_sched.h"
#include "mt_spec_sched_init.h"

#define U32_MAX_ 0xFFFFFFFFu

mt_status_t mt_sched_check_entry(const mt_task_t *tasks, uint32_t n, uint32_t i,
                                 uint32_t loop_rate_hz)
{
    const mt_task_t *t = &tasks[i];
    uint32_t period = 1000000u / loop_rate_hz;

    (void)n;
    if (t->fn == (mt_task_fn_t)0) {
        return MT_E_TASK_FN;
    }
    if (t->priority < MT_SCHED_FAST_PRIO_LIMIT) {
        if (t->rate_mhz != 0u) {
            return MT_E_TASK_RATE;
        }
    } else {
        if ((t->rate_mhz < 1u) || (t->rate_mhz > (loop_rate_hz * 1000u))) {
            return MT_E_TASK_RATE;
        }
        if (t->budget_us < 1u) {
            return MT_E_TASK_BUDGET;
        }
    }
    if (t->budget_us > period) {
        return MT_E_TASK_BUDGET;
    }
    if ((i > 0u) && (tasks[i - 1u].priority > t->priority)) {
        return MT_E_TASK_ORDER;
    }
    return MT_OK;
}

mt_status_t mt_sched_validate(const mt_task_t *tasks, uint32_t n, uint32_t loop_rate_hz,
                              uint32_t *bad_index)
{
    uint32_t i;

    if ((loop_rate_hz < MT_SCHED_RATE_MIN) || (loop_rate_hz > MT_SCHED_RATE_MAX)) {
        *bad_index = n;
        return MT_E_LOOP_RATE;
    }
    if ((n < 1u) || (n > MT_CFG_SCHED_MAX_TASKS)) {
        *bad_index = n;
        return MT_E_TASK_COUNT;
    }
    /*@ loop invariant 0 <= i <= n;
        loop invariant \forall integer j; 0 <= j < i ==> MtTaskOk(tasks + j, loop_rate_hz);
        loop invariant \forall integer j; 0 <= j < i ==>
            MtEntryStatus(tasks, j, loop_rate_hz) == MT_OK;
        loop invariant \forall integer j; 0 <= j < i - 1 ==> tasks[j].priority <= tasks[j + 1].priority;
        loop assigns i;
        loop variant n - i;
    */
    for (i = 0u; i < n; i++) {
        mt_status_t st = mt_sched_check_entry(tasks, n, i, loop_rate_hz);
        if (st != MT_OK) {
            *bad_index = i;
            return st;
        }
    }
    return MT_OK;
}

/* Ticks between releases of a task of a validated table. */
/*@ requires valid: \valid_read(t);
    requires ok: MtTaskOk(t, rate_hz);
    requires rate: MT_SCHED_RATE_MIN <= rate_hz <= MT_SCHED_RATE_MAX;
    assigns \nothing;
    ensures value: \result == MtInterval(t, rate_hz);
    ensures positive: \result >= 1;
*/
static uint32_t task_interval(const mt_task_t *t, uint32_t rate_hz)
{
    uint32_t interval = 1u;

    if (t->priority >= MT_SCHED_FAST_PRIO_LIMIT) {
        /* rate <= loop rate (validated), so the interval is >= 1 */
        interval = (rate_hz * 1000u) / t->rate_mhz;
        //@ assert positive: interval >= 1;
    }
    return interval;
}

/* Fresh run-time state with the given interval. */
/*@ requires valid: \valid(e);
    assigns *e;
    ensures fresh: e->interval == interval && e->last_run == 0 && e->runs == 0 && e->slips == 0 &&
                   e->overruns == 0 && e->min_us == 0 && e->max_us == 0 && e->total_us == 0 &&
                   e->not_achieved == 0 && e->budget_skips == 0;
*/
static void state_init(mt_task_state_t *e, uint32_t interval)
{
    e->last_run = 0u;
    e->interval = interval;
    e->min_us = 0u;
    e->max_us = 0u;
    e->overruns = 0u;
    e->runs = 0u;
    e->total_us = 0u;
    e->slips = 0u;
    e->not_achieved = 0u;
    e->budget_skips = 0u;
}

/* The scalar fields of a fresh scheduler, in small groups by type: each group is a function
 * of its own so that each frame goal (the table and the per-task states are kept) starts from
 * the function's own pre-state and stays small enough for the solvers. */
/*@ requires valid: \valid(s);
    requires facts: MtInitFacts(s, tasks, n, loop_rate_hz);
    requires sep: \separated(s, tasks + (0 .. n - 1));
    assigns s->tasks, s->ntasks, s->loop_rate_hz, s->period_us, s->current;
    ensures set: s->tasks == tasks && s->ntasks == n && s->loop_rate_hz == loop_rate_hz && s->period_us == 1000000 / loop_rate_hz && s->current == MT_SCHED_IDLE;
    ensures facts: MtInitFacts(s, tasks, n, loop_rate_hz);
*/
static void init_table_fields(mt_sched_t *s, const mt_task_t *tasks, uint32_t n, uint32_t loop_rate_hz)
{
    s->tasks = tasks;
    s->ntasks = n;
    s->loop_rate_hz = loop_rate_hz;
    s->period_us = 1000000u / loop_rate_hz;
    s->current = MT_SCHED_IDLE;
}

/*@ requires valid: \valid(s);
    requires facts: MtInitFacts(s, tasks, n, loop_rate_hz);
    requires sep: \separated(s, tasks + (0 .. n - 1));
    assigns s->tick, s->run_tick, s->spare_us, s->loops;
    ensures set: s->tick == 0 && s->run_tick == 0 && s->spare_us == 0 && s->loops == 0;
    ensures facts: MtInitFacts(s, tasks, n, loop_rate_hz);
*/
static void init_ticks(mt_sched_t *s, const mt_task_t *tasks, uint32_t n, uint32_t loop_rate_hz)
{
    /* the table arguments name the facts of the contract only */
    (void)tasks;
    (void)n;
    (void)loop_rate_hz;
    s->tick = 0u;
    s->run_tick = 0u;
    s->spare_us = 0u;
    s->loops = 0u;
    //@ assert kept: MtInitKept{Pre, Here}(s, tasks, n);
}

/*@ requires valid: \valid(s);
    requires facts: MtInitFacts(s, tasks, n, loop_rate_hz);
    requires sep: \separated(s, tasks + (0 .. n - 1));
    assigns s->loop_total_us, s->last_sample_us, s->task_start_us;
    ensures set: s->loop_total_us == 0 && s->last_sample_us == 0 && s->task_start_us == 0;
    ensures facts: MtInitFacts(s, tasks, n, loop_rate_hz);
*/
static void init_times(mt_sched_t *s, const mt_task_t *tasks, uint32_t n, uint32_t loop_rate_hz)
{
    /* the table arguments name the facts of the contract only */
    (void)tasks;
    (void)n;
    (void)loop_rate_hz;
    s->loop_total_us = 0u;
    s->last_sample_us = 0u;
    s->task_start_us = 0u;
    //@ assert kept: MtInitKept{Pre, Here}(s, tasks, n);
}

/*@ requires valid: \valid(s);
    requires facts: MtInitFacts(s, tasks, n, loop_rate_hz);
    requires sep: \separated(s, tasks + (0 .. n - 1));
    assigns s->extra_us, s->clean_loops, s->late_in_loop, s->spare_ticks;
    ensures set: s->extra_us == 0 && s->clean_loops == 0 && s->late_in_loop == 0 && s->spare_ticks == 0;
    ensures facts: MtInitFacts(s, tasks, n, loop_rate_hz);
*/
static void init_window(mt_sched_t *s, const mt_task_t *tasks, uint32_t n, uint32_t loop_rate_hz)
{
    /* the table arguments name the facts of the contract only */
    (void)tasks;
    (void)n;
    (void)loop_rate_hz;
    s->extra_us = 0u;
    s->clean_loops = 0u;
    s->late_in_loop = 0u;
    s->spare_ticks = 0u;
    //@ assert kept: MtInitKept{Pre, Here}(s, tasks, n);
}

/*@ requires valid: \valid(s);
    requires facts: MtInitFacts(s, tasks, n, loop_rate_hz);
    requires sep: \separated(s, tasks + (0 .. n - 1));
    assigns s->filtered_loop_q8, s->loop_min_us, s->loop_max_us, s->long_loops, s->task_allowed_us;
    ensures set: s->filtered_loop_q8 == (1000000 / loop_rate_hz) * 256 && s->loop_min_us == 0 && s->loop_max_us == 0 && s->long_loops == 0 && s->task_allowed_us == 0;
    ensures facts: MtInitFacts(s, tasks, n, loop_rate_hz);
*/
static void init_loop_stats(mt_sched_t *s, const mt_task_t *tasks, uint32_t n, uint32_t loop_rate_hz)
{
    /* the table arguments name the facts of the contract only */
    (void)tasks;
    (void)n;
    s->filtered_loop_q8 = (1000000u / loop_rate_hz) * 256u;
    s->loop_min_us = 0u;
    s->loop_max_us = 0u;
    s->long_loops = 0u;
    s->task_allowed_us = 0u;
    //@ assert kept: MtInitKept{Pre, Here}(s, tasks, n);
}

mt_status_t mt_sched_init(mt_sched_t *s, const mt_task_t *tasks, uint32_t n,
                          uint32_t loop_rate_hz, uint32_t *bad_index)
{
    uint32_t i;
    mt_status_t st = mt_sched_validate(tasks, n, loop_rate_hz, bad_index);

    if (st != MT_OK) {
        return st;
    }
    //@ assert table: MtTableOk{Pre}(tasks, n, loop_rate_hz);
    /* Per-task state first (the loop writes s->st only), then the scalars. */
    /*@ loop invariant 0 <= i <= MT_CFG_SCHED_MAX_TASKS;
        loop invariant kept: MtTableKept{Pre, Here}(tasks, n);
        loop invariant set: \forall integer j; 0 <= j < i ==> j < n ==>
            s->st[j].interval == MtInterval{Pre}(tasks + j, loop_rate_hz);
        loop invariant zero: \forall integer j; 0 <= j < i ==>
            s->st[j].runs == 0 && s->st[j].last_run == 0 && s->st[j].slips == 0 &&
            s->st[j].overruns == 0 && s->st[j].interval >= 1;
        loop assigns i, s->st[0 .. MT_CFG_SCHED_MAX_TASKS - 1];
        loop variant MT_CFG_SCHED_MAX_TASKS - i;
    */
    for (i = 0u; i < MT_CFG_SCHED_MAX_TASKS; i++) {
        uint32_t interval = 1u;
        if (i < n) {
            //@ assert ok_i: MtTaskOk{Pre}(tasks + i, loop_rate_hz);
            interval = task_interval(&tasks[i], loop_rate_hz);
        }
        state_init(&s->st[i], interval);
    }
    //@ assert facts: MtInitFacts(s, tasks, n, loop_rate_hz);
    init_table_fields(s, tasks, n, loop_rate_hz);
    init_ticks(s, tasks, n, loop_rate_hz);
    init_times(s, tasks, n, loop_rate_hz);
    init_window(s, tasks, n, loop_rate_hz);
    init_loop_stats(s, tasks, n, loop_rate_hz);
    //@ ghost sched_inv_fresh(s, tasks, n, loop_rate_hz);
    return MT_OK;
}

void mt_sched_tick(mt_sched_t *s)
{
    s->tick++;
}

/* Account a run of task i that took taken_us against allowed_us. */
/*@ requires valid: \valid(s);
    requires index: i < MT_CFG_SCHED_MAX_TASKS;
    requires room: s->st[i].runs < s->tick;
    assigns s->st[i].runs, s->st[i].min_us, s->st[i].max_us, s->st[i].total_us,
            s->st[i].overruns, s->st[i].last_run;
    ensures s->st[i].runs == \old(s->st[i].runs) + 1;
    ensures s->st[i].last_run == s->tick;
*/
static void note_run(mt_sched_t *s, uint32_t i, uint64_t taken_us, uint32_t allowed_us)
{
    mt_task_state_t *e = &s->st[i];
    uint32_t t = mt_clamp_u32(taken_us);

    if ((e->runs == 0u) || (t < e->min_us)) {
        e->min_us = t;
    }
    if (t > e->max_us) {
        e->max_us = t;
    }
    e->total_us = mt_add_sat_u64(e->total_us, taken_us);
    if ((taken_us > allowed_us) && (e->overruns < U32_MAX_)) {
        e->overruns++;
    }
    e->runs++;
    e->last_run = s->tick;
}

/* Run task i with allowance allowed_us; returns the time at which it ended. */
/*@ requires valid: \valid(s);
    requires index: i < MT_CFG_SCHED_MAX_TASKS;
    requires task: \valid_read(s->tasks + i) && s->tasks[i].fn != \null;
    requires sep: s->ntasks <= MT_CFG_SCHED_MAX_TASKS && \separated(s, s->tasks + (0 .. s->ntasks - 1));
    requires room: s->st[i].runs < s->tick;
    assigns s->current, s->task_start_us, s->task_allowed_us, MtPortNow, MtPortWakes,
            s->st[i].runs, s->st[i].min_us, s->st[i].max_us, s->st[i].total_us,
            s->st[i].overruns, s->st[i].last_run, MtCalls[MT_CALL_TASK(i)];
    ensures s->current == MT_SCHED_IDLE;
    ensures called: MtCalls[MT_CALL_TASK(i)] == MtCount64(\old(MtCalls[MT_CALL_TASK(i)]), 1);
    ensures s->st[i].runs == \old(s->st[i].runs) + 1;
    ensures s->st[i].last_run == s->tick;
    ensures \result == MtPortNow && \result >= \old(MtPortNow);
    ensures kept: MtSchedKept{Pre, Post}(s);
    ensures others: \forall integer j; 0 <= j < MT_CFG_SCHED_MAX_TASKS ==> j != i ==>
        s->st[j].runs == \old(s->st[j].runs) && s->st[j].last_run == \old(s->st[j].last_run);
    ensures tick: s->tick == \old(s->tick) && s->run_tick == \old(s->run_tick);
*/
static uint64_t run_task(mt_sched_t *s, uint32_t i, uint32_t allowed_us)
{
    uint64_t t0 = mt_port_now_us();
    uint64_t t1;

    s->task_start_us = t0;
    s->task_allowed_us = allowed_us;
    s->current = (int32_t)i;
    // cppcheck-suppress misra-c2012-11.8 ; D-103 no cast: the const table holds a void * by value
    mt_invoke(s->tasks[i].fn, s->tasks[i].arg, MT_CALL_TASK(i));
    s->current = MT_SCHED_IDLE;
    t1 = mt_port_now_us();
    note_run(s, i, t1 - t0, allowed_us);
    return t1;
}

/* Slip and lateness accounting for a normal task that runs dt ticks after its
 * last run (dt >= interval). */
/*@ requires valid: \valid(s);
    requires index: i < MT_CFG_SCHED_MAX_TASKS;
    requires due: s->st[i].interval >= 1 && dt >= s->st[i].interval;
    requires sep: s->ntasks <= MT_CFG_SCHED_MAX_TASKS && \separated(s, s->tasks + (0 .. s->ntasks - 1));
    assigns s->st[i].slips, s->st[i].not_achieved, s->late_in_loop;
    ensures s->st[i].slips == (\old(s->st[i].slips) + (dt / s->st[i].interval - 1) <= 0xFFFFFFFFFFFFFFFF ?
                               \old(s->st[i].slips) + (dt / s->st[i].interval - 1) : 0xFFFFFFFFFFFFFFFF);
    ensures counted: MtSlipsCounted(s->st[i].slips, \old(s->st[i].slips), dt, s->st[i].interval);
    ensures late: s->st[i].not_achieved == (dt >= MT_SCHED_SLOWDOWN * s->st[i].interval ?
        MtSatAdd64(\old(s->st[i].not_achieved), 1) : \old(s->st[i].not_achieved));
    ensures kept: MtSchedKept{Pre, Post}(s);
    ensures others: \forall integer j; 0 <= j < MT_CFG_SCHED_MAX_TASKS ==> j != i ==>
        s->st[j].runs == \old(s->st[j].runs) && s->st[j].last_run == \old(s->st[j].last_run);
    ensures tick: s->tick == \old(s->tick) && s->run_tick == \old(s->run_tick);
*/
static void note_release(mt_sched_t *s, uint32_t i, uint64_t dt)
{
    mt_task_state_t *e = &s->st[i];
    uint64_t iv = e->interval;

    if (dt >= (2u * iv)) {
        /* releases in dt = floor(dt / interval); all but the one served now slipped */
        e->slips = mt_add_sat_u64(e->slips, (dt / iv) - 1u);
    }
    //@ assert one_release: dt < 2 * iv ==> dt / iv == 1;
    //@ assert two_releases: 2 * iv <= dt < 3 * iv ==> dt / iv == 2;
    //@ assert three_or_more: 3 * iv <= dt ==> dt / iv >= 3;
    if (dt >= ((uint64_t)MT_SCHED_SLOWDOWN * iv)) {
        e->not_achieved = mt_add_sat_u64(e->not_achieved, 1u);
        if (s->late_in_loop < U32_MAX_) {
            s->late_in_loop++;
        }
    }
}

/* A due task skipped because its budget does not fit: counted, stays due. */
/*@ requires valid: \valid(s);
    requires index: i < MT_CFG_SCHED_MAX_TASKS;
    requires sep: s->ntasks <= MT_CFG_SCHED_MAX_TASKS && \separated(s, s->tasks + (0 .. s->ntasks - 1));
    assigns s->st[i].budget_skips;
    ensures counted: s->st[i].budget_skips == (\old(s->st[i].budget_skips) < 0xFFFFFFFFFFFFFFFF ?
                                              \old(s->st[i].budget_skips) + 1 : 0xFFFFFFFFFFFFFFFF);
    ensures kept: MtSchedKept{Pre, Post}(s);
    ensures others: \forall integer j; 0 <= j < MT_CFG_SCHED_MAX_TASKS ==>
        s->st[j].runs == \old(s->st[j].runs) && s->st[j].last_run == \old(s->st[j].last_run);
*/
static void note_skip(mt_sched_t *s, uint32_t i)
{
    s->st[i].budget_skips = mt_add_sat_u64(s->st[i].budget_skips, 1u);
}

/* Serve normal task i, due dt ticks after its last run: count its missed releases and its
 * lateness, then run it with its budget as the allowance. */
/*@ requires valid: \valid(s);
    requires index: i < MT_CFG_SCHED_MAX_TASKS;
    requires task: \valid_read(s->tasks + i) && s->tasks[i].fn != \null;
    requires sep: s->ntasks <= MT_CFG_SCHED_MAX_TASKS && \separated(s, s->tasks + (0 .. s->ntasks - 1));
    requires room: s->st[i].runs < s->tick;
    requires due: s->st[i].interval >= 1 && s->st[i].last_run <= s->tick &&
                  dt == s->tick - s->st[i].last_run && dt >= s->st[i].interval;
    assigns s->current, s->task_start_us, s->task_allowed_us, MtPortNow, MtPortWakes,
            s->st[i].runs, s->st[i].min_us, s->st[i].max_us, s->st[i].total_us,
            s->st[i].overruns, s->st[i].last_run, s->st[i].slips, s->st[i].not_achieved,
            s->late_in_loop, MtCalls[MT_CALL_TASK(i)];
    ensures served: s->st[i].runs == \old(s->st[i].runs) + 1 && s->st[i].last_run == s->tick &&
        MtCalls[MT_CALL_TASK(i)] == MtCount64(\old(MtCalls[MT_CALL_TASK(i)]), 1) &&
        MtSlipsCounted(s->st[i].slips, \old(s->st[i].slips), dt, \old(s->st[i].interval)) &&
        s->st[i].not_achieved == MtLateAfter(\old(s->st[i].not_achieved), dt, \old(s->st[i].interval));
    ensures s->current == MT_SCHED_IDLE;
    ensures \result == MtPortNow && \result >= \old(MtPortNow);
    ensures kept: MtSchedKept{Pre, Post}(s);
    ensures tick: s->tick == \old(s->tick) && s->run_tick == \old(s->run_tick);
*/
static uint64_t serve(mt_sched_t *s, uint32_t i, uint64_t dt)
{
    note_release(s, i, dt);
    return run_task(s, i, s->tasks[i].budget_us);
}

/* One step of the scan: task i runs if it is fast, or due and its budget fits the time left
 * (avail); returns the time left after it, measured from start (S-9). */
/*@ requires inv: MtSchedInv(s) && s->run_tick == s->tick;
    requires index: i < s->ntasks;
    requires fresh: s->st[i].runs < s->tick;
    requires left: avail <= time_available_us;
    requires start: start <= MtPortNow;
    requires spent: (integer)time_available_us - avail <= MtPortNow - start;
    assigns s->st[i].runs, s->st[i].min_us, s->st[i].max_us, s->st[i].total_us, s->st[i].overruns,
            s->st[i].last_run, s->st[i].slips, s->st[i].not_achieved, s->st[i].budget_skips,
            s->current, s->late_in_loop, s->task_start_us, s->task_allowed_us, MtPortNow, MtPortWakes,
            MtCalls[MT_CALL_TASK(i)];
    ensures inv: MtSchedInv(s) && s->run_tick == s->tick;
    ensures kept: MtSchedKept{Pre, Post}(s);
    ensures tick: s->tick == \old(s->tick);
    ensures time: MtPortNow >= \old(MtPortNow);
    ensures left: \result <= time_available_us;
    ensures crumb: s->current == \old(s->current) || s->current == MT_SCHED_IDLE;
    ensures spent: (integer)time_available_us - \result <= MtPortNow - start;
    ensures shrinks: \result <= avail;
    ensures kept_if_idle: s->st[i].runs == \old(s->st[i].runs) ==> \result == avail;
    ensures fast: \old(MtTaskFast(s->tasks + i)) ==>
        s->st[i].runs == \old(s->st[i].runs) + 1 && s->st[i].last_run == s->tick &&
        s->st[i].slips == \old(s->st[i].slips) && s->st[i].not_achieved == \old(s->st[i].not_achieved) &&
        s->st[i].budget_skips == \old(s->st[i].budget_skips) &&
        MtCalls[MT_CALL_TASK(i)] == MtCount64(\old(MtCalls[MT_CALL_TASK(i)]), 1);
    ensures idle: !\old(MtTaskFast(s->tasks + i)) ==> !\old(MtTaskDue(s, i)) ==>
        s->st[i].runs == \old(s->st[i].runs) && s->st[i].last_run == \old(s->st[i].last_run) &&
        s->st[i].slips == \old(s->st[i].slips) && s->st[i].not_achieved == \old(s->st[i].not_achieved) &&
        s->st[i].budget_skips == \old(s->st[i].budget_skips) &&
        MtCalls[MT_CALL_TASK(i)] == \old(MtCalls[MT_CALL_TASK(i)]);
    ensures served: !\old(MtTaskFast(s->tasks + i)) ==> \old(MtTaskDue(s, i)) ==>
        s->st[i].runs != \old(s->st[i].runs) ==>
        s->st[i].runs == \old(s->st[i].runs) + 1 && s->st[i].last_run == s->tick &&
        s->st[i].budget_skips == \old(s->st[i].budget_skips) &&
        MtCalls[MT_CALL_TASK(i)] == MtCount64(\old(MtCalls[MT_CALL_TASK(i)]), 1) &&
        MtSlipsCounted(s->st[i].slips, \old(s->st[i].slips), \old(s->tick - s->st[i].last_run),
                       \old(s->st[i].interval)) &&
        s->st[i].not_achieved == MtLateAfter(\old(s->st[i].not_achieved), \old(s->tick - s->st[i].last_run),
                                             \old(s->st[i].interval)) &&
        \old(s->tasks[i].budget_us) <= avail;
    ensures skipped: !\old(MtTaskFast(s->tasks + i)) ==> \old(MtTaskDue(s, i)) ==>
        s->st[i].runs == \old(s->st[i].runs) ==>
        s->st[i].last_run == \old(s->st[i].last_run) &&
        s->st[i].slips == \old(s->st[i].slips) && s->st[i].not_achieved == \old(s->st[i].not_achieved) &&
        s->st[i].budget_skips == MtSatAdd64(\old(s->st[i].budget_skips), 1) &&
        MtCalls[MT_CALL_TASK(i)] == \old(MtCalls[MT_CALL_TASK(i)]) && \old(s->tasks[i].budget_us) > avail;
    ensures others: \forall integer j; 0 <= j < MT_CFG_SCHED_MAX_TASKS ==> j != i ==>
        s->st[j].interval == \old(s->st[j].interval) && s->st[j].runs == \old(s->st[j].runs) &&
        s->st[j].last_run == \old(s->st[j].last_run) && s->st[j].slips == \old(s->st[j].slips) &&
        s->st[j].not_achieved == \old(s->st[j].not_achieved) &&
        s->st[j].budget_skips == \old(s->st[j].budget_skips) &&
        MtCalls[MT_CALL_TASK(j)] == \old(MtCalls[MT_CALL_TASK(j)]);
*/
static uint32_t run_step(mt_sched_t *s, uint32_t i, uint32_t time_available_us, uint64_t start,
                         uint32_t avail)
{
    const mt_task_t *t = &s->tasks[i];
    uint64_t end;

    if (t->priority < MT_SCHED_FAST_PRIO_LIMIT) {
        /* fast task: every tick, whatever is left */
        end = run_task(s, i, (t->budget_us != 0u) ? t->budget_us : s->period_us);
    } else {
        uint64_t dt = s->tick - s->st[i].last_run;
        if (dt < s->st[i].interval) {
            return avail; /* not due */
        }
        if (t->budget_us > avail) {
            /* due but does not fit: skipped, stays due, scan goes on */
            note_skip(s, i);
            //@ assert kept_skip: MtSchedKept{Pre, Here}(s);
            //@ ghost sched_inv_intro(s);
            return avail;
        }
        end = serve(s, i, dt);
    }
    //@ assert kept_run: MtSchedKept{Pre, Here}(s);
    //@ ghost sched_inv_intro(s);
    /* S-9: the budget shrinks by the wall time since the scan started, so time between tasks
     * and pre-emption by other threads count too */
    return ((end - start) >= time_available_us) ? 0u : (time_available_us - (uint32_t)(end - start));
}

uint32_t mt_sched_run(mt_sched_t *s, uint32_t time_available_us)
{
    uint32_t avail = time_available_us;
    uint64_t start;
    uint32_t i;
    /* Ghost copies of each task's accounting as its step left it: the scan's invariants state
     * each task's outcome over these copies, so that a later step's frame goal is one equality
     * per field (frozen) and no outcome goal carries a chain of memory updates. */
    //@ ghost uint64_t g_runs[MT_CFG_SCHED_MAX_TASKS];
    //@ ghost uint64_t g_last[MT_CFG_SCHED_MAX_TASKS];
    //@ ghost uint64_t g_slips[MT_CFG_SCHED_MAX_TASKS];
    //@ ghost uint64_t g_late[MT_CFG_SCHED_MAX_TASKS];
    //@ ghost uint64_t g_skips[MT_CFG_SCHED_MAX_TASKS];
    //@ ghost long long g_calls[MT_CFG_SCHED_MAX_TASKS];

    if (s->run_tick == s->tick) {
        return avail; /* this tick has been run already */
    }
    s->run_tick = s->tick;
    start = mt_port_now_us();
    //@ assert fresh_all: \forall integer j; 0 <= j < s->ntasks ==> s->st[j].runs < s->tick;
    /*@ loop invariant range: 0 <= i <= \at(s->ntasks, Pre);
        loop invariant kept: MtSchedKept{Pre, Here}(s);
        loop invariant inv: MtSchedInv(s) && s->run_tick == s->tick && s->tick == \at(s->tick, Pre);
        loop invariant avail <= time_available_us;
        loop invariant crumb: s->current == \at(s->current, Pre) || s->current == MT_SCHED_IDLE;
        loop invariant start <= MtPortNow;
        loop invariant spent: (integer)time_available_us - avail <= MtPortNow - start;
        loop invariant new_tick: \at(s->run_tick, Pre) < s->tick;
        loop invariant todo: \forall integer j; i <= j < MT_CFG_SCHED_MAX_TASKS ==>
            s->st[j].interval == \at(s->st[j].interval, Pre) && s->st[j].runs == \at(s->st[j].runs, Pre) &&
            s->st[j].last_run == \at(s->st[j].last_run, Pre) && s->st[j].slips == \at(s->st[j].slips, Pre) &&
            s->st[j].not_achieved == \at(s->st[j].not_achieved, Pre) &&
            s->st[j].budget_skips == \at(s->st[j].budget_skips, Pre) &&
            MtCalls[MT_CALL_TASK(j)] == \at(MtCalls[MT_CALL_TASK(j)], Pre);
        loop invariant fresh: \forall integer j; i <= j < \at(s->ntasks, Pre) ==> s->st[j].runs < s->tick;
        loop invariant frozen: \forall integer j; 0 <= j < i ==>
            s->st[j].interval == \at(s->st[j].interval, Pre) &&
            s->st[j].runs == g_runs[j] && s->st[j].last_run == g_last[j] && s->st[j].slips == g_slips[j] &&
            s->st[j].not_achieved == g_late[j] && s->st[j].budget_skips == g_skips[j] &&
            MtCalls[MT_CALL_TASK(j)] == g_calls[j];
        loop invariant none_yet: (\forall integer j; 0 <= j < i ==> g_runs[j] == \at(s->st[j].runs, Pre)) ==>
            avail == time_available_us;
        loop invariant done_fast: \forall integer j; 0 <= j < i ==> \at(MtTaskFast(s->tasks + j), Pre) ==>
            g_runs[j] == \at(s->st[j].runs, Pre) + 1 && g_last[j] == \at(s->tick, Pre) &&
            g_slips[j] == \at(s->st[j].slips, Pre) && g_late[j] == \at(s->st[j].not_achieved, Pre) &&
            g_skips[j] == \at(s->st[j].budget_skips, Pre) &&
            g_calls[j] == MtCount64(\at(MtCalls[MT_CALL_TASK(j)], Pre), 1);
        loop invariant done_idle: \forall integer j; 0 <= j < i ==> !\at(MtTaskFast(s->tasks + j), Pre) ==>
            !\at(MtTaskDue(s, j), Pre) ==>
            g_runs[j] == \at(s->st[j].runs, Pre) && g_last[j] == \at(s->st[j].last_run, Pre) &&
            g_slips[j] == \at(s->st[j].slips, Pre) && g_late[j] == \at(s->st[j].not_achieved, Pre) &&
            g_skips[j] == \at(s->st[j].budget_skips, Pre) && g_calls[j] == \at(MtCalls[MT_CALL_TASK(j)], Pre);
        loop invariant done_served: \forall integer j; 0 <= j < i ==> !\at(MtTaskFast(s->tasks + j), Pre) ==>
            \at(MtTaskDue(s, j), Pre) ==> g_runs[j] != \at(s->st[j].runs, Pre) ==>
            g_runs[j] == \at(s->st[j].runs, Pre) + 1 && g_last[j] == \at(s->tick, Pre) &&
            g_skips[j] == \at(s->st[j].budget_skips, Pre) &&
            g_calls[j] == MtCount64(\at(MtCalls[MT_CALL_TASK(j)], Pre), 1) &&
            MtSlipsCounted(g_slips[j], \at(s->st[j].slips, Pre), \at(s->tick - s->st[j].last_run, Pre),
                           \at(s->st[j].interval, Pre)) &&
            g_late[j] == MtLateAfter(\at(s->st[j].not_achieved, Pre), \at(s->tick - s->st[j].last_run, Pre),
                                     \at(s->st[j].interval, Pre)) &&
            \at(s->tasks[j].budget_us, Pre) <= time_available_us;
        loop invariant done_skipped: \forall integer j; 0 <= j < i ==> !\at(MtTaskFast(s->tasks + j), Pre) ==>
            \at(MtTaskDue(s, j), Pre) ==> g_runs[j] == \at(s->st[j].runs, Pre) ==>
            g_last[j] == \at(s->st[j].last_run, Pre) &&
            g_slips[j] == \at(s->st[j].slips, Pre) && g_late[j] == \at(s->st[j].not_achieved, Pre) &&
            g_skips[j] == MtSatAdd64(\at(s->st[j].budget_skips, Pre), 1) &&
            g_calls[j] == \at(MtCalls[MT_CALL_TASK(j)], Pre) && \at(s->tasks[j].budget_us, Pre) > avail;
        loop assigns i, avail, s->st[0 .. MT_CFG_SCHED_MAX_TASKS - 1], s->current, s->late_in_loop,
                     s->task_start_us, s->task_allowed_us, MtPortNow, MtPortWakes,
                     MtCalls[MT_CALL_TASK(0) .. MT_CALL_TASK(MT_CFG_SCHED_MAX_TASKS - 1)],
                     g_runs[0 .. MT_CFG_SCHED_MAX_TASKS - 1], g_last[0 .. MT_CFG_SCHED_MAX_TASKS - 1],
                     g_slips[0 .. MT_CFG_SCHED_MAX_TASKS - 1], g_late[0 .. MT_CFG_SCHED_MAX_TASKS - 1],
                     g_skips[0 .. MT_CFG_SCHED_MAX_TASKS - 1], g_calls[0 .. MT_CFG_SCHED_MAX_TASKS - 1];
        loop variant \at(s->ntasks, Pre) - i;
    */
    for (i = 0u; i < s->ntasks; i++) {
        avail = run_step(s, i, time_available_us, start, avail);
        //@ ghost g_runs[i] = s->st[i].runs;
        //@ ghost g_last[i] = s->st[i].last_run;
        //@ ghost g_slips[i] = s->st[i].slips;
        //@ ghost g_late[i] = s->st[i].not_achieved;
        //@ ghost g_skips[i] = s->st[i].budget_skips;
        //@ ghost g_calls[i] = MtCalls[MT_CALL_TASK(i)];
    }
    /*@ assert all_fast: \forall integer j; 0 <= j < s->ntasks ==> \at(MtTaskFast(s->tasks + j), Pre) ==>
            s->st[j].runs == \at(s->st[j].runs, Pre) + 1 && s->st[j].last_run == s->tick &&
            s->st[j].slips == \at(s->st[j].slips, Pre) && s->st[j].not_achieved == \at(s->st[j].not_achieved, Pre) &&
            s->st[j].budget_skips == \at(s->st[j].budget_skips, Pre) &&
            MtCalls[MT_CALL_TASK(j)] == MtCount64(\at(MtCalls[MT_CALL_TASK(j)], Pre), 1); */
    /*@ assert all_served: \forall integer j; 0 <= j < s->ntasks ==> !\at(MtTaskFast(s->tasks + j), Pre) ==>
            \at(MtTaskDue(s, j), Pre) ==> s->st[j].runs != \at(s->st[j].runs, Pre) ==>
            s->st[j].runs == \at(s->st[j].runs, Pre) + 1 && s->st[j].last_run == s->tick &&
            s->st[j].budget_skips == \at(s->st[j].budget_skips, Pre) &&
            MtCalls[MT_CALL_TASK(j)] == MtCount64(\at(MtCalls[MT_CALL_TASK(j)], Pre), 1) &&
            MtSlipsCounted(s->st[j].slips, \at(s->st[j].slips, Pre), \at(s->tick - s->st[j].last_run, Pre),
                           \at(s->st[j].interval, Pre)) &&
            s->st[j].not_achieved == MtLateAfter(\at(s->st[j].not_achieved, Pre),
                \at(s->tick - s->st[j].last_run, Pre), \at(s->st[j].interval, Pre)) &&
            \at(s->tasks[j].budget_us, Pre) <= time_available_us; */
    /*@ assert all_skipped: \forall integer j; 0 <= j < s->ntasks ==> !\at(MtTaskFast(s->tasks + j), Pre) ==>
            \at(MtTaskDue(s, j), Pre) ==> s->st[j].runs == \at(s->st[j].runs, Pre) ==>
            s->st[j].last_run == \at(s->st[j].last_run, Pre) &&
            s->st[j].slips == \at(s->st[j].slips, Pre) && s->st[j].not_achieved == \at(s->st[j].not_achieved, Pre) &&
            s->st[j].budget_skips == MtSatAdd64(\at(s->st[j].budget_skips, Pre), 1) &&
            MtCalls[MT_CALL_TASK(j)] == \at(MtCalls[MT_CALL_TASK(j)], Pre) &&
            \at(s->tasks[j].budget_us, Pre) > avail; */
    return avail;
}
