/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_work_schedule_isr against its ACSL contract (kernel/include/mt/wq.h), translated by
 * tools/acsl2cbmc into mt_work_schedule_isr_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_work_schedule_isr_contract.h"

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    mt_work_t *w = mtc_work(q);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_work_schedule_isr(w));
    mtc_snapshot();
    mt_status_t res = mt_work_schedule_isr(w);
    mtc_post_mt_work_schedule_isr(w, res);

    MTC_REACH(res == MT_OK && q->count == MT_CFG_WQ_MAX_ITEMS && q->head == MT_CFG_WQ_MAX_ITEMS - 1u);
    MTC_REACH(res == MT_W_WQ_MERGED && q->slot[w->slot].stats.merged == 0xFFFFFFFFu &&
              q->stats.merged == 0xFFFFFFFFu);
    MTC_REACH(res == MT_OK && q->slot[w->slot].queued_us == UINT64_MAX);
}
