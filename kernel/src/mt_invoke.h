/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_invoke.h
 * @brief The kernel's only indirect calls (kernel-private).
 *
 * WP cannot follow a function pointer, so every callback goes through one of
 * these functions. Their contracts are proof assumption A1 (listed in the
 * proof report): a callback returns, and does not write the kernel object
 * that called it, nor the kernel lock state. Each call names the callback's
 * slot (MT_CALL_* in mt_spec.h) and counts one call in the ghost MtCalls[slot],
 * so a caller's contract can say which callbacks ran and how often. Their
 * bodies (invoke.c) are the plain call and are excluded from WP; CBMC replaces
 * them with stubs generated from these contracts.
 */
#ifndef MT_INVOKE_H
#define MT_INVOKE_H

#include <stdint.h>

#include "mt_spec.h"

/** Call fn(arg), the callback of slot `slot`. */
/*@ requires callable: fn != \null;
    requires slot: slot < MT_CALL_SLOTS;
    assigns MtPortNow, MtPortWakes, MtCalls[slot];
    ensures time_moves_forward: MtPortNow >= \old(MtPortNow);
    ensures counted: MtCalls[slot] == MtCount64(\old(MtCalls[slot]), 1);
*/
void mt_invoke(void (*fn)(void *), void *arg, uint32_t slot);

/** Call fn(arg), the callback of slot `slot`, and return its result (a sample-wait
 *  function). */
/*@ requires callable: fn != \null;
    requires slot: slot < MT_CALL_SLOTS;
    assigns MtPortNow, MtPortWakes, MtCalls[slot];
    ensures time_moves_forward: MtPortNow >= \old(MtPortNow);
    ensures counted: MtCalls[slot] == MtCount64(\old(MtCalls[slot]), 1);
*/
uint64_t mt_invoke_u64(uint64_t (*fn)(void *), void *arg, uint32_t slot);

#endif /* MT_INVOKE_H */
