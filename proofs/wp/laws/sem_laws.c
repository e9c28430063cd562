/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file sem_laws.c
 * @brief Data-type laws of the binary semaphore (ardupilot.md §4.3), proved from the public
 *        contracts of mt/sem.h. Sequential, kernel lock held.
 */
#include "mt/sem.h"

/* A signal with nobody waiting makes the next poll succeed. */
/*@ requires held: MtLocked == 1;
    requires inv: MtSemInv(s);
    requires nobody: s->waiter == \null;
    assigns s->token, s->waiter, s->merged, MtPortNow, MtPortHandoffs, MtPortWakes;
    ensures taken: \result == MT_OK && s->token == 0;
    ensures nobody_woken: MtPortWakes == \old(MtPortWakes);
*/
mt_status_t law_sem_signal_then_poll(mt_sem_t *s)
{
    mt_sem_signal_i(s);
    return mt_sem_wait_s(s, 0u);
}

/* Binary: two signals give one token; the second poll times out without blocking. */
/*@ requires held: MtLocked == 1;
    requires inv: MtSemInv(s);
    requires nobody: s->waiter == \null;
    assigns s->token, s->waiter, s->merged, MtPortNow, MtPortHandoffs, MtPortWakes;
    ensures one_token: \result == MT_E_TIMEOUT && s->token == 0;
    ensures merge_counted: s->merged >= \old(s->merged);
*/
mt_status_t law_sem_binary(mt_sem_t *s)
{
    mt_status_t first;

    mt_sem_signal_i(s);
    mt_sem_signal_i(s);
    first = mt_sem_wait_s(s, 0u);
    //@ assert first_ok: first == MT_OK;
    return mt_sem_wait_s(s, 0u);
}

/* wait(0) never creates a token: polling an empty semaphore leaves it empty. */
/*@ requires held: MtLocked == 1;
    requires inv: MtSemInv(s);
    requires empty: s->token == 0 && s->waiter == \null;
    assigns s->token, s->waiter, MtPortNow, MtPortHandoffs;
    ensures no_token_created: \result == MT_E_TIMEOUT && s->token == 0 && s->waiter == \null;
*/
mt_status_t law_sem_poll_empty(mt_sem_t *s)
{
    return mt_sem_wait_s(s, 0u);
}
