/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_wq_run_pending against its ACSL contract (kernel/include/mt/wq.h), translated by
 * tools/acsl2cbmc into mt_wq_run_pending_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_wq_run_pending_contract.h"

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    uint32_t max = mtc_nondet_u32();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_wq_run_pending(q, max));
    mtc_snapshot();
    uint32_t res = mt_wq_run_pending(q, max);
    mtc_post_mt_wq_run_pending(q, max, res);

    MTC_REACH(res == MT_CFG_WQ_MAX_ITEMS && max == 0xFFFFFFFFu && q->count == 0u);
    MTC_REACH(res == 1u && max == 1u && q->count == 1u);
    MTC_REACH(res == 0u && MTC_OLDV(q->running) != MT_WQ_NONE);
}
