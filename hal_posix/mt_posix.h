/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_posix.h
 * @brief Host port of Metronome (POSIX threads): port contract, metronome,
 *        proc threads and the simulated-time mode.
 *
 * Real-time mode (default): time is CLOCK_MONOTONIC, threads are pthreads at
 * SCHED_FIFO priorities when the process may use them (otherwise a one-line
 * notice and normal priorities).
 *
 * Simulated-time mode (mt_posix_sim_enable): time only moves when the test
 * moves it (mt_posix_sim_advance) or when the metronome waits for the next
 * sample; runs are deterministic. A semaphore wait with a timeout advances
 * simulated time by the timeout and times out (no other thread runs in this
 * mode); a wait without timeout halts ("deadlock in simulated time").
 */
#ifndef MT_POSIX_H
#define MT_POSIX_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/proc.h"
#include "mt/wq.h"
#include "mt_port.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Switch to simulated time starting at start_us (call before any thread starts). */
void mt_posix_sim_enable(uint64_t start_us);
/** Back to real time. */
void mt_posix_sim_disable(void);
/** True in simulated-time mode. */
bool mt_posix_sim_active(void);
/** Move simulated time forward (a task "spending" time calls this). */
void mt_posix_sim_advance(uint64_t us);

/** Paces the main loop: one sample every period_us on absolute deadlines. */
typedef struct {
    uint32_t period_us;
    uint64_t next_us; /**< next sample time (0: not started) */
    uint64_t samples; /**< samples delivered */
} mt_posix_metronome_t;

void mt_posix_metronome_init(mt_posix_metronome_t *m, uint32_t period_us);
/** mt_sample_wait_fn_t: waits for the next sample, returns its time (us). */
uint64_t mt_posix_metronome_wait(void *metronome);

/** A thread that dispatches a proc set every period_us on absolute deadlines. */
typedef struct {
    mt_proc_set_t *set;
    uint32_t period_us;
    volatile int stop; /**< set by mt_posix_proc_thread_stop */
    void *impl;        /**< pthread handle storage */
} mt_posix_proc_thread_t;

/** Start the dispatching thread (timer: MT_PRIO_TIMER, 1000 us; IO: MT_PRIO_IO). */
mt_status_t mt_posix_proc_thread_start(mt_posix_proc_thread_t *t, mt_proc_set_t *set,
                                       uint32_t period_us, mt_prio_base_t prio);
/** Stop and join it. */
void mt_posix_proc_thread_stop(mt_posix_proc_thread_t *t);

/** The thread that serves a work queue (mt_wq_thread_body at the queue's
 *  prio_base + prio_offset). Real-time mode only: in simulated time, run the
 *  queue from the test with mt_wq_run_pending(). */
typedef struct {
    mt_wq_t *wq;
    void *impl; /**< pthread handle storage */
} mt_posix_wq_thread_t;

/** Start the queue's thread.
 *  @retval MT_OK
 *  @retval MT_E_INVALID NULL queue, a priority base out of range, or simulated time.
 *  @retval MT_E_FULL no thread could be created. */
mt_status_t mt_posix_wq_start(mt_posix_wq_thread_t *t, mt_wq_t *q);
/** Ask the queue's thread to stop (mt_wq_request_stop) and join it; it
 *  finishes the run in progress, queued items stay queued. */
void mt_posix_wq_stop(mt_posix_wq_thread_t *t);

/** Join every thread made by mt_port_thread_create (for tests and demos). */
void mt_posix_join_all(void);

/** True if the last thread creation got a real-time priority. */
bool mt_posix_rt_priorities(void);

#ifdef __cplusplus
}
#endif

#endif /* MT_POSIX_H */
