/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_work_notify_i against its ACSL contract (kernel/include/mt/wq.h), translated by
 * tools/acsl2cbmc into mt_work_notify_i_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_work_notify_i_contract.h"

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    mt_work_t *w = mtc_work(q);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_work_notify_i((void *)w));
    mtc_snapshot();
    mt_work_notify_i((void *)w);
    mtc_post_mt_work_notify_i((void *)w);

    MTC_REACH(q->count == MT_CFG_WQ_MAX_ITEMS && MTC_OLDV(q->count) == MT_CFG_WQ_MAX_ITEMS - 1u);
    MTC_REACH(q->slot[w->slot].stats.merged == 0xFFFFFFFFu && q->stats.merged == 0xFFFFFFFFu);
}
