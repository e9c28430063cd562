/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_work_schedule_interval against its ACSL contract (kernel/include/mt/wq_timer.h), translated by
 * tools/acsl2cbmc into mt_work_schedule_interval_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_work_schedule_interval_contract.h"

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    mt_work_t *w = mtc_work(q);
    mtc_ghosts_nondet();
    uint32_t period_us = mtc_nondet_u32();
    uint32_t delay_us = mtc_nondet_u32();

    __CPROVER_assume(mtc_pre_mt_work_schedule_interval(w, period_us, delay_us));
    mtc_snapshot();
    mt_status_t res = mt_work_schedule_interval(w, period_us, delay_us);
    mtc_post_mt_work_schedule_interval(w, period_us, delay_us, res);

    MTC_REACH(res == MT_OK && period_us == 0xFFFFFFFFu && q->slot[w->slot].deadline_us == UINT64_MAX);
    MTC_REACH(res == MT_E_INVALID);
}
