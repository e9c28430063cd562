/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file sched_loop.c
 * @brief Tick scheduler, the loop's side: end of a loop, loop samples, one whole loop, the
 *        time left to a task, the load, the reports and the statistics reset (see mt/sched.h;
 *        validation, set-up, tick and run are in sched.c).
 */
#include "mt/sched.h"

#include "mt_invoke.h"
#include "mt_sat.h"
#include "mt_spec_sched.h"

#define U32_MAX_ 0xFFFFFFFFu

void mt_sched_end_loop(mt_sched_t *s, uint32_t spare_us)
{
    s->spare_us += spare_us;
    s->spare_ticks++;
    if (s->spare_ticks >= MT_SCHED_SPARE_WINDOW) {
        /* exponential window: halve both */
        s->spare_us /= 2u;
        s->spare_ticks /= 2u;
    }
    if (s->late_in_loop > 0u) {
        s->extra_us = ((s->extra_us + MT_SCHED_EXTRA_STEP_US) <= MT_SCHED_EXTRA_MAX_US)
                          ? (s->extra_us + MT_SCHED_EXTRA_STEP_US)
                          : MT_SCHED_EXTRA_MAX_US;
        s->clean_loops = 0u;
    } else if (s->extra_us > 0u) {
        s->clean_loops++;
        if (s->clean_loops > MT_SCHED_CLEAN_LOOPS) {
            s->clean_loops = 0u;
            s->extra_us = (s->extra_us > MT_SCHED_EXTRA_DECAY_US)
                              ? (s->extra_us - MT_SCHED_EXTRA_DECAY_US)
                              : 0u;
        }
    } else {
        s->clean_loops = 0u;
    }
    s->late_in_loop = 0u;
    //@ assert kept: MtSchedKept{Pre, Here}(s);
    //@ ghost sched_inv_intro(s);
}

void mt_sched_note_sample(mt_sched_t *s, uint64_t sample_us)
{
    if ((s->last_sample_us != 0u) && (sample_us >= s->last_sample_us)) {
        uint32_t loop_us = mt_clamp_u32(sample_us - s->last_sample_us);
        /* loops longer than 1.2 periods + 10 ms are outliers for the filter */
        uint32_t outlier = ((s->period_us / 5u) * 6u) + 10000u;
        if ((s->loops == 0u) || (loop_us < s->loop_min_us)) {
            s->loop_min_us = loop_us;
        }
        if (loop_us > s->loop_max_us) {
            s->loop_max_us = loop_us;
        }
        if ((loop_us > ((s->period_us / 5u) * 6u)) && (s->long_loops < U32_MAX_)) {
            s->long_loops++;
        }
        if (loop_us <= outlier) {
            /* EMA 0.99 / 0.01 in Q8: f += (sample - f) / 100 */
            uint64_t f = s->filtered_loop_q8;
            uint64_t x = (uint64_t)loop_us * 256u;
            f = (x >= f) ? (f + ((x - f) / 100u)) : (f - ((f - x) / 100u));
            s->filtered_loop_q8 = mt_clamp_u32(f);
        }
        s->loop_total_us = mt_add_sat_u64(s->loop_total_us, loop_us);
        s->loops = mt_add_sat_u64(s->loops, 1u);
    }
    s->last_sample_us = sample_us;
    //@ assert kept: MtSchedKept{Pre, Here}(s);
    //@ ghost sched_inv_intro(s);
}

void mt_sched_loop_once(mt_sched_t *s, mt_sample_wait_fn_t wait, void *ctx)
{
    uint64_t sample;
    uint64_t now;
    uint64_t elapsed;
    uint32_t avail;
    uint32_t left;

    s->current = MT_SCHED_WAIT_SAMPLE;
    sample = mt_invoke_u64(wait, ctx, MT_CALL_WAIT);
    s->current = MT_SCHED_IDLE;
    mt_sched_note_sample(s, sample);
    mt_sched_tick(s);
    now = mt_port_now_us();
    // cppcheck-suppress misra-c2012-12.1 ; D-102 fully parenthesised; addon false positive
    elapsed = (now >= sample) ? (now - sample) : 0u;
    avail = (elapsed >= s->period_us) ? 0u : (s->period_us - (uint32_t)elapsed);
    avail += s->extra_us;
    left = mt_sched_run(s, avail);
    mt_sched_end_loop(s, left);
}

uint32_t mt_sched_time_available_us(const mt_sched_t *s)
{
    uint64_t now = mt_port_now_us();
    uint64_t used;

    if ((s->current < 0) || (now < s->task_start_us)) {
        return 0u;
    }
    used = now - s->task_start_us;
    return (used >= s->task_allowed_us) ? 0u : (s->task_allowed_us - (uint32_t)used);
}

uint32_t mt_sched_load_permille(const mt_sched_t *s)
{
    uint64_t mean_spare;

    /* filtered loop rate below 95% of the loop rate: the loop is saturated */
    if ((uint64_t)s->filtered_loop_q8 > (((uint64_t)s->period_us * 256u * 100u) / 95u)) {
        return 1000u;
    }
    if (s->spare_ticks == 0u) {
        return 0u;
    }
    mean_spare = s->spare_us / s->spare_ticks;
    if (mean_spare >= s->period_us) {
        return 0u; /* S-8: more spare time than the period means idle, not 100% */
    }
    return (uint32_t)(((s->period_us - mean_spare) * 1000u) / s->period_us);
}

