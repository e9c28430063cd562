/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file ref_ap_sync.c
 * @brief ArduPilot-style bench peers: _run_timers() and a mutex+condvar binary
 *        semaphore (see ref_ap.h). Own re-implementation, not ArduPilot code.
 */
#include <stddef.h>
#include <string.h>

#include "ref_ap.h"

void ap_timers_init(ap_timers_t *t)
{
    memset(t, 0, sizeof(*t));
    pthread_mutex_init(&t->lock, NULL);
}

void ap_timers_register(ap_timers_t *t, void (*fn)(void *), void *arg)
{
    uint8_t i;

    pthread_mutex_lock(&t->lock);
    for (i = 0; i < t->num_procs; i++) {
        if (t->procs[i].fn == fn && t->procs[i].arg == arg) {
            pthread_mutex_unlock(&t->lock);
            return;
        }
    }
    if (t->num_procs < AP_MAX_TIMER_PROCS) {
        t->procs[t->num_procs].fn = fn;
        t->procs[t->num_procs].arg = arg;
        t->num_procs++;
    }
    pthread_mutex_unlock(&t->lock);
}

void ap_run_timers(ap_timers_t *t)
{
    uint8_t n;
    uint8_t i;

    if (t->in_timer_proc) {
        return;
    }
    t->in_timer_proc = true;

    /* snapshot of the count under the registration lock */
    pthread_mutex_lock(&t->lock);
    n = t->num_procs;
    pthread_mutex_unlock(&t->lock);

    for (i = 0; i < n; i++) {
        if (t->procs[i].fn != NULL) {
            t->procs[i].fn(t->procs[i].arg);
        }
    }
    if (t->failsafe != NULL) {
        t->failsafe(NULL);
    }
    t->in_timer_proc = false;
}

void ap_bsem_init(ap_bsem_t *b, int available)
{
    pthread_mutex_init(&b->mu, NULL);
    pthread_cond_init(&b->cv, NULL);
    b->token = available ? 1 : 0;
}

void ap_bsem_signal(ap_bsem_t *b)
{
    pthread_mutex_lock(&b->mu);
    b->token = 1;
    pthread_cond_signal(&b->cv);
    pthread_mutex_unlock(&b->mu);
}

void ap_bsem_wait(ap_bsem_t *b)
{
    pthread_mutex_lock(&b->mu);
    while (b->token == 0) {
        pthread_cond_wait(&b->cv, &b->mu);
    }
    b->token = 0;
    pthread_mutex_unlock(&b->mu);
}
