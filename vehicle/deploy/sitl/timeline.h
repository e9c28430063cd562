/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file timeline.h
 * @brief SITL --timeline: where the time goes, as a Chrome trace-event JSON file.
 *
 * The file is the JSON object form of the Trace Event Format ({"traceEvents": [...]}), which
 * Perfetto's UI (ui.perfetto.dev, "Open trace file") and chrome://tracing open. One process,
 * one track per thread of the vehicle: the main loop, the timer thread, the IO thread and the
 * work queue's thread (in simulated time these are the threads the run stands for, named
 * after what each does on the real ports). Timestamps are the port's clock in microseconds.
 *
 *   main loop     "tick N" slices (the loop's sample to the end of the scheduler's tick), each
 *                 task run nested in its tick (the kernel's own start reading to the end of
 *                 the run), and instant events: "slip" (at the run that was late: args.missed
 *                 releases), "overrun" (at the end of the run that passed its allowance),
 *                 "budget skip" (at the end of the tick whose scan skipped the task)
 *   timer thread  one "timer procs" slice per dispatch round, its simulated cost as duration
 *   IO thread     one "io procs" slice per dispatch round (no simulated cost: duration 0)
 *   work queue    one slice per work item run, named after the item (from the items' run
 *                 counters around the round; the simulation gives work no cost, so the
 *                 round's items share its start and duration)
 *
 * Counts agree with the flight summary: task slices with each task's runs, instants with its
 * overruns, slips (sum of args.missed) and budget skips, dispatch slices with the proc sets'
 * dispatches, work slices with the queue's runs (tests/vehicle: t_timeline).
 */
#ifndef SITL_TIMELINE_H
#define SITL_TIMELINE_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/mt.h"

/** The tracks (thread ids in the file). */
typedef enum {
    TL_MAIN = 1,
    TL_TIMER = 2,
    TL_IO = 3,
    TL_WORK = 4
} tl_track_t;

/** Open FILE and write the header and the track names; false if it cannot be written. */
bool tl_open(const char *path, const mt_wq_t *wq);

/** A slice [ts, ts + dur] on a track; arg_name/arg (or NULL) becomes args. */
void tl_slice(tl_track_t track, const char *name, uint64_t ts, uint64_t dur, const char *arg_name,
              uint64_t arg);

/** An instant event on a track (thread scope). */
void tl_instant(tl_track_t track, const char *name, uint64_t ts, const char *task, uint64_t missed);

/** The task run in progress (called from the task's simulated work, where the kernel's
 *  scheduler names it as current and holds its start reading). */
void tl_task_begin(const mt_sched_t *sched);

/** The end of that run (after its simulated cost): its slice, with the allowance the
 *  scheduler gave it. */
void tl_task_end(const mt_sched_t *sched, uint64_t now);

/** A loop's sample time: the start of the next tick's slice. */
void tl_tick_begin(const mt_sched_t *sched, uint64_t sample);

/** The end of the tick: its slice, and the slips, overruns and budget skips the scheduler
 *  counted in it (from its per-task counters, the same the summary prints). */
void tl_tick_end(const mt_sched_t *sched, uint64_t now);

/** Before a round of the work queue (mt_wq_run_pending): its items' run counters. */
void tl_work_begin(const mt_wq_t *q);

/** After it: one slice [t0, t1] per run each item's counter gained, named by name_of(slot). */
void tl_work_end(const mt_wq_t *q, uint64_t t0, uint64_t t1, const char *(*name_of)(uint32_t slot));

/** Finish the JSON and close the file; false on a write error or a task run the scheduler
 *  did not name (never expected). */
bool tl_close(void);

#endif /* SITL_TIMELINE_H */