void mt_sched_task_report(const mt_sched_t *s, uint32_t i, mt_task_report_t *r)
{
    r->name = s->tasks[i].name;
    r->runs = s->st[i].runs;
    r->min_us = s->st[i].min_us;
    r->max_us = s->st[i].max_us;
    r->mean_us = (s->st[i].runs == 0u) ? 0u : mt_clamp_u32(s->st[i].total_us / s->st[i].runs);
    r->overruns = s->st[i].overruns;
    r->slips = s->st[i].slips;
    r->not_achieved = s->st[i].not_achieved;
    r->budget_skips = s->st[i].budget_skips;
    r->pending = (s->tick - s->st[i].last_run) / s->st[i].interval;
    r->interval = s->st[i].interval;
}

void mt_sched_loop_report(const mt_sched_t *s, mt_loop_report_t *r)
{
    /* first, while *r is untouched: the load needs the invariant of *s */
    uint32_t load = mt_sched_load_permille(s);

    r->ticks = s->tick;
    r->loops = s->loops;
    r->min_us = s->loop_min_us;
    r->max_us = s->loop_max_us;
    r->mean_us = (s->loops == 0u) ? 0u : mt_clamp_u32(s->loop_total_us / s->loops);
    r->long_loops = s->long_loops;
    r->extra_us = s->extra_us;
    r->filtered_us = s->filtered_loop_q8 / 256u;
    r->load_permille = load;
}

/* Zero the statistics of task i (not its due state). */
/*@ requires valid: \valid(s);
    requires index: i < MT_CFG_SCHED_MAX_TASKS;
    requires sep: s->ntasks <= MT_CFG_SCHED_MAX_TASKS && \separated(s, s->tasks + (0 .. s->ntasks - 1));
    assigns s->st[i].runs, s->st[i].min_us, s->st[i].max_us, s->st[i].total_us, s->st[i].overruns, s->st[i].slips, s->st[i].not_achieved, s->st[i].budget_skips;
    ensures zero: s->st[i].runs == 0 && s->st[i].min_us == 0 && s->st[i].max_us == 0 && s->st[i].total_us == 0 && s->st[i].overruns == 0 && s->st[i].slips == 0 && s->st[i].not_achieved == 0 && s->st[i].budget_skips == 0;
    ensures kept: MtSchedKept{Pre, Post}(s);
    ensures due: s->st[i].interval == \old(s->st[i].interval) && s->st[i].last_run == \old(s->st[i].last_run);
    ensures others: \forall integer j; 0 <= j < MT_CFG_SCHED_MAX_TASKS ==> j != i ==>
        s->st[j].runs == \old(s->st[j].runs) &&
        s->st[j].min_us == \old(s->st[j].min_us) &&
        s->st[j].max_us == \old(s->st[j].max_us) &&
        s->st[j].total_us == \old(s->st[j].total_us) &&
        s->st[j].overruns == \old(s->st[j].overruns) &&
        s->st[j].slips == \old(s->st[j].slips) &&
        s->st[j].not_achieved == \old(s->st[j].not_achieved) &&
        s->st[j].budget_skips == \old(s->st[j].budget_skips) &&
        s->st[j].interval == \old(s->st[j].interval) &&
        s->st[j].last_run == \old(s->st[j].last_run);
*/
static void stats_zero(mt_sched_t *s, uint32_t i)
{
    s->st[i].runs = 0u;
    s->st[i].min_us = 0u;
    s->st[i].max_us = 0u;
    s->st[i].total_us = 0u;
    s->st[i].overruns = 0u;
    s->st[i].slips = 0u;
    s->st[i].not_achieved = 0u;
    s->st[i].budget_skips = 0u;
}

/* Zero the loop statistics. A function of its own so that the frame fact `kept` is proved
 * over these five stores alone; the caller joins it to its loop's with MtSchedKept_trans. */
/*@ requires valid: \valid(s);
    requires sep: s->ntasks <= MT_CFG_SCHED_MAX_TASKS && \separated(s, s->tasks + (0 .. s->ntasks - 1));
    assigns s->loops, s->loop_total_us, s->loop_min_us, s->loop_max_us, s->long_loops;
    ensures zero: s->loops == 0 && s->loop_total_us == 0 && s->loop_min_us == 0 &&
        s->loop_max_us == 0 && s->long_loops == 0;
    ensures kept: MtSchedKept{Pre, Post}(s);
*/
static void loop_zero(mt_sched_t *s)
{
    s->loops = 0u;
    s->loop_total_us = 0u;
    s->loop_min_us = 0u;
    s->loop_max_us = 0u;
    s->long_loops = 0u;
}

void mt_sched_reset_stats(mt_sched_t *s)
{
    uint32_t i;

    /*@ loop invariant 0 <= i <= MT_CFG_SCHED_MAX_TASKS;
        loop invariant kept: MtSchedKept{Pre, Here}(s);
        loop invariant zeroed: \forall integer j; 0 <= j < i ==>
            s->st[j].runs == 0 && s->st[j].min_us == 0 && s->st[j].max_us == 0 && s->st[j].total_us == 0 &&
            s->st[j].overruns == 0 && s->st[j].slips == 0 && s->st[j].not_achieved == 0 &&
            s->st[j].budget_skips == 0;
        loop invariant due_kept: \forall integer j; 0 <= j < MT_CFG_SCHED_MAX_TASKS ==>
            s->st[j].interval == \at(s->st[j].interval, Pre) && s->st[j].last_run == \at(s->st[j].last_run, Pre);
        loop assigns i, s->st[0 .. MT_CFG_SCHED_MAX_TASKS - 1];
        loop variant MT_CFG_SCHED_MAX_TASKS - i;
    */
    for (i = 0u; i < MT_CFG_SCHED_MAX_TASKS; i++) {
        stats_zero(s, i);
    }
    loop_zero(s);
    //@ assert kept: MtSchedKept{Pre, Here}(s);
    //@ ghost sched_inv_intro(s);
}
