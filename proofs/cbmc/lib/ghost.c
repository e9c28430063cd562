/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file ghost.c
 * @brief The ghost variables of kernel/spec/mt_spec.h as real C globals in the CBMC build,
 *        maintained by the port stubs (generated mtc_stubs.c), and their pre-call copies.
 */
#include "mtc_logic.h"
#include "mt_spec.h" /* MT_CALL_SLOTS */

int MtLocked;
unsigned long long MtPortNow;
unsigned long long MtPortHandoffs;
unsigned long long MtPortWakes;
int mtc_old_MtLocked;
unsigned long long mtc_old_MtPortNow;
unsigned long long mtc_old_MtPortHandoffs;
unsigned long long mtc_old_MtPortWakes;
long long MtCalls[MT_CALL_SLOTS];
long long mtc_old_MtCalls[MT_CALL_SLOTS];

/* Any lock state, any time, any hand-off and wake-up count and any call counts: the function's requires
 * then selects the legal ones. */
void mtc_ghosts_nondet(void)
{
    MtLocked = (int)mtc_nondet_i32();
    MtPortNow = mtc_nondet_u64();
    MtPortHandoffs = mtc_nondet_u64();
    MtPortWakes = mtc_nondet_u64();
    __CPROVER_havoc_object(MtCalls);
}

void mtc_snapshot_ghosts(void)
{
    mtc_old_MtLocked = MtLocked;
    mtc_old_MtPortNow = MtPortNow;
    mtc_old_MtPortHandoffs = MtPortHandoffs;
    mtc_old_MtPortWakes = MtPortWakes;
    __CPROVER_array_copy(mtc_old_MtCalls, MtCalls);
}
