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

/* The abstract state the contracts below are stated in: the token is available; a waiter is
 * parked. A change of representation changes these definitions, not the clauses. Between
 * L1 and L2:
 * - MtSemTook: the caller took the available token (none left; the waiter is kept);
 * - MtSemKept: the token and the waiter are unchanged;
 * - MtSemHandedOver: the parked waiter was resumed with the token (the port delivered a
 *   wake-up: MtPortWakes moved), which never became available, and no merge was counted;
 * - MtSemSet: the token was set, no merge counted, nobody resumed;
 * - MtSemMerged: the token was already set and stays set; the merge is counted
 *   (saturating), nobody resumed.
 * A signal meets exactly one of the last three: it never loses a token. MtSemUnsignalled:
 * no signal was given (token, waiter and merge count unchanged, nobody resumed).
 * MtSemSignalled and
 * MtSemWaited state a whole signal and a whole wait (timeout t, result r) case by case, as the
 * behaviors of mt_sem_signal_i and mt_sem_wait_s do; the task and ISR forms use them. */
/*@ predicate MtSemAvailable(mt_sem_t *s) = s->token == 1;
    predicate MtSemParked(mt_sem_t *s) = s->waiter != \null;

    predicate MtSemTook{L1, L2}(mt_sem_t *s) =
        \at(MtSemAvailable(s), L1) && !\at(MtSemAvailable(s), L2) &&
        \at(s->waiter, L2) == \at(s->waiter, L1);
    predicate MtSemKept{L1, L2}(mt_sem_t *s) =
        \at(s->token, L2) == \at(s->token, L1) && \at(s->waiter, L2) == \at(s->waiter, L1);

    predicate MtSemHandedOver{L1, L2}(mt_sem_t *s) =
        !\at(MtSemAvailable(s), L2) && !\at(MtSemParked(s), L2) &&
        \at(s->merged, L2) == \at(s->merged, L1) &&
        \at(MtPortWakes, L2) != \at(MtPortWakes, L1);
    predicate MtSemSet{L1, L2}(mt_sem_t *s) =
        \at(MtSemAvailable(s), L2) && !\at(MtSemParked(s), L2) &&
        \at(s->merged, L2) == \at(s->merged, L1) &&
        \at(MtPortWakes, L2) == \at(MtPortWakes, L1);
    predicate MtSemMerged{L1, L2}(mt_sem_t *s) =
        \at(MtSemAvailable(s), L2) && !\at(MtSemParked(s), L2) &&
        \at(MtPortWakes, L2) == \at(MtPortWakes, L1) &&
        \at(s->merged, L2) == (\at(s->merged, L1) < 0xFFFFFFFF ? \at(s->merged, L1) + 1
                                                                 : \at(s->merged, L1));

    predicate MtSemUnsignalled{L1, L2}(mt_sem_t *s) =
        MtSemKept{L1, L2}(s) && \at(s->merged, L2) == \at(s->merged, L1) &&
        \at(MtPortWakes, L2) == \at(MtPortWakes, L1);

    predicate MtSemSignalled{L1, L2}(mt_sem_t *s) =
        (\at(MtSemParked(s), L1) ==> MtSemHandedOver{L1, L2}(s)) &&
        (!\at(MtSemParked(s), L1) && !\at(MtSemAvailable(s), L1) ==> MtSemSet{L1, L2}(s)) &&
        (!\at(MtSemParked(s), L1) && \at(MtSemAvailable(s), L1) ==> MtSemMerged{L1, L2}(s));

    predicate MtSemWaited{L1, L2}(mt_sem_t *s, integer t, integer r) =
        (\at(MtSemAvailable(s), L1) ==> r == MT_OK && MtSemTook{L1, L2}(s)) &&
        (!\at(MtSemAvailable(s), L1) && \at(MtSemParked(s), L1) ==>
            r == MT_E_BUSY && MtSemKept{L1, L2}(s)) &&
        (!\at(MtSemAvailable(s), L1) && !\at(MtSemParked(s), L1) && t == 0 ==>
            r == MT_E_TIMEOUT && MtSemKept{L1, L2}(s)) &&
        (!\at(MtSemAvailable(s), L1) && !\at(MtSemParked(s), L1) && t > 0 ==>
            (r == MT_OK || r == MT_E_TIMEOUT) &&
            (r == MT_OK <==> \at(MtPortHandoffs, L2) != \at(MtPortHandoffs, L1)) &&
            !\at(MtSemAvailable(s), L2) && !\at(MtSemParked(s), L2)) &&
        (\at(MtPortHandoffs, L2) != \at(MtPortHandoffs, L1) ==>
            !\at(MtSemAvailable(s), L1) && !\at(MtSemParked(s), L1) && t > 0);
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
 *  no limit). S-class: kernel lock held. MT_OK means the caller took the token, or
 *  was parked and handed it by a signal (MtPortHandoffs moved).
 *  @retval MT_OK the token was taken.
 *  @retval MT_E_TIMEOUT no token within the timeout (none consumed).
 *  @retval MT_E_BUSY another task is already waiting. */
