/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file bench_kernel.c
 * @brief Scheduler tick, timer-proc dispatch and binary semaphore against the
 *        ArduPilot-style peers (ref_ap.c) and POSIX primitives.
 *
 * Built three times (bench/bench.mk):
 *   kernel_stub     kernel + bench port (port_stub.c): stub time, flag lock
 *   kernel_stub255  the same with -DMT_CFG_SCHED_MAX_TASKS=255
 *   kernel_posix    kernel + hal_posix/port.c (-DBENCH_POSIX_PORT); the
 *                   scheduler and proc entries run in simulated-time mode
 *
 *   bench_kernel cg ENTRY N [ARGS]     one callgrind entry, N operations
 *       bench_sched_{mt,ap}  N ticks, ARGS = mix|idle NTASKS
 *       bench_proc_{mt,ap}   N dispatch rounds, ARGS = NPROCS
 *       bench_sem_{mt,posix,bsem}  N signal+wait pairs
 *   bench_kernel semwall PAIRS ROUNDS  wall-clock ns per pair, interleaved rounds
 */
#define _GNU_SOURCE
#include <semaphore.h>

#include "bench_util.h"
#include "mt/proc.h"
#include "mt/sched.h"
#include "mt/sem.h"
#include "ref_ap.h"

#ifdef BENCH_POSIX_PORT
#include "mt_posix.h"
#endif

#define LOOP_HZ 400u
#define BUDGET_US 50u

static const uint16_t k_mix_hz[10] = {400, 400, 200, 100, 50, 50, 10, 10, 5, 1};

static uint64_t g_calls; /* task and proc bodies count their calls */

static void body(void *arg)
{
    (void)arg;
    g_calls++;
}

/* ------------------------------------------------------------- scheduler */
static mt_task_t g_mt_tasks[255];
static mt_sched_t g_mt;
static ap_task_t g_ap_tasks[255];
static ap_sched_t g_ap;

static int sched_setup(const char *set, uint32_t n)
{
    uint32_t i;
    uint32_t bad = 0;
    int mix = (strcmp(set, "mix") == 0);

    if ((!mix && strcmp(set, "idle") != 0) || n < 1u || n > 255u || n > MT_CFG_SCHED_MAX_TASKS) {
        fprintf(stderr, "bench_kernel: bad task set %s/%u (max %u)\n", set, n, (unsigned)MT_CFG_SCHED_MAX_TASKS);
        return -1;
    }
    for (i = 0; i < n; i++) {
        uint16_t hz = mix ? k_mix_hz[i % 10u] : 1u;
        g_mt_tasks[i].name = "t";
        g_mt_tasks[i].fn = body;
        g_mt_tasks[i].arg = NULL;
        g_mt_tasks[i].rate_mhz = MT_HZ(hz);
        g_mt_tasks[i].budget_us = BUDGET_US;
        g_mt_tasks[i].priority = 10u;
        g_ap_tasks[i].fn = body;
        g_ap_tasks[i].arg = NULL;
        g_ap_tasks[i].rate_hz = hz;
        g_ap_tasks[i].max_time_micros = BUDGET_US;
        g_ap_tasks[i].priority = 10u;
    }
    if (mt_sched_init(&g_mt, g_mt_tasks, n, LOOP_HZ, &bad) != MT_OK) {
        fprintf(stderr, "bench_kernel: mt_sched_init failed at %u\n", bad);
        return -1;
    }
    ap_sched_init(&g_ap, g_ap_tasks, (uint8_t)n, LOOP_HZ);
    return 0;
}

/* One tick of each: count, scan and run, end-of-loop bookkeeping. */
NOINL uint64_t bench_sched_mt(uint64_t ticks)
{
    uint64_t k;
    uint32_t period = g_mt.period_us;
    for (k = 0; k < ticks; k++) {
        uint32_t left;
        mt_sched_tick(&g_mt);
        left = mt_sched_run(&g_mt, period);
        mt_sched_end_loop(&g_mt, left);
    }
    return g_calls;
}

NOINL uint64_t bench_sched_ap(uint64_t ticks)
{
    uint64_t k;
    uint32_t period = g_ap.loop_period_us;
    for (k = 0; k < ticks; k++) {
        ap_sched_tick(&g_ap);
        ap_sched_run(&g_ap, period);
        ap_sched_end_loop(&g_ap);
    }
    return g_calls;
}

/* ------------------------------------------------------------------ procs */
static mt_proc_set_t g_mt_procs;
static ap_timers_t g_ap_timers;
static int g_proc_args[MT_CFG_PROC_MAX];

static int proc_setup(uint32_t n)
{
    uint32_t i;
    if (n < 1u || n > MT_CFG_PROC_MAX || n > AP_MAX_TIMER_PROCS) {
        fprintf(stderr, "bench_kernel: bad proc count %u\n", n);
        return -1;
    }
    mt_proc_set_init(&g_mt_procs);
    ap_timers_init(&g_ap_timers);
    for (i = 0; i < n; i++) {
        if (mt_proc_register(&g_mt_procs, body, &g_proc_args[i]) != MT_OK) {
            fprintf(stderr, "bench_kernel: mt_proc_register failed\n");
            return -1;
        }
        ap_timers_register(&g_ap_timers, body, &g_proc_args[i]);
    }
    return 0;
}

NOINL uint64_t bench_proc_mt(uint64_t rounds)
{
    uint64_t k;
    for (k = 0; k < rounds; k++) {
        (void)mt_proc_dispatch(&g_mt_procs);
    }
    return g_calls;
}

