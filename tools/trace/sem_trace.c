/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file tools/trace/sem_trace.c
 * @brief Trace generator for trace validation of tla/Sem.tla.
 *
 * Runs the real kernel/src/sem.c on the POSIX port (hal_posix/port.c) with
 * three threads: a waiting task (random poll / timed / forever waits), a
 * signalling task (mt_sem_signal) and a simulated ISR (mt_sem_signal_isr),
 * each sleeping a random few microseconds between calls. The calls from
 * sem.c into the port are intercepted with the linker's --wrap: every event
 * is logged while the kernel lock is held, so the log order is the order in
 * which the critical sections ran.
 *
 * The log is a TLA+ module (SemTraceData.tla, operator Trace) of records:
 *   [t, k = "lock", m]          lock taken (t = "W" with the wait's mode m)
 *   [t = "W", k = "suspend"]    mt_port_suspend_s called
 *   [t = "W", k = "wake", r]    mt_port_suspend_s returned r ("RESUMED"/"TIMEOUT")
 *   [t, k = "resume", r]        mt_port_resume_i returned r (TRUE/FALSE)
 *   [t, k = "unlock", token, waiting, merged]  state of the semaphore at unlock
 *   [t = "W", k = "ret", st]    the status mt_sem_wait returned (logged after it)
 * and the constants the check needs (Signals: the signals given).
 *
 * usage: sem_trace WAITS SIGNALS SEED OUT_DIR
 */
#define _GNU_SOURCE
#include <errno.h>
#include <pthread.h>
#include <sched.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "mt/sem.h"
#include "mt_port.h"
#include "trace_rng.h"

#define LOG_MAX 20000

static mt_sem_t g_sem;
static char *g_log[LOG_MAX];
static unsigned g_nlog;
static pthread_mutex_t g_log_mu = PTHREAD_MUTEX_INITIALIZER;
static unsigned g_waits, g_signals_quota;
static unsigned g_signals;        /* signals given (under the kernel lock) */
static volatile int g_waiter_done;
static uint64_t g_seed;
static uint32_t g_gap_us, g_timed_us; /* pause between signals, timed-wait limit (by seed) */

static __thread char tl_who = '?';
static __thread const char *tl_mode = "";
static __thread uint64_t tl_rng;

void __real_mt_port_lock(void);
void __real_mt_port_unlock(void);
void __real_mt_port_lock_isr(void);
void __real_mt_port_unlock_isr(void);
int32_t __real_mt_port_suspend_s(mt_port_tref_t *ref, uint64_t timeout_us);
bool __real_mt_port_resume_i(mt_port_tref_t *ref);

void __wrap_mt_port_lock(void);
void __wrap_mt_port_unlock(void);
void __wrap_mt_port_lock_isr(void);
void __wrap_mt_port_unlock_isr(void);
int32_t __wrap_mt_port_suspend_s(mt_port_tref_t *ref, uint64_t timeout_us);
bool __wrap_mt_port_resume_i(mt_port_tref_t *ref);

static uint32_t rnd(uint32_t n)
{
    return trace_rnd(&tl_rng, n);
}

static void logf_(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static void logf_(const char *fmt, ...)
{
    va_list ap;
    char *s = NULL;

    va_start(ap, fmt);
    if (vasprintf(&s, fmt, ap) < 0) {
        abort();
    }
    va_end(ap);
    pthread_mutex_lock(&g_log_mu);
    if (g_nlog >= LOG_MAX) {
        fprintf(stderr, "sem_trace: log full\n");
        abort();
    }
    g_log[g_nlog++] = s;
    pthread_mutex_unlock(&g_log_mu);
}

static void log_lock(void)
{
    if (tl_who == 'W') {
        logf_("[t |-> \"W\", k |-> \"lock\", m |-> \"%s\"]", tl_mode);
    } else {
        logf_("[t |-> \"%c\", k |-> \"lock\"]", tl_who);
    }
}

static void log_unlock(void)
{
    logf_("[t |-> \"%c\", k |-> \"unlock\", token |-> %u, waiting |-> %s, merged |-> %u]", tl_who,
          g_sem.token, g_sem.waiter != NULL ? "TRUE" : "FALSE", g_sem.merged);
}

void __wrap_mt_port_lock(void)
{
    __real_mt_port_lock();
    log_lock();
}

void __wrap_mt_port_unlock(void)
{
    log_unlock();
    __real_mt_port_unlock();
}

void __wrap_mt_port_lock_isr(void)
{
    __real_mt_port_lock_isr();
    log_lock();
}

void __wrap_mt_port_unlock_isr(void)
{
    log_unlock();
    __real_mt_port_unlock_isr();
}

int32_t __wrap_mt_port_suspend_s(mt_port_tref_t *ref, uint64_t timeout_us)
{
    int32_t r;

    logf_("[t |-> \"W\", k |-> \"suspend\"]");
    r = __real_mt_port_suspend_s(ref, timeout_us);
    logf_("[t |-> \"W\", k |-> \"wake\", r |-> \"%s\"]",
          r == MT_PORT_RESUMED ? "RESUMED" : "TIMEOUT");
    return r;
}

bool __wrap_mt_port_resume_i(mt_port_tref_t *ref)
{
    bool r = __real_mt_port_resume_i(ref);

    g_signals++; /* every mt_sem_signal_i calls resume_i exactly once */
    logf_("[t |-> \"%c\", k |-> \"resume\", r |-> %s]", tl_who, r ? "TRUE" : "FALSE");
    return r;
}

static void pause_us(uint32_t max_us)
{
    struct timespec ts = {0, (long)(rnd(max_us + 1u) * 1000u)};
    if (ts.tv_nsec == 0) {
        sched_yield();
    } else {
        nanosleep(&ts, NULL);
    }
}

static void *waiter(void *arg)
{
    unsigned i;

    (void)arg;
    tl_who = 'W';
    tl_rng = g_seed * 3u + 1u;
    for (i = 0; i < g_waits; i++) {
        uint32_t pick = rnd(3);
        uint64_t t = pick == 0u ? 0u : pick == 1u ? 10u + rnd(g_timed_us) : MT_WAIT_FOREVER;
        mt_status_t st;
        tl_mode = pick == 0u ? "poll" : pick == 1u ? "timed" : "forever";
        st = mt_sem_wait(&g_sem, t);
        logf_("[t |-> \"W\", k |-> \"ret\", st |-> \"%s\"]",
              st == MT_OK ? "OK" : st == MT_E_TIMEOUT ? "TIMEOUT" : "BUSY");
        pause_us(100);
    }
    g_waiter_done = 1;
    return NULL;
}

static void *signaller(void *arg)
{
    unsigned i;

    tl_who = *(const char *)arg;
    tl_rng = g_seed * 7u + (tl_who == 'S' ? 2u : 3u);
    for (i = 0; i < g_signals_quota; i++) {
        pause_us(g_gap_us);
        if (tl_who == 'S') {
            mt_sem_signal(&g_sem);
        } else {
            mt_sem_signal_isr(&g_sem);
        }
    }
    return NULL;
}

int main(int argc, char **argv)
{
    pthread_t tw, ts, ti;
    static const char s_id = 'S', i_id = 'I';
    char path[4096];
    FILE *out;
    unsigned k;

    if (argc != 5) {
        fprintf(stderr, "usage: %s WAITS SIGNALS SEED OUT_DIR\n", argv[0]);
        return 2;
    }
    g_waits = (unsigned)strtoul(argv[1], NULL, 0);
    g_signals_quota = (unsigned)strtoul(argv[2], NULL, 0);
    g_seed = strtoull(argv[3], NULL, 0);
    g_gap_us = 100u + 200u * (uint32_t)(g_seed % 3u);
    g_timed_us = 50u + 150u * (uint32_t)(g_seed % 2u);
    mt_sem_init(&g_sem, false);

    pthread_create(&tw, NULL, waiter, NULL);
    pthread_create(&ts, NULL, signaller, (void *)&s_id);
    pthread_create(&ti, NULL, signaller, (void *)&i_id);
    pthread_join(ts, NULL);
    pthread_join(ti, NULL);
    /* The signalling task keeps signalling until the waiter has finished, so a
     * wait without a time limit always ends. */
    tl_who = 'S';
    tl_rng = g_seed * 11u + 5u;
    while (!g_waiter_done) {
        mt_sem_signal(&g_sem);
        pause_us(500);
    }
    pthread_join(tw, NULL);

    snprintf(path, sizeof path, "%s/SemTraceData.tla", argv[4]);
    out = fopen(path, "w");
    if (out == NULL) {
        fprintf(stderr, "sem_trace: %s: %s\n", path, strerror(errno));
        return 2;
    }
    fprintf(out, "---- MODULE SemTraceData ----\n"
                 "\\* Generated by tools/trace/sem_trace %s %s %s\n"
                 "Signals == %u\n"
                 "Trace == <<\n",
            argv[1], argv[2], argv[3], g_signals);
    for (k = 0; k < g_nlog; k++) {
        fprintf(out, "    %s%s\n", g_log[k], k + 1u < g_nlog ? "," : "");
        free(g_log[k]);
    }
    fputs(">>\n====\n", out);
    fclose(out);
    printf("%u\n", g_signals);
    return 0;
}
