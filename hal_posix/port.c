/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file port.c
 * @brief The port contract (kernel/port/mt_port.h) on POSIX threads.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <pthread.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "mt_posix.h"

#define MT_POSIX_MAX_THREADS 32
#define MT_POSIX_CHUNK_US (3600ull * 1000000ull) /* longest single timed wait */

/* ---- time ------------------------------------------------------------- */

/* Simulated time: the flag and the clock are read without a lock (atomic
 * loads), so mt_port_now_us costs one clock_gettime in real-time mode. */
static int g_sim_on;
static uint64_t g_sim_now;

static uint64_t real_now_us(void)
{
    struct timespec ts;
    (void)clock_gettime(CLOCK_MONOTONIC, &ts);
    return ((uint64_t)ts.tv_sec * 1000000u) + ((uint64_t)ts.tv_nsec / 1000u);
}

void mt_posix_sim_enable(uint64_t start_us)
{
    __atomic_store_n(&g_sim_now, start_us, __ATOMIC_RELEASE);
    __atomic_store_n(&g_sim_on, 1, __ATOMIC_RELEASE);
}

void mt_posix_sim_disable(void)
{
    __atomic_store_n(&g_sim_on, 0, __ATOMIC_RELEASE);
}

bool mt_posix_sim_active(void)
{
    return __atomic_load_n(&g_sim_on, __ATOMIC_ACQUIRE) != 0;
}

void mt_posix_sim_advance(uint64_t us)
{
    uint64_t t = __atomic_load_n(&g_sim_now, __ATOMIC_ACQUIRE);
    uint64_t n;
    do {
        n = (t <= UINT64_MAX - us) ? t + us : UINT64_MAX;
    } while (
        !__atomic_compare_exchange_n(&g_sim_now, &t, n, false, __ATOMIC_ACQ_REL, __ATOMIC_ACQUIRE));
}

static void sim_set_at_least(uint64_t target)
{
    uint64_t t = __atomic_load_n(&g_sim_now, __ATOMIC_ACQUIRE);
    while ((t < target) && !__atomic_compare_exchange_n(&g_sim_now, &t, target, false,
                                                        __ATOMIC_ACQ_REL, __ATOMIC_ACQUIRE)) {
    }
}

uint64_t mt_port_now_us(void)
{
    if (__atomic_load_n(&g_sim_on, __ATOMIC_ACQUIRE) != 0) {
        return __atomic_load_n(&g_sim_now, __ATOMIC_ACQUIRE);
    }
    return real_now_us();
}

/* ---- kernel lock ---------------------------------------------------------- */

/* Error-checking, statically initialised: a nested lock or an unlock by a
 * thread that does not hold it is a contract violation and halts. */
static pthread_mutex_t g_kernel_mu = PTHREAD_ERRORCHECK_MUTEX_INITIALIZER_NP;

void mt_port_lock(void)
{
    if (pthread_mutex_lock(&g_kernel_mu) != 0) {
        mt_port_halt("mt_port_lock: kernel lock already held by this thread");
    }
}

void mt_port_unlock(void)
{
    if (pthread_mutex_unlock(&g_kernel_mu) != 0) {
        mt_port_halt("mt_port_unlock: kernel lock not held");
    }
}

/* A simulated ISR is a host thread: same lock. */
void mt_port_lock_isr(void)
{
    mt_port_lock();
}

void mt_port_unlock_isr(void)
{
    mt_port_unlock();
}

/* ---- suspend / resume ------------------------------------------------------ */

typedef struct {
    pthread_cond_t cond;
    int resumed;
    int ready;
} waiter_t;

static __thread waiter_t t_waiter;

static void waiter_prepare(waiter_t *w)
{
    if (w->ready == 0) {
        pthread_condattr_t a;
        pthread_condattr_init(&a);
        pthread_condattr_setclock(&a, CLOCK_MONOTONIC);
        pthread_cond_init(&w->cond, &a);
        pthread_condattr_destroy(&a);
        w->ready = 1;
    }
    w->resumed = 0;
}

int32_t mt_port_suspend_s(mt_port_tref_t *ref, uint64_t timeout_us)
{
    waiter_t *me = &t_waiter;
    uint64_t deadline;

    if (mt_posix_sim_active()) {
        if (timeout_us == MT_WAIT_FOREVER) {
            mt_port_halt("mt_port_suspend_s: endless wait in simulated time");
        }
        mt_posix_sim_advance(timeout_us);
        return MT_PORT_TIMEOUT;
    }
    waiter_prepare(me);
    *ref = me;
    deadline = (timeout_us == MT_WAIT_FOREVER)              ? UINT64_MAX
               : (real_now_us() <= UINT64_MAX - timeout_us) ? real_now_us() + timeout_us
                                                            : UINT64_MAX;
    while (me->resumed == 0) {
        uint64_t now = real_now_us();
        uint64_t chunk;
        struct timespec ts;
        if (now >= deadline) {
            *ref = (mt_port_tref_t)0; /* under the lock: a later resume finds nobody */
            return MT_PORT_TIMEOUT;
        }
        chunk = deadline - now;
        if (chunk > MT_POSIX_CHUNK_US) {
            chunk = MT_POSIX_CHUNK_US;
        }
        now += chunk;
        ts.tv_sec = (time_t)(now / 1000000u);
        ts.tv_nsec = (long)((now % 1000000u) * 1000u);
        /* releases the kernel lock while parked, re-takes it before returning */
        (void)pthread_cond_timedwait(&me->cond, &g_kernel_mu, &ts);
    }
    return MT_PORT_RESUMED;
}

