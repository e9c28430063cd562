/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file ref_ap.h
 * @brief Bench peers in the style of ArduPilot, written for this project from
 *        the algorithm descriptions in shared/reference/performance.md §3.1-3.2
 *        and ardupilot.md §1.1-1.2. NOT ArduPilot code.
 *
 * - ap_sched_*: AP_Scheduler::run() as described: every tick the whole table
 *   is scanned; per task a 16-bit dt, a division loop_rate / rate_hz, the due
 *   test, slip / not-achieved counts, the budget check; after each run one
 *   time read and the budget bookkeeping; after the scan the spare-time window
 *   (halved at 32 ticks). ap_sched_end_loop is loop()'s extra-time adaptation.
 *   Per-task perf records (TaskInfo, off by default in ArduPilot) are left out,
 *   as in the performance.md reference; slip and overrun counters are kept.
 * - ap_timers_*: AP_HAL_ChibiOS Scheduler::_run_timers(): a re-entry flag, the
 *   proc count snapshot taken under a lock (a pthread mutex stands in for the
 *   ChibiOS binary semaphore), then the procs called without the lock, then the
 *   failsafe hook.
 * - ap_bsem_*: a binary semaphore from a mutex and a condition variable (the
 *   "bsem" of performance.md §2.3).
 */
#ifndef REF_AP_H
#define REF_AP_H

#include <stdbool.h>
#include <stdint.h>

#define AP_MAX_TASKS 255
#define AP_MAX_FAST_PRIO 3
#define AP_MAX_TIMER_PROCS 8

/** Stand-in for AP_HAL::micros(): a counter in its own translation unit
 *  (bench/src/stub_time.c), the same cost as the Metronome bench port's time. */
uint32_t ref_micros(void);

typedef struct {
    void (*fn)(void *);
    void *arg;
    uint32_t rate_hz;         /* 0 = every loop (ArduPilot: a float) */
    uint16_t max_time_micros;
    uint8_t priority;         /* <= 3: fast (as AP's `priority > 3` test) */
} ap_task_t;

typedef struct {
    const ap_task_t *tasks;
    uint8_t num_tasks;
    uint16_t loop_rate_hz;
    uint32_t loop_period_us;
    uint16_t tick_counter;
    uint32_t tick_counter32;
    uint16_t last_run[AP_MAX_TASKS];
    uint16_t slips[AP_MAX_TASKS];
    uint16_t overruns[AP_MAX_TASKS];
    uint32_t task_time_allowed;
    uint32_t task_time_started;
    int16_t current_task;
    uint32_t task_not_achieved;
    uint32_t spare_micros;
    uint8_t spare_ticks;
    uint32_t extra_loop_us;
    uint32_t clean_loops;
} ap_sched_t;

void ap_sched_init(ap_sched_t *s, const ap_task_t *tasks, uint8_t n, uint16_t loop_rate_hz);
void ap_sched_tick(ap_sched_t *s);
void ap_sched_run(ap_sched_t *s, uint32_t time_available);
void ap_sched_end_loop(ap_sched_t *s);

/* ref_ap_sync.c (host only; ref_ap_sched.c also builds for Cortex-M4) */
#ifndef REF_AP_SCHED_ONLY
#include <pthread.h>

typedef struct {
    void (*fn)(void *);
    void *arg;
} ap_proc_t;

typedef struct {
    pthread_mutex_t lock;
    ap_proc_t procs[AP_MAX_TIMER_PROCS];
    uint8_t num_procs;
    volatile bool in_timer_proc;
    void (*failsafe)(void *);
} ap_timers_t;

void ap_timers_init(ap_timers_t *t);
void ap_timers_register(ap_timers_t *t, void (*fn)(void *), void *arg);
void ap_run_timers(ap_timers_t *t);

typedef struct {
    pthread_mutex_t mu;
    pthread_cond_t cv;
    int token;
} ap_bsem_t;

void ap_bsem_init(ap_bsem_t *b, int available);
void ap_bsem_signal(ap_bsem_t *b);
void ap_bsem_wait(ap_bsem_t *b);
#endif /* REF_AP_SCHED_ONLY */

#endif /* REF_AP_H */
