/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/sched.h
 * @brief Cooperative tick scheduler with AP_Scheduler semantics, its known
 *        defects removed.
 *
 * Operating rules
 * - One main-loop thread owns the scheduler: every function here is called
 *   from that thread only (reports may be read elsewhere as racy snapshots).
 * - Each tick: wait for the sensor sample (the "metronome"), count the tick,
 *   then one mt_sched_run() with the time left in the period plus the adaptive
 *   extra time. Tasks run to completion; a budget is advisory.
 * - Fast tasks (priority < MT_SCHED_FAST_PRIO_LIMIT, rate 0) run every tick,
 *   whatever the budget left; their time counts against it.
 * - A normal task is due when tick - last_run >= interval, with
 *   interval = max(1, floor(loop_rate / rate)) computed once at init from the
 *   latched loop rate. A due task whose budget does not fit the time left is
 *   skipped and stays due; the scan goes on to later, cheaper tasks.
 * - Ticks are 64-bit and never wrap; last_run is the tick of the actual run
 *   (no catch-up bursts).
 * - Releases of a task happen every interval ticks after its last run; when a
 *   task runs, the releases it did not serve are counted as slips:
 *   slips += floor(dt / interval) - 1. Every release is therefore a run, a
 *   counted slip, or still pending (floor((tick - last_run) / interval)).
 * - A task that runs 4 or more intervals late is "not achieved": counted, and
 *   the next loops get 100 us more (up to 5000 us); after more than 50 clean
 *   loops the extra time shrinks by 50 us.
 *
 * Reference defects fixed (ardupilot.md §3.1): S-1 slips and overruns are
 * separate counters; S-2 the fast class is priority < 3 exactly; S-3 the loop
 * rate is latched at init and used for every interval; S-4 64-bit ticks and
 * 32-bit intervals; S-5 a normal task with budget 0 is rejected at init; S-6
 * state is a fixed array zeroed at init (no allocation); S-7 statistics are
 * 32/64-bit, saturating, and means are guarded against zero runs; S-8 load is
 * 0 when the average spare time exceeds the period; S-9 the time left shrinks
 * by the wall time since the scan began, so gaps between tasks and pre-emption
 * by other threads are charged too, not only the tasks' own run times.
 */
#ifndef MT_SCHED_H
#define MT_SCHED_H

#include <stdint.h>

#include "mt/config.h"
#include "mt/status.h"
#include "mt_port.h"
#include "mt_spec.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Rates are given in millihertz: MT_HZ(50) is 50 Hz, 100 is 0.1 Hz. */
#define MT_HZ(hz) ((uint32_t)(hz) * 1000u)

#define MT_SCHED_RATE_MIN 50u          /**< lowest loop rate, Hz */
#define MT_SCHED_RATE_MAX 2000u        /**< highest loop rate, Hz */
#define MT_SCHED_FAST_PRIO_LIMIT 3u    /**< priorities below this are fast tasks */
#define MT_SCHED_SLOWDOWN 4u           /**< "not achieved" when dt >= 4 intervals */
#define MT_SCHED_EXTRA_STEP_US 100u    /**< extra time added per late loop */
#define MT_SCHED_EXTRA_DECAY_US 50u    /**< extra time removed after clean loops */
#define MT_SCHED_EXTRA_MAX_US 5000u    /**< cap of the extra time */
#define MT_SCHED_CLEAN_LOOPS 50u       /**< clean loops before the extra time shrinks */
#define MT_SCHED_SPARE_WINDOW 32u      /**< spare-time window, halved when full */

/** Breadcrumb values of mt_sched_t.current besides a task index. */
#define MT_SCHED_IDLE (-1)
#define MT_SCHED_WAIT_SAMPLE (-3)

/** Task body. */
typedef void (*mt_task_fn_t)(void *arg);

/** Sample wait: blocks until the next sensor sample and returns its time (us). */
typedef uint64_t (*mt_sample_wait_fn_t)(void *ctx);

/** One entry of a task table (usually a const array in flash). */
typedef struct {
    const char *name;      /**< for reports */
    mt_task_fn_t fn;       /**< body */
    void *arg;             /**< body argument */
    uint32_t rate_mhz;     /**< rate in millihertz; 0 for fast tasks */
    uint32_t budget_us;    /**< time allowance per run; > 0 for normal tasks */
    uint8_t priority;      /**< non-decreasing along the table; < 3 = fast */
} mt_task_t;