/*@ requires held: MtLocked == 1;
    requires inv: MtSemInv(s);
    assigns s->token, s->waiter, MtPortNow, MtPortHandoffs;
    ensures held: MtLocked == 1;
    ensures inv: MtSemInv(s);
    ensures parked_to_block: MtPortHandoffs != \old(MtPortHandoffs) ==>
        \old(!MtSemAvailable(s) && !MtSemParked(s)) && timeout_us > 0;
    behavior token:
      assumes MtSemAvailable(s);
      ensures status: \result == MT_OK;
      ensures taken: MtSemTook{Pre, Post}(s);
    behavior busy:
      assumes !MtSemAvailable(s) && MtSemParked(s);
      ensures status: \result == MT_E_BUSY;
      ensures unchanged: MtSemKept{Pre, Post}(s);
    behavior poll:
      assumes !MtSemAvailable(s) && !MtSemParked(s) && timeout_us == 0;
      ensures status: \result == MT_E_TIMEOUT;
      ensures unchanged: MtSemKept{Pre, Post}(s);
    behavior block:
      assumes !MtSemAvailable(s) && !MtSemParked(s) && timeout_us > 0;
      ensures status: \result == MT_OK || \result == MT_E_TIMEOUT;
      ensures handed: \result == MT_OK <==> MtPortHandoffs != \old(MtPortHandoffs);
      ensures no_token_consumed: !MtSemAvailable(s) && !MtSemParked(s);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_sem_wait_s(mt_sem_t *s, uint64_t timeout_us);

/** mt_sem_wait_s() from task context (takes and releases the kernel lock): the same
 *  outcomes. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtSemInv(s);
    assigns s->token, s->waiter, MtPortNow, MtPortHandoffs, MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtSemInv(s);
    ensures waited: MtSemWaited{Pre, Post}(s, timeout_us, \result);
*/
mt_status_t mt_sem_wait(mt_sem_t *s, uint64_t timeout_us);

/** Give the token. I-class: kernel lock held (task or ISR). A parked waiter is resumed
 *  with it (the port delivers a wake-up); else the token is set; else (already set) the
 *  merge is counted. */
/*@ requires held: MtLocked == 1;
    requires inv: MtSemInv(s);
    assigns s->token, s->waiter, s->merged, MtPortWakes;
    ensures inv: MtSemInv(s);
    behavior handoff:
      assumes MtSemParked(s);
      ensures direct: MtSemHandedOver{Pre, Post}(s);
    behavior set:
      assumes !MtSemParked(s) && !MtSemAvailable(s);
      ensures token: MtSemSet{Pre, Post}(s);
    behavior merge:
      assumes !MtSemParked(s) && MtSemAvailable(s);
      ensures counted: MtSemMerged{Pre, Post}(s);
    complete behaviors;
    disjoint behaviors;
*/
void mt_sem_signal_i(mt_sem_t *s);

/** mt_sem_signal_i() from task context: the same outcomes. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtSemInv(s);
    assigns s->token, s->waiter, s->merged, MtPortWakes, MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtSemInv(s);
    ensures given: MtSemSignalled{Pre, Post}(s);
*/
void mt_sem_signal(mt_sem_t *s);

/** mt_sem_signal_i() from an interrupt handler: the same outcomes. */
/*@ requires not_held: MtLocked == 0;
    requires inv: MtSemInv(s);
    assigns s->token, s->waiter, s->merged, MtPortWakes, MtLocked;
    ensures released: MtLocked == 0;
    ensures inv: MtSemInv(s);
    ensures given: MtSemSignalled{Pre, Post}(s);
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
