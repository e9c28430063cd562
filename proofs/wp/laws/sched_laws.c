/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file sched_laws.c
 * @brief Laws of the tick scheduler (ardupilot.md §4.1), proved from the public contracts of
 *        mt/sched.h.
 */
#include "mt/sched.h"

/* Budget rule: a due normal task whose budget exceeds the time available stays due. */
/*@ requires inv: MtSchedInv(s);
    requires index: i < s->ntasks;
    requires normal: !MtTaskFast(s->tasks + i);
    requires due: s->tick - s->st[i].last_run >= s->st[i].interval;
    requires too_big: s->tasks[i].budget_us > time_available_us;
    assigns s->st[0 .. MT_CFG_SCHED_MAX_TASKS - 1], s->current, s->late_in_loop, s->run_tick,
            s->task_start_us, s->task_allowed_us, MtPortNow, MtPortWakes,
            MtCalls[MT_CALL_TASK(0) .. MT_CALL_TASK(MT_CFG_SCHED_MAX_TASKS - 1)];
    ensures stays_due: s->tick - s->st[i].last_run >= s->st[i].interval;
    ensures not_run: s->st[i].runs == \old(s->st[i].runs);
*/
void law_sched_budget_keeps_due(mt_sched_t *s, uint32_t i, uint32_t time_available_us)
{
    (void)mt_sched_run(s, time_available_us);
}

/* Once per tick: two runs in the same tick run each task at most once. */
/*@ requires inv: MtSchedInv(s);
    assigns s->st[0 .. MT_CFG_SCHED_MAX_TASKS - 1], s->current, s->late_in_loop, s->run_tick,
            s->task_start_us, s->task_allowed_us, MtPortNow, MtPortWakes,
            MtCalls[MT_CALL_TASK(0) .. MT_CALL_TASK(MT_CFG_SCHED_MAX_TASKS - 1)];
    ensures once_per_tick: \forall integer i; 0 <= i < s->ntasks ==>
        s->st[i].runs == \old(s->st[i].runs) || s->st[i].runs == \old(s->st[i].runs) + 1;
*/
void law_sched_twice_same_tick(mt_sched_t *s, uint32_t t1, uint32_t t2)
{
    (void)mt_sched_run(s, t1);
    (void)mt_sched_run(s, t2);
}

/* Fast tasks every tick: after a tick, a run runs every fast task exactly once, whatever the
 * time available. */
/*@ requires inv: MtSchedInv(s);
    requires room: s->tick < 0xFFFFFFFFFFFFFFFE;
    assigns s->tick, s->st[0 .. MT_CFG_SCHED_MAX_TASKS - 1], s->current, s->late_in_loop,
            s->run_tick, s->task_start_us, s->task_allowed_us, MtPortNow, MtPortWakes,
            MtCalls[MT_CALL_TASK(0) .. MT_CALL_TASK(MT_CFG_SCHED_MAX_TASKS - 1)];
    ensures fast_every_tick: \forall integer i; 0 <= i < s->ntasks ==> MtTaskFast(s->tasks + i) ==>
        s->st[i].runs == \old(s->st[i].runs) + 1;
*/
void law_sched_fast_every_tick(mt_sched_t *s, uint32_t time_available_us)
{
    mt_sched_tick(s);
    (void)mt_sched_run(s, time_available_us);
}