/** Per-task run-time state and statistics. */
typedef struct {
    uint64_t last_run;     /**< tick of the last run (0 before the first) */
    uint32_t interval;     /**< ticks between releases, >= 1 (1 for fast tasks) */
    uint32_t min_us;       /**< shortest run (0 before the first run) */
    uint32_t max_us;       /**< longest run */
    uint32_t overruns;     /**< runs longer than the allowance (saturating) */
    uint64_t runs;         /**< completed runs */
    uint64_t total_us;     /**< sum of run times (saturating) */
    uint64_t slips;        /**< releases not served (see file comment) */
    uint64_t not_achieved; /**< runs >= 4 intervals late */
    uint64_t budget_skips; /**< due but skipped because the budget did not fit */
} mt_task_state_t;

typedef struct {
    const mt_task_t *tasks;          /**< the validated table */
    uint32_t ntasks;                 /**< entries in the table */
    uint32_t loop_rate_hz;           /**< latched at init */
    uint32_t period_us;              /**< 1e6 / loop_rate_hz */
    int32_t current;                 /**< breadcrumb: task index, IDLE or WAIT_SAMPLE */
    uint64_t tick;                   /**< ticks since init (never wraps) */
    uint64_t run_tick;               /**< tick of the last mt_sched_run() (0: none) */
    mt_task_state_t st[MT_CFG_SCHED_MAX_TASKS];
    /* adaptive extra time */
    uint32_t extra_us;               /**< extra time added to each loop, <= 5000 */
    uint32_t clean_loops;            /**< loops since the last late task */
    uint32_t late_in_loop;           /**< tasks not achieved in the current loop */
    /* load */
    uint64_t spare_us;               /**< spare time in the window */
    uint32_t spare_ticks;            /**< loops in the window, < 32 */
    uint32_t filtered_loop_q8;       /**< filtered loop time, us * 256 */
    /* loop statistics */
    uint64_t loops;                  /**< loops measured */
    uint64_t loop_total_us;          /**< sum of loop times (saturating) */
    uint32_t loop_min_us;            /**< shortest loop (0 before the second sample) */
    uint32_t loop_max_us;            /**< longest loop */
    uint32_t long_loops;             /**< loops longer than 1.2 periods (saturating) */
    uint64_t last_sample_us;         /**< time of the previous sample (0: none yet) */
    /* current run */
    uint64_t task_start_us;          /**< start of the running task */
    uint32_t task_allowed_us;        /**< its allowance */
} mt_sched_t;

/** Report of one task (derived values computed without division by zero). */
typedef struct {
    const char *name;
    uint64_t runs;
    uint32_t min_us;
    uint32_t max_us;
    uint32_t mean_us;        /**< 0 when runs == 0 */
    uint32_t overruns;
    uint64_t slips;
    uint64_t not_achieved;
    uint64_t budget_skips;
    uint64_t pending;        /**< releases since the last run not yet served */
    uint32_t interval;
} mt_task_report_t;

/** Loop report. */
typedef struct {
    uint64_t ticks;
    uint64_t loops;
    uint32_t min_us;
    uint32_t max_us;
    uint32_t mean_us;        /**< 0 when loops == 0 */
    uint32_t long_loops;
    uint32_t extra_us;
    uint32_t filtered_us;
    uint32_t load_permille;
} mt_loop_report_t;

/*@ predicate MtTaskFast(mt_task_t *t) = t->priority < MT_SCHED_FAST_PRIO_LIMIT;

    predicate MtTaskOk(mt_task_t *t, integer rate_hz) =
        t->fn != \null && t->budget_us <= 1000000 / rate_hz &&
        (MtTaskFast(t) ? t->rate_mhz == 0
                       : (t->rate_mhz >= 1 && t->rate_mhz <= rate_hz * 1000 && t->budget_us >= 1));

    predicate MtTableOk(mt_task_t *tasks, integer n, integer rate_hz) =
        1 <= n <= MT_CFG_SCHED_MAX_TASKS &&
        MT_SCHED_RATE_MIN <= rate_hz <= MT_SCHED_RATE_MAX &&
        \valid_read(tasks + (0 .. n - 1)) &&
        (\forall integer i; 0 <= i < n ==> MtTaskOk(tasks + i, rate_hz)) &&
        (\forall integer i; 0 <= i < n - 1 ==> tasks[i].priority <= tasks[i + 1].priority);

    logic integer MtInterval(mt_task_t *t, integer rate_hz) =
        t->priority < MT_SCHED_FAST_PRIO_LIMIT ? 1 : (rate_hz * 1000) / t->rate_mhz;
*/

