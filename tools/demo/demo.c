/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file demo.c
 * @brief `make demo`: a small task table on the host port for a few seconds,
 *        then a per-task statistics table (like ArduPilot's tasks.txt) and the
 *        load average.
 *
 * Usage: mt_demo [--sim] [seconds]
 *   real time (default): main loop at 400 Hz paced by the port's metronome on
 *   real threads, a 1 kHz timer-proc thread feeding an object ring, an IO-proc
 *   thread draining a byte ring, a semaphore hand-off between threads.
 *   --sim: the same table in deterministic simulated time (no threads).
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "mt/mt.h"
#include "mt_posix.h"

#define LOOP_HZ 400u

static int g_sim;
static mt_oring_t g_baro_ring;
static uint8_t g_baro_store[MT_ORING_STORAGE_BYTES(sizeof(uint32_t), 64u)];
static mt_bring_t g_log_ring;
static uint8_t g_log_store[4096];
static mt_sem_t g_sem;
static uint32_t g_baro_seq;
static uint32_t g_baro_recv;
static uint64_t g_log_bytes;
static uint32_t g_sem_given;
static uint32_t g_sem_taken;

/* Spend about us microseconds (simulated: advance the clock; real: spin). */
static void work(uint32_t us)
{
    if (g_sim) {
        mt_posix_sim_advance(us);
    } else {
        uint64_t end = mt_port_now_us() + us;
        while (mt_port_now_us() < end) {
        }
    }
}

static void fast_imu(void *a) { (void)a; work(120); }
static void fast_rate_ctrl(void *a) { (void)a; work(180); }

static void nav_update(void *a)
{
    uint32_t v;
    (void)a;
    while (mt_oring_pop(&g_baro_ring, &v) == MT_OK) {
        g_baro_recv++;
    }
    work(150);
}

static void gps_update(void *a) { (void)a; work(200); }

static void telemetry(void *a)
{
    char line[64];
    int n;
    (void)a;
    n = snprintf(line, sizeof(line), "tlm seq=%u\n", (unsigned)g_baro_recv);
    (void)mt_bring_write(&g_log_ring, (const uint8_t *)line, (uint32_t)n);
    work(250);
}

static void logger(void *a)
{
    (void)a;
    if (!g_sim) {
        mt_sem_signal(&g_sem); /* hand-off to the worker thread */
        g_sem_given++;
    }
    work(300);
}

static void housekeeping(void *a) { (void)a; work(400); }
static void status_1hz(void *a) { (void)a; work(100); }

static const mt_task_t g_tasks[] = {
    {"ins_update*", fast_imu, NULL, 0u, 0u, 0u},
    {"rate_ctrl*", fast_rate_ctrl, NULL, 0u, 0u, 1u},
    {"nav_update", nav_update, NULL, MT_HZ(50), 300u, 10u},
    {"gps_update", gps_update, NULL, MT_HZ(10), 400u, 20u},
    {"telemetry", telemetry, NULL, MT_HZ(20), 500u, 30u},
    {"logger", logger, NULL, MT_HZ(25), 450u, 40u},
    {"housekeeping", housekeeping, NULL, MT_HZ(3), 600u, 50u},
    {"status", status_1hz, NULL, MT_HZ(1), 200u, 60u},
};

static void baro_proc(void *a)
{
    (void)a;
    if (mt_oring_push(&g_baro_ring, &g_baro_seq) == MT_OK) {
        g_baro_seq++;
    }
}

static void log_drain(void *a)
{
    uint8_t buf[256];
    (void)a;
    g_log_bytes += mt_bring_read(&g_log_ring, buf, sizeof(buf));
}

static volatile int g_stop;

static void sem_worker(void *a)
{
    (void)a;
    while (!__atomic_load_n(&g_stop, __ATOMIC_ACQUIRE)) {
        if (mt_sem_wait(&g_sem, 20000u) == MT_OK) {
            g_sem_taken++;
        }
    }
}

int main(int argc, char **argv)
{
    static mt_sched_t sched;
    static mt_proc_set_t timer_procs;
    static mt_proc_set_t io_procs;
    mt_posix_metronome_t met;
    mt_posix_proc_thread_t timer_thr;
    mt_posix_proc_thread_t io_thr;
    mt_loop_report_t lr;
    uint32_t bad = 0;
    uint32_t seconds = 3u;
    uint64_t loops;
    uint64_t i;
    int a;
    mt_status_t st;

    for (a = 1; a < argc; a++) {
        if (strcmp(argv[a], "--sim") == 0) {
            g_sim = 1;
        } else {
            seconds = (uint32_t)strtoul(argv[a], NULL, 10);
        }
    }
    if (g_sim) {
        mt_posix_sim_enable(1000000u);
    }
    (void)mt_oring_init(&g_baro_ring, g_baro_store, sizeof(uint32_t), 64u);
    (void)mt_bring_init(&g_log_ring, g_log_store, sizeof(g_log_store));
    mt_sem_init(&g_sem, false);
    st = mt_sched_init(&sched, g_tasks, (uint32_t)(sizeof(g_tasks) / sizeof(g_tasks[0])), LOOP_HZ,
                       &bad);
    if (st != MT_OK) {
        fprintf(stderr, "task table rejected: %s at entry %u\n", mt_status_str(st), bad);
        return 1;
    }
    mt_proc_set_init(&timer_procs);
    mt_proc_set_init(&io_procs);
    if ((mt_proc_register(&timer_procs, baro_proc, NULL) != MT_OK) ||
        (mt_proc_register(&io_procs, log_drain, NULL) != MT_OK)) {
        fprintf(stderr, "proc registration failed\n");
        return 1;
    }
    if (!g_sim) {
        if ((mt_posix_proc_thread_start(&timer_thr, &timer_procs, 1000u, MT_PRIO_TIMER) != MT_OK) ||
            (mt_posix_proc_thread_start(&io_thr, &io_procs, 1000u, MT_PRIO_IO) != MT_OK) ||
            (mt_port_thread_create("sem_worker", sem_worker, NULL, NULL, 0u, MT_PRIO_UART, 0) !=
             MT_OK)) {
            fprintf(stderr, "thread start failed\n");
            return 1;
        }
    }
    mt_posix_metronome_init(&met, sched.period_us);
    loops = (uint64_t)seconds * LOOP_HZ;
    for (i = 0; i < loops; i++) {
        if (g_sim) {
            /* no threads in simulated time: procs are dispatched once per loop */
            (void)mt_proc_dispatch(&timer_procs);
            (void)mt_proc_dispatch(&io_procs);
        }
        mt_sched_loop_once(&sched, mt_posix_metronome_wait, &met);
    }
    if (!g_sim) {
        __atomic_store_n(&g_stop, 1, __ATOMIC_RELEASE);
        mt_posix_proc_thread_stop(&timer_thr);
        mt_posix_proc_thread_stop(&io_thr);
        mt_posix_join_all();
    }

    printf("Metronome demo: %u s, loop %u Hz, %s time%s\n", seconds, LOOP_HZ,
           g_sim ? "simulated" : "real",
           (!g_sim && !mt_posix_rt_priorities()) ? " (normal thread priorities)" : "");
    printf("%-14s %9s %9s %7s %7s %7s %5s %6s %6s %6s\n", "TASK", "RUNS", "EXPECTED", "MIN", "MAX",
           "AVG", "OVR", "SLIP", "SKIP", "NACH");
    for (i = 0; i < sched.ntasks; i++) {
        mt_task_report_t r;
        uint64_t expected;
        mt_sched_task_report(&sched, (uint32_t)i, &r);
        expected = sched.tick / r.interval;
        printf("%-14s %9llu %9llu %7u %7u %7u %5u %6llu %6llu %6llu\n", r.name,
               (unsigned long long)r.runs, (unsigned long long)expected, r.min_us, r.max_us,
               r.mean_us, r.overruns, (unsigned long long)r.slips,
               (unsigned long long)r.budget_skips, (unsigned long long)r.not_achieved);
    }
    mt_sched_loop_report(&sched, &lr);
    printf("loop: ticks %llu, mean %u us (min %u, max %u), long loops %u, extra %u us\n",
           (unsigned long long)lr.ticks, lr.mean_us, lr.min_us, lr.max_us, lr.long_loops,
           lr.extra_us);
    printf("load average: %u.%u%%\n", lr.load_permille / 10u, lr.load_permille % 10u);
    printf("timer procs: %llu rounds, %u periods missed; baro sent %u received %u queued %u, "
           "ring lost %u rejected %u\n",
           (unsigned long long)timer_procs.dispatches, timer_procs.periods_missed, g_baro_seq,
           g_baro_recv, mt_oring_available(&g_baro_ring), g_baro_ring.lost, g_baro_ring.rejected);
    printf("io procs: %llu rounds, log bytes drained %llu; semaphore given %u taken %u merged %u\n",
           (unsigned long long)io_procs.dispatches, (unsigned long long)g_log_bytes, g_sem_given,
           g_sem_taken, g_sem.merged);
    return 0;
}
