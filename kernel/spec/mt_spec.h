/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_spec.h
 * @brief ACSL logic shared by every module: the ghost state of the port.
 *
 * Only ACSL lives here (inside annotation comments): to a C compiler this
 * header is empty.
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
 */
#ifndef MT_SPEC_H
#define MT_SPEC_H

/*@ ghost int MtLocked; */
/*@ ghost unsigned long long MtPortNow; */
/*@ ghost unsigned long long MtPortHandoffs; */

/*@ predicate MtUnlocked = MtLocked == 0;
    predicate MtLockHeld = MtLocked == 1;
*/

#endif /* MT_SPEC_H */