/* The status of entry i of a table: the first rule it breaks, in the order fn, rate, budget,
 * order; MT_OK when it breaks none (MtTaskOk and not below the previous entry's priority). */
/*@ logic integer MtEntryStatus(mt_task_t *tasks, integer i, integer rate_hz) =
        tasks[i].fn == \null ? MT_E_TASK_FN :
        (tasks[i].priority < MT_SCHED_FAST_PRIO_LIMIT ? tasks[i].rate_mhz != 0
            : tasks[i].rate_mhz < 1 || tasks[i].rate_mhz > rate_hz * 1000) ? MT_E_TASK_RATE :
        (tasks[i].budget_us > 1000000 / rate_hz ||
         (tasks[i].priority >= MT_SCHED_FAST_PRIO_LIMIT && tasks[i].budget_us < 1)) ?
            MT_E_TASK_BUDGET :
        (i > 0 && tasks[i - 1].priority > tasks[i].priority) ? MT_E_TASK_ORDER : MT_OK;

    predicate MtRateOk(integer rate_hz) = MT_SCHED_RATE_MIN <= rate_hz <= MT_SCHED_RATE_MAX;
*/

/* What a rejected table is reported as (status r, index bad): a loop-rate problem, then a
 * count problem, names n; an entry problem names the first faulty entry, with its status. */
/*@ predicate MtTableRejected(mt_task_t *tasks, integer n, integer rate_hz, integer r,
                               integer bad) =
        (!MtRateOk(rate_hz) ==> r == MT_E_LOOP_RATE && bad == n) &&
        (MtRateOk(rate_hz) && (n < 1 || n > MT_CFG_SCHED_MAX_TASKS) ==>
            r == MT_E_TASK_COUNT && bad == n) &&
        (MtRateOk(rate_hz) && 1 <= n <= MT_CFG_SCHED_MAX_TASKS ==>
            0 <= bad < n && r == MtEntryStatus(tasks, bad, rate_hz) &&
            \forall integer j; 0 <= j < bad ==> MtEntryStatus(tasks, j, rate_hz) == MT_OK);
*/

/* The fields of tasks[0 .. n - 1] that the predicates above read are the same at L1 and L2. */
/*@ predicate MtTableKept{L1, L2}(mt_task_t *t, integer n) =
        \forall integer i; 0 <= i < n ==>
            \at(t[i].fn, L1) == \at(t[i].fn, L2) && \at(t[i].rate_mhz, L1) == \at(t[i].rate_mhz, L2) &&
            \at(t[i].budget_us, L1) == \at(t[i].budget_us, L2) && \at(t[i].priority, L1) == \at(t[i].priority, L2);
*/

/* Frame lemmas (proved by WP): a kept table stays valid and keeps its intervals. */
/*@ lemma MtTableOk_kept{L1, L2}: \forall mt_task_t *t, integer n, r;
        MtTableOk{L1}(t, n, r) ==> MtTableKept{L1, L2}(t, n) ==> \valid_read{L2}(t + (0 .. n - 1)) ==>
        MtTableOk{L2}(t, n, r);
    lemma MtInterval_kept{L1, L2}: \forall mt_task_t *t, integer n, r, i;
        MtTableKept{L1, L2}(t, n) ==> 0 <= i < n ==> MtInterval{L1}(t + i, r) == MtInterval{L2}(t + i, r);
*/

/* The table part of the invariant: the only part with divisions. */
/*@ predicate MtSchedCore(mt_sched_t *s) =
        \valid(s) && MtTableOk(s->tasks, s->ntasks, s->loop_rate_hz) &&
        \separated(s, s->tasks + (0 .. s->ntasks - 1)) &&
        s->period_us == 1000000 / s->loop_rate_hz &&
        (\forall integer i; 0 <= i < s->ntasks ==>
            s->st[i].interval == MtInterval(s->tasks + i, s->loop_rate_hz) && s->st[i].interval >= 1);

    predicate MtSchedInv(mt_sched_t *s) =
        MtSchedCore(s) &&
        s->extra_us <= MT_SCHED_EXTRA_MAX_US && s->spare_ticks < MT_SCHED_SPARE_WINDOW &&
        s->spare_us <= (integer)MT_SCHED_SPARE_WINDOW * 2 * 0xFFFFFFFF &&
        s->spare_us <= ((integer)s->spare_ticks + MT_SCHED_SPARE_WINDOW) * 0xFFFFFFFF &&
        s->clean_loops <= MT_SCHED_CLEAN_LOOPS &&
        s->tick < 0xFFFFFFFFFFFFFFFF && s->run_tick <= s->tick &&
        (\forall integer i; 0 <= i < s->ntasks ==>
            s->st[i].last_run <= s->run_tick && s->st[i].runs <= s->run_tick);
*/

