/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_invoke.h
 * @brief The kernel's only indirect calls (kernel-private).
 *
 * WP cannot follow a function pointer, so every callback goes through one of
 * these functions. Their contracts are proof assumption A1 (listed in the
 * proof report): a callback returns, and does not write the kernel object
 * that called it, nor the kernel lock state. Their bodies (invoke.c) are the
 * plain call and are excluded from WP; CBMC harnesses replace the callback
 * with a stub that obeys the same assumption.
 */
#ifndef MT_INVOKE_H
#define MT_INVOKE_H

#include <stdint.h>

#include "mt_spec.h"

/** Call fn(arg). */
/*@ requires callable: fn != \null;
    assigns MtPortNow;
    ensures time_moves_forward: MtPortNow >= \old(MtPortNow);
*/
void mt_invoke(void (*fn)(void *), void *arg);

/** Call fn(arg) and return its result (a sample-wait function). */
/*@ requires callable: fn != \null;
    assigns MtPortNow;
    ensures time_moves_forward: MtPortNow >= \old(MtPortNow);
*/
uint64_t mt_invoke_u64(uint64_t (*fn)(void *), void *arg);

#endif /* MT_INVOKE_H */
