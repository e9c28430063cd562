/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_work_run_wait against its ACSL contract (kernel/include/mt/wq.h), translated by
 * tools/acsl2cbmc into mt_work_run_wait_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_work_run_wait_contract.h"

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    mt_work_t *w = mtc_work(q);
    mtc_ghosts_nondet();
    uint64_t timeout_us = mtc_nondet_u64();

    __CPROVER_assume(mtc_pre_mt_work_run_wait(w, timeout_us));
    mtc_snapshot();
    mt_status_t res = mt_work_run_wait(w, timeout_us);
    mtc_post_mt_work_run_wait(w, timeout_us, res);

    MTC_REACH(res == MT_E_BUSY);
    MTC_REACH(res == MT_E_TIMEOUT && timeout_us == MT_WAIT_FOREVER);
    MTC_REACH(res == MT_E_TIMEOUT && timeout_us == 0u && q->slot[w->slot].stats.merged == 0xFFFFFFFFu);
}