/* Every location MtSchedCore reads is the same at L1 and L2 (a linear frame fact; the
 * lemma below then carries the core across, so no frame goal has to see the divisions). */
/*@ predicate MtSchedKept{L1, L2}(mt_sched_t *s) =
        \at(s->tasks, L1) == \at(s->tasks, L2) && \at(s->ntasks, L1) == \at(s->ntasks, L2) &&
        \at(s->loop_rate_hz, L1) == \at(s->loop_rate_hz, L2) &&
        \at(s->period_us, L1) == \at(s->period_us, L2) &&
        MtTableKept{L1, L2}(\at(s->tasks, L1), \at(s->ntasks, L1)) &&
        (\forall integer i; 0 <= i < \at(s->ntasks, L1) ==>
            \at(s->st[i].interval, L1) == \at(s->st[i].interval, L2));

    lemma MtSchedKept_trans{L1, L2, L3}: \forall mt_sched_t *s;
        MtSchedKept{L1, L2}(s) ==> MtSchedKept{L2, L3}(s) ==> MtSchedKept{L1, L3}(s);

    lemma MtSchedCore_kept{L1, L2}: \forall mt_sched_t *s;
        MtSchedCore{L1}(s) ==> MtSchedKept{L1, L2}(s) ==> \valid{L2}(s) ==>
        \valid_read{L2}(\at(s->tasks, L1) + (0 .. \at(s->ntasks, L1) - 1)) ==> MtSchedCore{L2}(s);
*/

/* What one mt_sched_run() did to task i, from L1 (before) to L2 (after).
 * - Due: a release is waiting (tick - last_run >= interval).
 * - Ran: one more run stamped with the tick, its body called once (the ghost MtCalls,
 *   mt_invoke.h), no skip counted. A fast task's run counts no slip and no lateness; a normal
 *   task's run counts the releases it did not serve as slips, and lateness when it is
 *   MT_SCHED_SLOWDOWN or more intervals late (MtTaskServed, MtLateAfter). The slips are stated
 *   exactly up to three intervals late and as at least two beyond (MtSlipsCounted): the exact
 *   count, floor(dt / interval) - 1, is the contract of the static note_release (WP), and a
 *   quotient in the scan's loop invariant is more than WP's provers decide (measured).
 * - Skipped: due but its budget did not fit: one more budget skip, still due, body not called.
 * - Untouched: none of its accounting moved and its body was not called. */
