/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_proc_register_i against its ACSL contract (kernel/include/mt/proc.h), translated by
 * tools/acsl2cbmc into mt_proc_register_i_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_proc_register_i_contract.h"

void harness(void)
{
    mt_proc_set_t *p = mtc_proc_set();
    /* fn: NULL, a new callback, or one already in the table (duplicate); arg likewise */
    uint32_t k = mtc_nondet_u32();
    __CPROVER_assume(k < MT_CFG_PROC_MAX);
    uint8_t sel = mtc_nondet_u8();
    mt_proc_fn_t fn = sel == 0u ? (mt_proc_fn_t)0
                    : sel == 1u ? (mt_proc_fn_t)mtc_callback() : p->procs[k].fn;
    void *arg = mtc_nondet_bool() ? p->procs[k].arg : (void *)0;
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_proc_register_i(p, fn, arg));
    mtc_snapshot();
    mt_status_t res = mt_proc_register_i(p, fn, arg);
    mtc_post_mt_proc_register_i(p, fn, arg, res);

    MTC_REACH(res == MT_OK && p->count == MT_CFG_PROC_MAX);
    MTC_REACH(res == MT_E_DUPLICATE);
    MTC_REACH(res == MT_E_FULL);
}