NOINL uint64_t bench_proc_ap(uint64_t rounds)
{
    uint64_t k;
    for (k = 0; k < rounds; k++) {
        ap_run_timers(&g_ap_timers);
    }
    return g_calls;
}

/* ------------------------------------------------------------- semaphores */
static mt_sem_t g_mt_sem;
static sem_t g_posix_sem;
static ap_bsem_t g_bsem;
static uint64_t g_sem_bad;

static void sem_setup(void)
{
    mt_sem_init(&g_mt_sem, false);
    sem_init(&g_posix_sem, 0, 0);
    ap_bsem_init(&g_bsem, 0);
}

NOINL uint64_t bench_sem_mt(uint64_t pairs)
{
    uint64_t k;
    for (k = 0; k < pairs; k++) {
        mt_sem_signal(&g_mt_sem);
        g_sem_bad += (mt_sem_wait(&g_mt_sem, MT_WAIT_FOREVER) != MT_OK);
    }
    return pairs;
}

NOINL uint64_t bench_sem_posix(uint64_t pairs)
{
    uint64_t k;
    for (k = 0; k < pairs; k++) {
        sem_post(&g_posix_sem);
        g_sem_bad += (sem_wait(&g_posix_sem) != 0);
    }
    return pairs;
}

NOINL uint64_t bench_sem_bsem(uint64_t pairs)
{
    uint64_t k;
    for (k = 0; k < pairs; k++) {
        ap_bsem_signal(&g_bsem);
        ap_bsem_wait(&g_bsem);
    }
    return pairs;
}

static int sem_wall(uint64_t pairs, int rounds)
{
    static const char *names[3] = {"mt", "posix", "bsem"};
    uint64_t (*fns[3])(uint64_t) = {bench_sem_mt, bench_sem_posix, bench_sem_bsem};
    double *res[3];
    int r, k, i;

    for (k = 0; k < 3; k++) {
        res[k] = calloc((size_t)rounds, sizeof(double));
    }
    (void)bench_pin(0);
    for (k = 0; k < 3; k++) {
        (void)fns[k](pairs / 10u + 1u); /* warm-up */
    }
    for (r = 0; r < rounds; r++) {
        for (i = 0; i < 3; i++) {
            k = (r + i) % 3;
            double t0 = bench_now_s();
            (void)fns[k](pairs);
            res[k][r] = (bench_now_s() - t0) * 1e9 / (double)pairs;
        }
    }
    for (k = 0; k < 3; k++) {
        char key[64];
        char all[4096];
        size_t off = 0;
        for (r = 0; r < rounds && off < sizeof(all) - 32; r++) {
            off += (size_t)snprintf(all + off, sizeof(all) - off, "%s%.4g", r ? "," : "", res[k][r]);
        }
        double med = bench_median(res[k], rounds);
        snprintf(key, sizeof key, "semwall.%s", names[k]);
        BENCH_RESULT(key, "%.6g %.6g %.6g %s", med, res[k][0], res[k][rounds - 1], all);
        free(res[k]);
    }
    return g_sem_bad ? 3 : 0;
}

/* ------------------------------------------------------------------- main */
typedef struct {
    const char *name;
    uint64_t (*fn)(uint64_t);
    int kind; /* 0 sched, 1 proc, 2 sem */
} entry_t;

static const entry_t k_entries[] = {
    {"bench_sched_mt", bench_sched_mt, 0}, {"bench_sched_ap", bench_sched_ap, 0},
    {"bench_proc_mt", bench_proc_mt, 1},   {"bench_proc_ap", bench_proc_ap, 1},
    {"bench_sem_mt", bench_sem_mt, 2},     {"bench_sem_posix", bench_sem_posix, 2},
    {"bench_sem_bsem", bench_sem_bsem, 2},
};

int main(int argc, char **argv)
{
    size_t i;

    if (argc >= 4 && strcmp(argv[1], "semwall") == 0) {
        sem_setup();
        return sem_wall(strtoull(argv[2], NULL, 10), atoi(argv[3]));
    }
    if (argc < 4 || strcmp(argv[1], "cg") != 0) {
        fprintf(stderr, "usage: %s cg ENTRY N [mix|idle NTASKS | NPROCS] | semwall PAIRS ROUNDS\n", argv[0]);
        return 2;
    }
    for (i = 0; i < sizeof(k_entries) / sizeof(k_entries[0]); i++) {
        const entry_t *e = &k_entries[i];
        uint64_t n = strtoull(argv[3], NULL, 10);
        uint64_t calls;
        if (strcmp(argv[2], e->name) != 0) {
            continue;
        }
#ifdef BENCH_POSIX_PORT
        if (e->kind != 2) {
            mt_posix_sim_enable(1000000u);
        }
#endif
        if (e->kind == 0) {
            if (argc < 6 || sched_setup(argv[4], (uint32_t)strtoul(argv[5], NULL, 10)) != 0) {
                return 2;
            }
        } else if (e->kind == 1) {
            if (argc < 5 || proc_setup((uint32_t)strtoul(argv[4], NULL, 10)) != 0) {
                return 2;
            }
        } else {
            sem_setup();
        }
        g_calls = 0;
        calls = e->fn(n);
        if (g_sem_bad != 0u) {
            fprintf(stderr, "bench_kernel: a semaphore wait failed\n");
            return 3;
        }
        BENCH_RESULT(e->name, "%llu calls %llu max_tasks %u", (unsigned long long)n, (unsigned long long)calls,
                     (unsigned)MT_CFG_SCHED_MAX_TASKS);
        return 0;
    }
    fprintf(stderr, "bench_kernel: unknown entry %s\n", argv[2]);
    return 2;
}