/*@ predicate MtTaskDue(mt_sched_t *s, integer i) = s->tick - s->st[i].last_run >= s->st[i].interval;

    logic integer MtSatAdd64(integer x, integer d) =
        x + d <= 0xFFFFFFFFFFFFFFFF ? x + d : 0xFFFFFFFFFFFFFFFF;

    predicate MtSlipsCounted(integer now, integer before, integer dt, integer iv) =
        (dt < 2 * iv ==> now == before) &&
        (2 * iv <= dt < 3 * iv ==> now == MtSatAdd64(before, 1)) &&
        (3 * iv <= dt ==> now >= MtSatAdd64(before, 2));

    logic integer MtLateAfter(integer late, integer dt, integer iv) =
        dt >= MT_SCHED_SLOWDOWN * iv ? MtSatAdd64(late, 1) : late;

    predicate MtTaskCalled{L1, L2}(integer i, integer n) =
        \at(MtCalls[MT_CALL_TASK(i)], L2) == MtCount64(\at(MtCalls[MT_CALL_TASK(i)], L1), n);

    predicate MtTaskRan{L1, L2}(mt_sched_t *s, integer i) =
        \at(s->st[i].runs, L2) == \at(s->st[i].runs, L1) + 1 &&
        \at(s->st[i].last_run, L2) == \at(s->tick, L2) &&
        \at(s->st[i].budget_skips, L2) == \at(s->st[i].budget_skips, L1) && MtTaskCalled{L1, L2}(i, 1);

    predicate MtTaskRanFast{L1, L2}(mt_sched_t *s, integer i) =
        MtTaskRan{L1, L2}(s, i) && \at(s->st[i].slips, L2) == \at(s->st[i].slips, L1) &&
        \at(s->st[i].not_achieved, L2) == \at(s->st[i].not_achieved, L1);

    predicate MtTaskServed{L1, L2}(mt_sched_t *s, integer i) =
        MtTaskRan{L1, L2}(s, i) &&
        MtSlipsCounted(\at(s->st[i].slips, L2), \at(s->st[i].slips, L1),
            \at(s->tick - s->st[i].last_run, L1), \at(s->st[i].interval, L1)) &&
        \at(s->st[i].not_achieved, L2) == MtLateAfter(\at(s->st[i].not_achieved, L1),
            \at(s->tick - s->st[i].last_run, L1), \at(s->st[i].interval, L1));

    predicate MtTaskSkipped{L1, L2}(mt_sched_t *s, integer i) =
        \at(s->st[i].runs, L2) == \at(s->st[i].runs, L1) &&
        \at(s->st[i].last_run, L2) == \at(s->st[i].last_run, L1) &&
        \at(s->st[i].slips, L2) == \at(s->st[i].slips, L1) &&
        \at(s->st[i].not_achieved, L2) == \at(s->st[i].not_achieved, L1) &&
        \at(s->st[i].budget_skips, L2) == MtSatAdd64(\at(s->st[i].budget_skips, L1), 1) &&
        \at(MtCalls[MT_CALL_TASK(i)], L2) == \at(MtCalls[MT_CALL_TASK(i)], L1);

    predicate MtTaskUntouched{L1, L2}(mt_sched_t *s, integer i) =
        \at(s->st[i].interval, L2) == \at(s->st[i].interval, L1) &&
        \at(s->st[i].runs, L2) == \at(s->st[i].runs, L1) &&
        \at(s->st[i].last_run, L2) == \at(s->st[i].last_run, L1) &&
        \at(s->st[i].slips, L2) == \at(s->st[i].slips, L1) &&
        \at(s->st[i].not_achieved, L2) == \at(s->st[i].not_achieved, L1) &&
        \at(s->st[i].budget_skips, L2) == \at(s->st[i].budget_skips, L1) &&
        \at(MtCalls[MT_CALL_TASK(i)], L2) == \at(MtCalls[MT_CALL_TASK(i)], L1);
*/

/** Check entry i of a table (the first problem found for that entry).
 *  @retval MT_OK, MT_E_TASK_FN, MT_E_TASK_RATE, MT_E_TASK_BUDGET, MT_E_TASK_ORDER
 *          (priority below the previous entry's). */
/*@ requires table: n >= 1 && \valid_read(tasks + (0 .. n - 1));
    requires index: i < n;
    requires rate: MT_SCHED_RATE_MIN <= loop_rate_hz <= MT_SCHED_RATE_MAX;
    assigns \nothing;
    ensures ok: \result == MT_OK <==>
        (MtTaskOk(tasks + i, loop_rate_hz) && (i == 0 || tasks[i - 1].priority <= tasks[i].priority));
    ensures fn: tasks[i].fn == \null ==> \result == MT_E_TASK_FN;
    ensures status: \result == MT_OK || \result == MT_E_TASK_FN || \result == MT_E_TASK_RATE ||
                    \result == MT_E_TASK_BUDGET || \result == MT_E_TASK_ORDER;
    ensures exact: \result == MtEntryStatus(tasks, i, loop_rate_hz);
*/
mt_status_t mt_sched_check_entry(const mt_task_t *tasks, uint32_t n, uint32_t i,
                                 uint32_t loop_rate_hz);

/** Validate a whole table; on a problem *bad_index names the first faulty
 *  entry (n for a count or loop-rate problem).
 *  @retval MT_OK, MT_E_LOOP_RATE, MT_E_TASK_COUNT, or a status of
 *          mt_sched_check_entry(). */
