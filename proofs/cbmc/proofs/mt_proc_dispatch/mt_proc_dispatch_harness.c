/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_proc_dispatch against its ACSL contract (kernel/include/mt/proc.h), translated by
 * tools/acsl2cbmc into mt_proc_dispatch_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_proc_dispatch_contract.h"

void harness(void)
{
    mt_proc_set_t *p = mtc_proc_set();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_proc_dispatch(p));
    mtc_snapshot();
    mt_status_t res = mt_proc_dispatch(p);
    mtc_post_mt_proc_dispatch(p, res);

    MTC_REACH(res == MT_OK && p->count == MT_CFG_PROC_MAX);
    MTC_REACH(res == MT_OK && p->procs[0].calls == 0xFFFFFFFFu && p->procs[0].total_us == UINT64_MAX);
    MTC_REACH(res == MT_E_BUSY && p->refused == 0xFFFFFFFFu);
}
