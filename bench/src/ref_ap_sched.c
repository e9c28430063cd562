/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file ref_ap_sched.c
 * @brief ArduPilot-style scheduler peer (see ref_ap.h). Own re-implementation of
 *        the described algorithms, not ArduPilot code.
 */
#include "ref_ap.h"

#include <string.h>

void ap_sched_init(ap_sched_t *s, const ap_task_t *tasks, uint8_t n, uint16_t loop_rate_hz)
{
    memset(s, 0, sizeof(*s));
    s->tasks = tasks;
    s->num_tasks = n;
    s->loop_rate_hz = loop_rate_hz;
    s->loop_period_us = 1000000u / loop_rate_hz;
    s->current_task = -1;
}

void ap_sched_tick(ap_sched_t *s)
{
    s->tick_counter++;
    s->tick_counter32++;
}

void ap_sched_run(ap_sched_t *s, uint32_t time_available)
{
    uint32_t now = ref_micros();
    const uint32_t n = s->num_tasks;
    const uint32_t loop_rate_hz = s->loop_rate_hz;
    uint32_t i;

    for (i = 0; i < n; i++) {
        const ap_task_t *task = &s->tasks[i];
        const bool fast = task->priority <= AP_MAX_FAST_PRIO;

        if (!fast) {
            const uint16_t dt = (uint16_t)(s->tick_counter - s->last_run[i]);
            /* the division per task per tick */
            uint32_t interval_ticks = (task->rate_hz == 0u) ? 1u : (loop_rate_hz / task->rate_hz);
            if (interval_ticks < 1u) {
                interval_ticks = 1u;
            }
            if (dt < interval_ticks) {
                continue; /* not due */
            }
            if (dt >= interval_ticks * 2u) {
                s->slips[i]++;
            }
            if (dt >= interval_ticks * 4u) {
                s->task_not_achieved++;
            }
            s->task_time_allowed = task->max_time_micros;
            if (s->task_time_allowed > time_available) {
                continue; /* does not fit: stays due */
            }
        } else {
            s->task_time_allowed = s->loop_period_us;
        }

        s->task_time_started = now;
        s->current_task = (int16_t)i;
        task->fn(task->arg);
        s->current_task = -1;
        s->last_run[i] = s->tick_counter;

        /* one time read after each run */
        now = ref_micros();
        {
            const uint32_t time_taken = now - s->task_time_started;
            if (time_taken > s->task_time_allowed) {
                s->overruns[i]++;
            }
            if (time_taken >= time_available) {
                time_available = 0;
            } else {
                time_available -= time_taken;
            }
        }
    }

    /* spare-time window */
    s->spare_micros += time_available;
    s->spare_ticks++;
    if (s->spare_ticks == 32u) {
        s->spare_micros /= 2u;
        s->spare_ticks /= 2u;
    }
}

void ap_sched_end_loop(ap_sched_t *s)
{
    if (s->task_not_achieved > 0u) {
        s->extra_loop_us = (s->extra_loop_us + 100u < 5000u) ? s->extra_loop_us + 100u : 5000u;
        s->task_not_achieved = 0;
        s->clean_loops = 0;
    } else if (s->extra_loop_us > 0u) {
        s->clean_loops++;
        if (s->clean_loops > 50u) {
            s->clean_loops = 0;
            s->extra_loop_us = (s->extra_loop_us > 50u) ? s->extra_loop_us - 50u : 0u;
        }
    }
}