/*@ requires idx: \valid(bad_index);
    requires table: n >= 1 ==> n <= MT_CFG_SCHED_MAX_TASKS ==> \valid_read(tasks + (0 .. n - 1));
    requires sep: \separated(bad_index, tasks + (0 .. n - 1));
    assigns *bad_index;
    ensures ok: \result == MT_OK <==> \old(MtTableOk(tasks, n, loop_rate_hz));
    ensures where: \result != MT_OK ==> *bad_index <= n;
    ensures rate: (loop_rate_hz < MT_SCHED_RATE_MIN || loop_rate_hz > MT_SCHED_RATE_MAX) ==>
                  \result == MT_E_LOOP_RATE;
    ensures count: MT_SCHED_RATE_MIN <= loop_rate_hz <= MT_SCHED_RATE_MAX ==>
                   (n < 1 || n > MT_CFG_SCHED_MAX_TASKS) ==> \result == MT_E_TASK_COUNT;
    ensures first: \result != MT_OK ==>
        MtTableRejected(tasks, n, loop_rate_hz, \result, *bad_index);
    ensures kept: \result == MT_OK ==> *bad_index == \old(*bad_index);
*/
mt_status_t mt_sched_validate(const mt_task_t *tasks, uint32_t n, uint32_t loop_rate_hz,
                              uint32_t *bad_index);

/** Validate, then set up the scheduler (seL4 style: a rejected table leaves
 *  *s untouched). Statuses as mt_sched_validate(). */
/*@ requires valid: \valid(s) && \valid(bad_index);
    requires table: n >= 1 ==> n <= MT_CFG_SCHED_MAX_TASKS ==> \valid_read(tasks + (0 .. n - 1));
    requires sep: \separated(s, bad_index, tasks + (0 .. n - 1));
    assigns *s, *bad_index;
    behavior ok:
      assumes MtTableOk(tasks, n, loop_rate_hz);
      ensures status: \result == MT_OK;
      ensures inv: MtSchedInv(s);
      ensures fresh: s->tick == 0 && s->run_tick == 0 && s->current == MT_SCHED_IDLE && s->extra_us == 0 &&
                     s->tasks == tasks && s->ntasks == n && s->loop_rate_hz == loop_rate_hz;
      ensures zeroed: \forall integer i; 0 <= i < n ==> s->st[i].runs == 0 && s->st[i].last_run == 0 &&
                      s->st[i].slips == 0 && s->st[i].overruns == 0;
      ensures index_kept: *bad_index == \old(*bad_index);
    behavior rejected:
      assumes !MtTableOk(tasks, n, loop_rate_hz);
      ensures status: \result != MT_OK;
      ensures reported: MtTableRejected(tasks, n, loop_rate_hz, \result, *bad_index);
      ensures untouched: *s == \old(*s);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_sched_init(mt_sched_t *s, const mt_task_t *tasks, uint32_t n,
                          uint32_t loop_rate_hz, uint32_t *bad_index);

/** Count one tick. */
/*@ requires inv: MtSchedInv(s);
    requires room: s->tick < 0xFFFFFFFFFFFFFFFE;
    assigns s->tick;
    ensures inv: MtSchedInv(s);
    ensures counted: s->tick == \old(s->tick) + 1;
*/
void mt_sched_tick(mt_sched_t *s);

/** Run the due tasks of the current tick within time_available_us; returns
 *  the time left (0 when exhausted). A second call in the same tick runs
 *  nothing, so no task runs twice in one tick. */
/*@ requires inv: MtSchedInv(s);
    assigns s->st[0 .. MT_CFG_SCHED_MAX_TASKS - 1], s->current, s->late_in_loop, s->run_tick,
            s->task_start_us, s->task_allowed_us, MtPortNow, MtPortWakes,
            MtCalls[MT_CALL_TASK(0) .. MT_CALL_TASK(MT_CFG_SCHED_MAX_TASKS - 1)];
    ensures inv: MtSchedInv(s);
    ensures idle: \old(s->current) == MT_SCHED_IDLE ==> s->current == MT_SCHED_IDLE;
    ensures crumb: s->current == \old(s->current) || s->current == MT_SCHED_IDLE;
    ensures left: \result <= time_available_us;
    ensures run_tick: s->run_tick == s->tick;
    ensures intervals_kept: \forall integer i; 0 <= i < s->ntasks ==>
        s->st[i].interval == \old(s->st[i].interval);
    ensures once_per_tick: \forall integer i; 0 <= i < s->ntasks ==>
        s->st[i].runs == \old(s->st[i].runs) || s->st[i].runs == \old(s->st[i].runs) + 1;
    ensures same_tick_untouched: \old(s->run_tick) == s->tick ==> \result == time_available_us &&
        \forall integer i; 0 <= i < MT_CFG_SCHED_MAX_TASKS ==> MtTaskUntouched{Pre, Post}(s, i);
    ensures fast_ran: \old(s->run_tick) != s->tick ==> \forall integer i; 0 <= i < s->ntasks ==>
        \old(MtTaskFast(s->tasks + i)) ==> MtTaskRanFast{Pre, Post}(s, i);
    ensures not_due_untouched: \forall integer i; 0 <= i < s->ntasks ==> !\old(MtTaskFast(s->tasks + i)) ==>
        !\old(MtTaskDue(s, i)) ==> MtTaskUntouched{Pre, Post}(s, i);
    ensures due_served_or_skipped: \old(s->run_tick) != s->tick ==> \forall integer i; 0 <= i < s->ntasks ==>
        !\old(MtTaskFast(s->tasks + i)) ==> \old(MtTaskDue(s, i)) ==>
        (MtTaskServed{Pre, Post}(s, i) && \old(s->tasks[i].budget_us) <= time_available_us) ||
        (MtTaskSkipped{Pre, Post}(s, i) && \old(s->tasks[i].budget_us) > \result);
    ensures none_ran_all_left: (\forall integer i; 0 <= i < s->ntasks ==> s->st[i].runs == \old(s->st[i].runs)) ==>
        \result == time_available_us;
    ensures unused_untouched: \forall integer i; s->ntasks <= i < MT_CFG_SCHED_MAX_TASKS ==>
        MtTaskUntouched{Pre, Post}(s, i);
*/
uint32_t mt_sched_run(mt_sched_t *s, uint32_t time_available_us);