bool mt_port_resume_i(mt_port_tref_t *ref)
{
    waiter_t *w = (waiter_t *)*ref;

    if (w == (waiter_t *)0) {
        return false;
    }
    *ref = (mt_port_tref_t)0;
    w->resumed = 1;
    pthread_cond_signal(&w->cond);
    return true;
}

/* ---- threads ---------------------------------------------------------------- */

typedef struct {
    pthread_t th;
    mt_thread_fn_t fn;
    void *arg;
    int used;
} thread_slot_t;

static pthread_mutex_t g_thr_mu = PTHREAD_MUTEX_INITIALIZER;
static thread_slot_t g_threads[MT_POSIX_MAX_THREADS];
static int g_rt_ok = -1; /* -1 unknown, 0 refused, 1 granted */

static void *thread_tramp(void *p)
{
    thread_slot_t *s = (thread_slot_t *)p;
    s->fn(s->arg);
    return NULL;
}

bool mt_posix_rt_priorities(void)
{
    return g_rt_ok == 1;
}

/* SCHED_FIFO priorities keeping ArduPilot's order (IO 58 ... boost 182 map
 * to 10 ... 50 here). */
static int fifo_prio(mt_prio_base_t base, int8_t offset)
{
    static const int map[MT_PRIO_BASE_COUNT] = {10, 12, 14, 16, 18, 30, 35, 40, 45};
    int p = map[base] + offset;
    int lo = sched_get_priority_min(SCHED_FIFO);
    int hi = sched_get_priority_max(SCHED_FIFO);
    return (p < lo) ? lo : ((p > hi) ? hi : p);
}

/* Create a thread at the SCHED_FIFO priority of base+offset when permitted,
 * else at normal priority (with a one-time notice). Returns 0 or an errno. */
static int spawn(pthread_t *th, void *(*body)(void *), void *arg, mt_prio_base_t base,
                 int8_t offset)
{
    pthread_attr_t a;
    int rc = -1;

    pthread_attr_init(&a);
    if (g_rt_ok != 0) {
        struct sched_param sp;
        memset(&sp, 0, sizeof(sp));
        sp.sched_priority = fifo_prio(base, offset);
        pthread_attr_setinheritsched(&a, PTHREAD_EXPLICIT_SCHED);
        pthread_attr_setschedpolicy(&a, SCHED_FIFO);
        pthread_attr_setschedparam(&a, &sp);
        rc = pthread_create(th, &a, body, arg);
        if (rc == 0) {
            g_rt_ok = 1;
        } else if (g_rt_ok == -1) {
            g_rt_ok = 0;
            fprintf(stderr,
                    "metronome: real-time priorities not permitted (%s); threads run at "
                    "normal priority\n",
                    strerror(rc));
        }
    }
    pthread_attr_destroy(&a);
    if (rc != 0) {
        rc = pthread_create(th, NULL, body, arg);
    }
    return rc;
}

mt_status_t mt_port_thread_create(const char *name, mt_thread_fn_t fn, void *arg, void *stack,
                                  uint32_t stack_bytes, mt_prio_base_t base, int8_t offset)
{
    thread_slot_t *slot = NULL;
    int i;

    (void)stack; /* host threads use their own stacks */
    (void)stack_bytes;
    if ((fn == NULL) || ((unsigned)base >= (unsigned)MT_PRIO_BASE_COUNT)) {
        return MT_E_INVALID;
    }
    pthread_mutex_lock(&g_thr_mu);
    for (i = 0; i < MT_POSIX_MAX_THREADS; i++) {
        if (g_threads[i].used == 0) {
            slot = &g_threads[i];
            slot->used = 1;
            break;
        }
    }
    pthread_mutex_unlock(&g_thr_mu);
    if (slot == NULL) {
        return MT_E_FULL;
    }
    slot->fn = fn;
    slot->arg = arg;
    if (spawn(&slot->th, thread_tramp, slot, base, offset) != 0) {
        slot->used = 0;
        return MT_E_FULL;
    }
    if (name != NULL) {
        char nm[16];
        snprintf(nm, sizeof(nm), "%s", name);
        (void)pthread_setname_np(slot->th, nm);
    }
    return MT_OK;
}

void mt_posix_join_all(void)
{
    int i;
    for (i = 0; i < MT_POSIX_MAX_THREADS; i++) {
        if (g_threads[i].used != 0) {
            pthread_join(g_threads[i].th, NULL);
            g_threads[i].used = 0;
        }
    }
}

