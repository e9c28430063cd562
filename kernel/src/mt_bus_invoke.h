/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_bus_invoke.h
 * @brief The topic bus's indirect calls (kernel-private), in the style of mt_invoke.h.
 *
 * Proof assumption A2: a notifier returns with the kernel lock still held and
 * writes neither the topic that calls it nor the kernel lock state; it must not publish
 * (to any topic: the lock is held). It may signal a semaphore or schedule work. The
 * bodies (bus_invoke.c) are the plain call and the poll wake-up, excluded from WP; CBMC
 * replaces mt_bus_invoke_notify with a stub generated from its contract.
 */
#ifndef MT_BUS_INVOKE_H
#define MT_BUS_INVOKE_H

#include "mt/bus.h"
#include "mt_spec.h"

/** Call the notifier fn(arg), the callback of slot `slot` (MT_CALL_NOTIFY(i) for the
 *  topic's notifier i), and count the call in MtCalls[slot] (mt_spec.h). I-class: kernel
 *  lock held. */
/*@ requires held: MtLocked == 1;
    requires callable: fn != \null;
    requires slot: slot < MT_CALL_SLOTS;
    assigns MtPortNow, MtPortWakes, MtCalls[slot];
    ensures time_moves_forward: MtPortNow >= \old(MtPortNow);
    ensures counted: MtCalls[slot] == MtCount64(\old(MtCalls[slot]), 1);
*/
void mt_bus_invoke_notify(mt_bus_notify_fn_t fn, void *arg, uint32_t slot);

/** The poll notifier (registered by mt_sub_poll_enable, called only through
 *  mt_bus_invoke_notify): mt_sem_signal_i() on the subscriber's semaphore `sem`.
 *  The contract is A1's view of every notifier (nothing of the topic is written; the
 *  semaphore it signals is outside the bus's contracts); WP never calls it directly. */
/*@ requires held: MtLocked == 1;
    assigns MtPortNow, MtPortWakes;
    ensures time_moves_forward: MtPortNow >= \old(MtPortNow);
*/
void mt_bus_invoke_wake(void *sem);

/** The poll notifier's argument for sem: sem as `void *` (the pointer conversion is done
 *  here, outside WP's typed memory model). */
/*@ requires valid: \valid(sem);
    assigns \nothing;
    ensures not_null: \result != \null;
*/
void *mt_bus_invoke_wake_arg(mt_sem_t *sem);

#endif /* MT_BUS_INVOKE_H */