/** Bookkeeping after a run: spare-time window and adaptive extra time. */
/*@ requires inv: MtSchedInv(s);
    assigns s->spare_us, s->spare_ticks, s->extra_us, s->clean_loops, s->late_in_loop;
    ensures inv: MtSchedInv(s);
    ensures extra_bounded: s->extra_us <= MT_SCHED_EXTRA_MAX_US;
    ensures extra_up: \old(s->late_in_loop) > 0 ==>
        s->extra_us == (\old(s->extra_us) + MT_SCHED_EXTRA_STEP_US <= MT_SCHED_EXTRA_MAX_US ?
                        \old(s->extra_us) + MT_SCHED_EXTRA_STEP_US : MT_SCHED_EXTRA_MAX_US);
    ensures extra_steps: s->extra_us == \old(s->extra_us) || s->extra_us > \old(s->extra_us) ||
                         \old(s->extra_us) - s->extra_us <= MT_SCHED_EXTRA_DECAY_US;
    ensures reset: s->late_in_loop == 0;
*/
void mt_sched_end_loop(mt_sched_t *s, uint32_t spare_us);

/** Record a sample time for the loop statistics. */
/*@ requires inv: MtSchedInv(s);
    assigns s->loops, s->loop_total_us, s->loop_min_us, s->loop_max_us, s->long_loops,
            s->last_sample_us, s->filtered_loop_q8;
    ensures inv: MtSchedInv(s);
    ensures last: s->last_sample_us == sample_us;
*/
void mt_sched_note_sample(mt_sched_t *s, uint64_t sample_us);

/** One main-loop iteration: breadcrumb WAIT_SAMPLE, wait(ctx) for the sample,
 *  tick, run with max(0, period - (now - sample)) + extra, then end_loop. */
/*@ requires inv: MtSchedInv(s);
    requires room: s->tick < 0xFFFFFFFFFFFFFFFE;
    requires callable: wait != \null;
    assigns s->st[0 .. MT_CFG_SCHED_MAX_TASKS - 1], s->current, s->late_in_loop, s->tick,
            s->run_tick, s->task_start_us, s->task_allowed_us, s->spare_us, s->spare_ticks, s->extra_us,
            s->clean_loops, s->loops, s->loop_total_us, s->loop_min_us, s->loop_max_us,
            s->long_loops, s->last_sample_us, s->filtered_loop_q8, MtPortNow, MtPortWakes,
            MtCalls[MT_CALL_TASK(0) .. MT_CALL_TASK(MT_CFG_SCHED_MAX_TASKS - 1)], MtCalls[MT_CALL_WAIT];
    ensures inv: MtSchedInv(s);
    ensures ticked: s->tick == \old(s->tick) + 1;
    ensures idle: s->current == MT_SCHED_IDLE;
    ensures waited: MtCalls[MT_CALL_WAIT] == MtCount64(\old(MtCalls[MT_CALL_WAIT]), 1);
*/
void mt_sched_loop_once(mt_sched_t *s, mt_sample_wait_fn_t wait, void *ctx);

/** Time left in the running task's allowance (0 when over or idle), at the clock
 *  reading it takes (MtPortNow after the call). */
