/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file proc_laws.c
 * @brief Laws of the timer/IO proc sets (ardupilot.md §4.2), proved from the public
 *        contracts of mt/proc.h.
 */
#include "mt/proc.h"

/* Registration is bounded and reported: a full set never accepts another proc, and a
 * registration either appends exactly one entry or changes nothing. */
/*@ requires held: MtLocked == 1;
    requires inv: MtProcSetInv(p);
    assigns p->procs[p->count], p->count;
    ensures bounded: p->count <= MT_CFG_PROC_MAX;
    ensures reported: \result == MT_OK ==> p->count == \old(p->count) + 1 && \old(p->count) < MT_CFG_PROC_MAX;
    ensures full_refused: \old(p->count) == MT_CFG_PROC_MAX ==> \result != MT_OK;
*/
mt_status_t law_proc_register_bounded(mt_proc_set_t *p, mt_proc_fn_t fn, void *arg)
{
    return mt_proc_register_i(p, fn, arg);
}

/* Registered procs are kept: registering a second proc keeps the first, and after two
 * successful registrations both are registered. */
/*@ requires held: MtLocked == 1;
    requires inv: MtProcSetInv(p);
    requires empty: p->count == 0;
    requires distinct: f != g;
    assigns p->procs[0 .. MT_CFG_PROC_MAX - 1], p->count;
    ensures both: \result == MT_OK ==> MtProcRegistered(p, f, \null) && MtProcRegistered(p, g, \null);
*/
mt_status_t law_proc_register_keeps(mt_proc_set_t *p, mt_proc_fn_t f, mt_proc_fn_t g)
{
    mt_status_t st = mt_proc_register_i(p, f, (void *)0);
    if (st != MT_OK) {
        return st;
    }
    return mt_proc_register_i(p, g, (void *)0);
}
