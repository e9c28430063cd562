/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file sem.c
 * @brief Binary semaphore (see mt/sem.h). The port only parks and un-parks
 *        threads; who gets the token is decided here.
 */
#include "mt/sem.h"

void mt_sem_init(mt_sem_t *s, bool available)
{
    if (available) {
        s->token = 1u;
    } else {
        s->token = 0u;
    }
    s->waiter = (mt_port_tref_t)0;
    s->merged = 0u;
}

mt_status_t mt_sem_wait_s(mt_sem_t *s, uint64_t timeout_us)
{
    mt_status_t st;

    if (s->token != 0u) {
        s->token = 0u;
        st = MT_OK;
    } else if (s->waiter != (mt_port_tref_t)0) {
        st = MT_E_BUSY;
    } else if (timeout_us == 0u) {
        st = MT_E_TIMEOUT;
    } else {
        /* A signal while parked hands the token over directly (token stays 0). */
        st = (mt_port_suspend_s(&s->waiter, timeout_us) == MT_PORT_RESUMED) ? MT_OK
                                                                             : MT_E_TIMEOUT;
    }
    return st;
}

mt_status_t mt_sem_wait(mt_sem_t *s, uint64_t timeout_us)
{
    mt_status_t st;

    mt_port_lock();
    st = mt_sem_wait_s(s, timeout_us);
    mt_port_unlock();
    return st;
}

void mt_sem_signal_i(mt_sem_t *s)
{
    if (!mt_port_resume_i(&s->waiter)) {
        if ((s->token != 0u) && (s->merged < 0xFFFFFFFFu)) {
            s->merged++;
        }
        s->token = 1u;
    }
}

void mt_sem_signal(mt_sem_t *s)
{
    mt_port_lock();
    mt_sem_signal_i(s);
    mt_port_unlock();
}

void mt_sem_signal_isr(mt_sem_t *s)
{
    mt_port_lock_isr();
    mt_sem_signal_i(s);
    mt_port_unlock_isr();
}

bool mt_sem_valid(const mt_sem_t *s)
{
    return (s->token == 0u) || ((s->token == 1u) && (s->waiter == (mt_port_tref_t)0));
}
