/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_port_chibios.h
 * @brief ChibiOS/RT port: the services beyond kernel/port/mt_port.h that a
 *        firmware needs to run the kernel (no ChibiOS type appears here, so
 *        applications never include a ChibiOS header).
 *
 * Operating rules
 * - mt_chibios_init() once from main(), after the board bring-up and before
 *   any other Metronome call; main() then runs as an RT thread.
 * - The main loop calls mt_sched_loop_once(&sched, mt_chibios_metronome_wait,
 *   &metronome): the sample wait sleeps until absolute deadlines one loop
 *   period apart (no drift) and returns the sample time.
 * - Timer and IO procs run in proc threads: sleep until an absolute deadline,
 *   mt_proc_dispatch(), then mt_proc_period_next()/mt_proc_note_missed().
 * - ISR timers call their function from the system-tick interrupt with the
 *   kernel lock NOT held: use the `_isr` kernel calls there
 *   (mt_sem_signal_isr), never the task or `_i` ones.
 * - Time resolution: one RT tick (1 ms with hal_chibios/cfg/chconf.h),
 *   refined to 1 us inside the tick from the SysTick counter when the RT
 *   tick is the periodic Cortex-M SysTick (MT_PORT_CHIBIOS_SUBTICK).
 */
#ifndef MT_PORT_CHIBIOS_H
#define MT_PORT_CHIBIOS_H

#include <stdint.h>

#include "mt/proc.h"
#include "mt/sem.h"
#include "mt/status.h"
#include "mt/wq.h"
#include "mt_port.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Number of ISR timers (mt_chibios_isr_timer_start) available. */
#if !defined(MT_CHIBIOS_ISR_TIMERS)
#define MT_CHIBIOS_ISR_TIMERS 2u
#endif

/** Start ChibiOS/RT (chSysInit(): main() becomes a thread at NORMALPRIO,
 *  interrupts on) and the time keeper that samples the system tick often
 *  enough for the 64-bit extension to see every counter wrap. */
void mt_chibios_init(void);

/** Set the calling thread's priority (ArduPilot-like base plus offset, the
 *  mapping of mt_port_thread_create()). */
void mt_chibios_set_priority(mt_prio_base_t base, int8_t offset);

/** Sleep until mt_port_now_us() >= deadline_us (returns at once when it
 *  already is). Wakes on the first tick edge at or after the deadline. */
void mt_chibios_sleep_until_us(uint64_t deadline_us);

/** Main-loop metronome: sample times on a fixed grid of period_us. */
typedef struct {
    uint64_t deadline_us; /**< next sample time */
    uint32_t period_us;   /**< 1e6 / rate, rounded down */
    uint32_t missed;      /**< sample times the loop came too late for (saturating) */
    uint64_t samples;     /**< samples delivered */
} mt_chibios_metronome_t;

/** Start the grid at the last tick edge. @retval MT_OK
 *  @retval MT_E_INVALID rate_hz is 0 or above the RT tick rate. */
mt_status_t mt_chibios_metronome_init(mt_chibios_metronome_t *m, uint32_t rate_hz);

/** Sample wait (an mt_sample_wait_fn_t; ctx is the metronome): moves the
 *  deadline to the next grid time after now (counting skipped ones in
 *  missed), sleeps until it and returns it. */
uint64_t mt_chibios_metronome_wait(void *ctx);

/** A thread that dispatches a proc set every period_us. */
typedef struct {
    mt_proc_set_t *set;   /**< procs to dispatch */
    uint64_t deadline_us; /**< next dispatch time */
    uint32_t period_us;   /**< dispatch period */
    uint32_t stop;        /**< stop request (written under the kernel lock) */
    uint64_t rounds;      /**< dispatch rounds done */
    mt_sem_t done;        /**< signalled once the thread has terminated (stack free) */
} mt_chibios_proc_thread_t;

/** Create the thread on stack (priority base + 0); the first dispatch comes
 *  one period after the last tick edge.
 *  @retval MT_OK, MT_E_INVALID (period 0, or as mt_port_thread_create). */
mt_status_t mt_chibios_proc_thread_start(mt_chibios_proc_thread_t *pt, const char *name,
                                         mt_proc_set_t *set, uint32_t period_us, void *stack,
                                         uint32_t stack_bytes, mt_prio_base_t base);

/** Ask the thread to stop after its current round and wait up to
 *  timeout_us for it to exit. [task context]
 *  @retval MT_OK stopped. @retval MT_E_TIMEOUT still running. */
mt_status_t mt_chibios_proc_thread_stop(mt_chibios_proc_thread_t *pt, uint64_t timeout_us);

/** The thread that serves a work queue (mt_wq_thread_body). */
typedef struct {
    mt_wq_t *wq;   /**< the queue */
    mt_sem_t done; /**< signalled once the thread has terminated (stack free) */
} mt_chibios_wq_thread_t;

/** Create the queue's thread on stack at the queue's prio_base + prio_offset,
 *  named after the queue.
 *  @retval MT_OK, MT_E_INVALID (as mt_port_thread_create: bad priority base,
 *          stack too small). */
mt_status_t mt_chibios_wq_start(mt_chibios_wq_thread_t *wt, mt_wq_t *q, void *stack,
                                uint32_t stack_bytes);

/** Ask the queue's thread to stop (mt_wq_request_stop; it ends the run in
 *  progress) and wait up to timeout_us for it to exit. [task context]
 *  @retval MT_OK stopped. @retval MT_E_TIMEOUT still running. */
mt_status_t mt_chibios_wq_stop(mt_chibios_wq_thread_t *wt, uint64_t timeout_us);

/** ISR timer function: ISR context, kernel lock not held. */
typedef void (*mt_chibios_isr_fn_t)(void *arg);

/** Call fn(arg) from the system-tick interrupt every period_us (rounded up
 *  to whole ticks), first one period from now; *id names the timer.
 *  @retval MT_OK
 *  @retval MT_E_INVALID fn is NULL, or the period is 0 or too long for one RT interval.
 *  @retval MT_E_FULL all MT_CHIBIOS_ISR_TIMERS timers are in use. */
mt_status_t mt_chibios_isr_timer_start(uint32_t *id, uint32_t period_us, mt_chibios_isr_fn_t fn,
                                       void *arg);

/** Stop an ISR timer: after the call fn is not called again. [task context] */
void mt_chibios_isr_timer_stop(uint32_t id);

#ifdef __cplusplus
}
#endif

#endif /* MT_PORT_CHIBIOS_H */