void mt_port_halt(const char *reason)
{
    fprintf(stderr, "metronome: halt: %s\n", reason);
    abort();
}

/* ---- metronome ---------------------------------------------------------------- */

void mt_posix_metronome_init(mt_posix_metronome_t *m, uint32_t period_us)
{
    m->period_us = period_us;
    m->next_us = 0u;
    m->samples = 0u;
}

static void sleep_until_us(uint64_t t)
{
    struct timespec ts;
    ts.tv_sec = (time_t)(t / 1000000u);
    ts.tv_nsec = (long)((t % 1000000u) * 1000u);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) == EINTR) {
    }
}

uint64_t mt_posix_metronome_wait(void *metronome)
{
    mt_posix_metronome_t *m = (mt_posix_metronome_t *)metronome;
    uint64_t now = mt_port_now_us();

    if (m->next_us == 0u) {
        m->next_us = now + m->period_us;
    } else {
        /* absolute deadlines: no drift; a late loop skips to the next boundary */
        m->next_us += m->period_us;
        if (m->next_us < now) {
            /* late: skip to the first period boundary at or after now */
            uint64_t behind = ((now - m->next_us) + m->period_us - 1u) / m->period_us;
            m->next_us += behind * m->period_us;
        }
    }
    if (mt_posix_sim_active()) {
        sim_set_at_least(m->next_us);
    } else {
        sleep_until_us(m->next_us);
    }
    m->samples++;
    return m->next_us;
}

/* ---- proc threads ---------------------------------------------------------------- */

static void proc_thread_body(void *p)
{
    mt_posix_proc_thread_t *t = (mt_posix_proc_thread_t *)p;
    uint64_t deadline = mt_port_now_us();

    while (__atomic_load_n(&t->stop, __ATOMIC_ACQUIRE) == 0) {
        uint32_t missed;
        sleep_until_us(deadline);
        (void)mt_proc_dispatch(t->set);
        missed = mt_proc_period_next(&deadline, mt_port_now_us(), t->period_us);
        mt_proc_note_missed(t->set, missed);
    }
}

typedef struct {
    pthread_t th;
} proc_impl_t;

static void *proc_tramp(void *p)
{
    proc_thread_body(p);
    return NULL;
}

mt_status_t mt_posix_proc_thread_start(mt_posix_proc_thread_t *t, mt_proc_set_t *set,
                                       uint32_t period_us, mt_prio_base_t prio)
{
    proc_impl_t *impl;
    if ((set == NULL) || (period_us == 0u) || mt_posix_sim_active()) {
        return MT_E_INVALID;
    }
    impl = (proc_impl_t *)calloc(1, sizeof(*impl));
    if (impl == NULL) {
        return MT_E_FULL;
    }
    t->set = set;
    t->period_us = period_us;
    t->stop = 0;
    t->impl = impl;
    if (spawn(&impl->th, proc_tramp, t, prio, 0) != 0) {
        free(impl);
        t->impl = NULL;
        return MT_E_FULL;
    }
    return MT_OK;
}

void mt_posix_proc_thread_stop(mt_posix_proc_thread_t *t)
{
    proc_impl_t *impl = (proc_impl_t *)t->impl;
    if (impl == NULL) {
        return;
    }
    __atomic_store_n(&t->stop, 1, __ATOMIC_RELEASE);
    pthread_join(impl->th, NULL);
    free(impl);
    t->impl = NULL;
}

/* ---- work-queue threads ------------------------------------------------------------ */

typedef struct {
    pthread_t th;
} wq_impl_t;

static void *wq_tramp(void *p)
{
    mt_wq_thread_body(p);
    return NULL;
}

mt_status_t mt_posix_wq_start(mt_posix_wq_thread_t *t, mt_wq_t *q)
{
    wq_impl_t *impl;
    if ((t == NULL) || (q == NULL) || ((unsigned)q->prio_base >= (unsigned)MT_PRIO_BASE_COUNT) ||
        mt_posix_sim_active()) {
        return MT_E_INVALID;
    }
    impl = (wq_impl_t *)calloc(1, sizeof(*impl));
    if (impl == NULL) {
        return MT_E_FULL;
    }
    t->wq = q;
    t->impl = impl;
    if (spawn(&impl->th, wq_tramp, q, q->prio_base, q->prio_offset) != 0) {
        free(impl);
        t->impl = NULL;
        return MT_E_FULL;
    }
    if (q->name != NULL) {
        char nm[16];
        snprintf(nm, sizeof(nm), "%s", q->name);
        (void)pthread_setname_np(impl->th, nm);
    }
    return MT_OK;
}

void mt_posix_wq_stop(mt_posix_wq_thread_t *t)
{
    wq_impl_t *impl = (wq_impl_t *)t->impl;
    if (impl == NULL) {
        return;
    }
    mt_wq_request_stop(t->wq);
    pthread_join(impl->th, NULL);
    free(impl);
    t->impl = NULL;
}
