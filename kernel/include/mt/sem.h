/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/sem.h
 * @brief Binary semaphore with timeout, signalled from tasks or ISRs.
 *
 * Operating rules
 * - At most one token: signalling twice before a wait leaves one token (the
 *   merge is counted in `merged`, never silent).
 * - One waiter at a time: a second concurrent waiter gets MT_E_BUSY.
 * - A signal that finds a parked waiter hands the token straight to it (the
 *   token never becomes visible to a third party), so no wake-up is lost and a
 *   timed-out wait consumes no token. A signal that races with a timeout finds
 *   the port reference already cleared and leaves the token set.
 * - Function classes: no suffix = task context (takes the kernel lock);
 *   `_s`/`_i` = kernel lock held by the caller; `_isr` = interrupt handler.
 * - The contracts below are sequential; the interleavings of waiters, task
 *   signals and ISR signals are checked by tla/Sem.tla.
 */
#ifndef MT_SEM_H
#define MT_SEM_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/status.h"
#include "mt_port.h"
#include "mt_spec.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    uint32_t token;        /**< 0 or 1 */
    mt_port_tref_t waiter; /**< the parked waiter, or NULL */
    uint32_t merged;       /**< signals that found the token already set (saturating) */
} mt_sem_t;

/*@ predicate MtSemInv(mt_sem_t *s) =
        \valid(s) && (s->token == 0 || s->token == 1) &&
        (s->token == 1 ==> s->waiter == \null);
*/

/** Initialise; `available` makes the first wait succeed at once. [init] */
/*@ requires valid: \valid(s);
    assigns *s;
    ensures inv: MtSemInv(s);
    ensures token: s->token == (available ? 1 : 0);
    ensures no_waiter: s->waiter == \null && s->merged == 0;
*/
void mt_sem_init(mt_sem_t *s, bool available);

/** Take the token, waiting up to timeout_us (0: never block; MT_WAIT_FOREVER:
 *  no limit). S-class: kernel lock held.
 *  @retval MT_OK the token was taken.
 *  @retval MT_E_TIMEOUT no token within the timeout (none consumed).
 *  @retval MT_E_BUSY another task is already waiting. */
/*@ requires held: MtLocked == 1;
    requires inv: MtSemInv(s);
    assigns s->token, s->waiter, MtPortNow;
    ensures held: MtLocked == 1;
    ensures inv: MtSemInv(s);
    behavior token:
      assumes s->token == 1;
      ensures status: \result == MT_OK;
      ensures taken: s->token == 0;
      ensures no_waiter: s->waiter == \old(s->waiter);
    behavior busy:
      assumes s->token == 0 && s->waiter != \null;
      ensures status: \result == MT_E_BUSY;
      ensures unchanged: s->token == 0 && s->waiter == \old(s->waiter);
    behavior poll:
      assumes s->token == 0 && s->waiter == \null && timeout_us == 0;
      ensures status: \result == MT_E_TIMEOUT;
      ensures unchanged: s->token == 0 && s->waiter == \null;
    behavior block:
      assumes s->token == 0 && s->waiter == \null && timeout_us > 0;
      ensures status: \result == MT_OK || \result == MT_E_TIMEOUT;
      ensures no_token_consumed: s->token == 0 && s->waiter == \null;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_sem_wait_s(mt_sem_t *s, uint64_t timeout_us);

/** mt_sem_wait_s() from task context (takes and releases the kernel lock). */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtSemInv(s);
    assigns s->token, s->waiter, MtPortNow, MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtSemInv(s);
    ensures status: \result == MT_OK || \result == MT_E_TIMEOUT || \result == MT_E_BUSY;
    ensures poll_never_blocks: timeout_us == 0 ==> \result != MT_OK ==> \old(s->token) == 0;
*/
mt_status_t mt_sem_wait(mt_sem_t *s, uint64_t timeout_us);

/** Give the token. I-class: kernel lock held (task or ISR). */
/*@ requires held: MtLocked == 1;
    requires inv: MtSemInv(s);
    assigns s->token, s->waiter, s->merged;
    ensures inv: MtSemInv(s);
    ensures no_waiter: s->waiter == \null;
    ensures merged_monotonic: s->merged >= \old(s->merged);
    behavior handoff:
      assumes s->waiter != \null;
      ensures direct: s->token == 0;
    behavior set:
      assumes s->waiter == \null && s->token == 0;
      ensures token: s->token == 1;
    behavior merge:
      assumes s->waiter == \null && s->token == 1;
      ensures token: s->token == 1;
      ensures counted: s->merged == (\old(s->merged) < 0xFFFFFFFF ? \old(s->merged) + 1 : \old(s->merged));
    complete behaviors;
    disjoint behaviors;
*/
void mt_sem_signal_i(mt_sem_t *s);

/** mt_sem_signal_i() from task context. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtSemInv(s);
    assigns s->token, s->waiter, s->merged, MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtSemInv(s);
    ensures given: s->waiter == \null;
*/
void mt_sem_signal(mt_sem_t *s);

/** mt_sem_signal_i() from an interrupt handler. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtSemInv(s);
    assigns s->token, s->waiter, s->merged, MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtSemInv(s);
    ensures given: s->waiter == \null;
*/
void mt_sem_signal_isr(mt_sem_t *s);

/** Constant-time validity check, the C twin of MtSemInv (the object itself must be valid
 *  memory: its precondition). For debug assertions and tests. [lock held, or no other
 *  context running] */
/*@ requires obj: \valid(s);
    assigns \nothing;
    ensures twin: \result != 0 <==> MtSemInv(s);
*/
bool mt_sem_valid(const mt_sem_t *s);

#ifdef __cplusplus
}
#endif

#endif /* MT_SEM_H */