/*@ requires inv: MtSchedInv(s);
    assigns MtPortNow;
    ensures bounded: \result <= s->task_allowed_us;
    ensures exact: \result == (s->current < 0 || MtPortNow < s->task_start_us ? 0 :
        MtPortNow - s->task_start_us >= s->task_allowed_us ? 0 :
        s->task_allowed_us - (MtPortNow - s->task_start_us));
*/
uint32_t mt_sched_time_available_us(const mt_sched_t *s);

/* A 64-bit mean as the reports give it: clamped to 32 bits (mt_clamp_u32). */
/*@ logic integer MtClampU32(integer v) = v > 0xFFFFFFFF ? 0xFFFFFFFF : v; */

/** Load in permille: 1000 when the filtered loop rate is below 95% of the
 *  loop rate; otherwise 1000 * (period - mean spare) / period, 0 when the
 *  mean spare time is at least the period; 0 before the first loop. */
/*@ requires inv: MtSchedInv(s);
    assigns \nothing;
    ensures range: 0 <= \result <= 1000;
    ensures idle_is_zero: s->spare_ticks > 0 && s->filtered_loop_q8 <= (s->period_us * 256 * 100) / 95 &&
        s->spare_us / s->spare_ticks >= s->period_us ==> \result == 0;
*/
uint32_t mt_sched_load_permille(const mt_sched_t *s);

/** Fill a task report. */
/*@ requires inv: MtSchedInv(s);
    requires index: i < s->ntasks;
    requires out: \valid(r) && \separated(r, s);
    assigns *r;
    ensures runs: r->runs == s->st[i].runs;
    ensures mean_guarded: s->st[i].runs == 0 ==> r->mean_us == 0;
    ensures pending: r->pending == (s->tick - s->st[i].last_run) / s->st[i].interval;
    ensures mean: s->st[i].runs > 0 ==>
        r->mean_us == MtClampU32(s->st[i].total_us / s->st[i].runs);
    ensures copied: r->name == s->tasks[i].name && r->min_us == s->st[i].min_us &&
        r->max_us == s->st[i].max_us && r->overruns == s->st[i].overruns &&
        r->slips == s->st[i].slips && r->not_achieved == s->st[i].not_achieved &&
        r->budget_skips == s->st[i].budget_skips && r->interval == s->st[i].interval;
*/
void mt_sched_task_report(const mt_sched_t *s, uint32_t i, mt_task_report_t *r);

/** Fill the loop report. */
/*@ requires inv: MtSchedInv(s);
    requires out: \valid(r) && \separated(r, s);
    assigns *r;
    ensures mean_guarded: s->loops == 0 ==> r->mean_us == 0;
    ensures load: r->load_permille <= 1000;
    ensures copied: r->ticks == s->tick && r->loops == s->loops && r->min_us == s->loop_min_us &&
        r->max_us == s->loop_max_us && r->long_loops == s->long_loops &&
        r->extra_us == s->extra_us && r->filtered_us == s->filtered_loop_q8 / 256;
*/
void mt_sched_loop_report(const mt_sched_t *s, mt_loop_report_t *r);

/** Zero every statistic (not the due state). */
/*@ requires inv: MtSchedInv(s);
    assigns s->st[0 .. MT_CFG_SCHED_MAX_TASKS - 1], s->loops, s->loop_total_us, s->loop_min_us,
            s->loop_max_us, s->long_loops;
    ensures inv: MtSchedInv(s);
    ensures zero: \forall integer i; 0 <= i < MT_CFG_SCHED_MAX_TASKS ==>
        s->st[i].runs == 0 && s->st[i].min_us == 0 && s->st[i].max_us == 0 && s->st[i].total_us == 0 &&
        s->st[i].overruns == 0 && s->st[i].slips == 0 && s->st[i].not_achieved == 0 &&
        s->st[i].budget_skips == 0;
    ensures due_kept: \forall integer i; 0 <= i < MT_CFG_SCHED_MAX_TASKS ==>
        s->st[i].interval == \old(s->st[i].interval) && s->st[i].last_run == \old(s->st[i].last_run);
    ensures loop_zero: s->loops == 0 && s->loop_total_us == 0 && s->loop_min_us == 0 &&
        s->loop_max_us == 0 && s->long_loops == 0;
*/
void mt_sched_reset_stats(mt_sched_t *s);

#ifdef __cplusplus
}
#endif

#endif /* MT_SCHED_H */
