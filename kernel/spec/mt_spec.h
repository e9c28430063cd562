/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_spec.h
 * @brief ACSL logic shared by every module: the ghost state of the port and of
 *        the callback trampolines.
 *
 * Besides ACSL (inside annotation comments) this header holds only the
 * MT_CALL_* slot macros below; it declares nothing to a C compiler.
 *
 * - MtLocked: 1 while the kernel lock is held by the caller, 0 otherwise. The
 *   function-class suffix is a proof obligation through it: `_i` functions
 *   require MtLocked == 1, plain functions require MtLocked == 0 and take the
 *   lock themselves.
 * - MtPortNow: the last value returned by mt_port_now_us(); the port's time is
 *   monotonic (see mt_port.h).
 * - MtPortHandoffs: the wake-ups the calling thread has been handed by
 *   mt_port_resume_i() while parked, counted modulo 2^64. A park that ends by a
 *   hand-off changes it; a park that times out, and every other call, leave it.
 *   This is how a contract says "the caller was handed the token".
 * - MtPortWakes: the wake-ups mt_port_resume_i() has delivered to parked threads, counted
 *   modulo 2^64. A resume that finds a parked thread changes it; one that finds none, and
 *   every other port call, leave it. This is how a contract says "the parked waiter was
 *   resumed" (mt_sem_signal_i's hand-off). A callback may signal a semaphore (assumption
 *   A1), so every trampoline may change it too.
 * - MtCalls[slot]: how many times the kernel has called the callback of a slot
 *   through its trampoline (mt_invoke.h), modulo 2^64 (MtCount64). Only a trampoline's
 *   contract changes it, so "task i ran once" is the postcondition
 *   MtCalls[MT_CALL_TASK(i)] == MtCount64(\old(MtCalls[MT_CALL_TASK(i)]), 1)
 *   (assumption A1).
 * - MtSeqRacing: holds in a run where a writer in another context may store a seqlock
 *   slot (a topic's stamp and message bytes, mt/bus.h) while a reader copies that slot
 *   without the lock. An environment choice: declared, never defined, assigned by no
 *   function (assumption C3). Without it (the sequential case, every single-context use)
 *   the stamp re-check reads what the slot holds, and a contract can say that a copy is
 *   never torn; with it, the re-check may see any newer stamp.
 *
 * The callback slots (MT_CALL_*, used by the trampolines' callers): one per
 * scheduler task, one per timer proc, the sample wait, one per work-queue item
 * (all counted through mt_invoke.h), one per notifier of a topic (counted through
 * mt_bus_invoke.h), and, reserved, the mission's command start, verify and done
 * callbacks (their trampoline, mt_mission_invoke.h, does not count calls yet). A slot is a
 * position in its kernel object (task i of the running scheduler, item k of the
 * queue being run), not a global name: contracts compare counts before and
 * after one call.
 */
#ifndef MT_SPEC_H
#define MT_SPEC_H

#include "mt/config.h"

#define MT_CALL_TASK(i) (i)
#define MT_CALL_PROC(k) (MT_CFG_SCHED_MAX_TASKS + (k))
#define MT_CALL_WAIT (MT_CFG_SCHED_MAX_TASKS + MT_CFG_PROC_MAX)
#define MT_CALL_WORK(k) (MT_CALL_WAIT + 1u + (k))
#define MT_CALL_MISSION_START (MT_CALL_WAIT + 1u + MT_CFG_WQ_MAX_ITEMS)
#define MT_CALL_MISSION_VERIFY (MT_CALL_MISSION_START + 1u)
#define MT_CALL_MISSION_DONE (MT_CALL_MISSION_START + 2u)
#define MT_CALL_NOTIFY(k) (MT_CALL_MISSION_START + 3u + (k))
#define MT_CALL_SLOTS (MT_CALL_MISSION_START + 3u + MT_CFG_BUS_MAX_NOTIFY)

/*@ ghost int MtLocked; */
/*@ ghost unsigned long long MtPortNow; */
/*@ ghost unsigned long long MtPortHandoffs; */
/*@ ghost unsigned long long MtPortWakes; */
/* long long: no kernel object has a field of that type, so in WP's typed memory model the
 * counters share no memory with kernel state and no frame goal has to separate them. */
/*@ ghost long long MtCalls[MT_CALL_SLOTS]; */

/*@ axiomatic MtSeqEnvironment {
      predicate MtSeqRacing;
    }
*/

/* A count n steps on from x, wrapping as a 64-bit two's complement counter does (for x a
 * long long and n 0 or 1, the only uses; no division, so that neither WP nor CBMC has to
 * reason about a modulus). */
/*@ logic integer MtCount64(integer x, integer n) =
        x + n <= 0x7FFFFFFFFFFFFFFF ? x + n : x + n - 0xFFFFFFFFFFFFFFFF - 1;
*/

/*@ predicate MtUnlocked = MtLocked == 0;
    predicate MtLockHeld = MtLocked == 1;
*/

#endif /* MT_SPEC_H */
