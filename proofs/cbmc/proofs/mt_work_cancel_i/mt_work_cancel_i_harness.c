/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_work_cancel_i against its ACSL contract (kernel/include/mt/wq_timer.h), translated by
 * tools/acsl2cbmc into mt_work_cancel_i_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_work_cancel_i_contract.h"

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    mt_work_t *w = mtc_work(q);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_work_cancel_i(w));
    mtc_snapshot();
    mt_status_t res = mt_work_cancel_i(w);
    mtc_post_mt_work_cancel_i(w, res);

    MTC_REACH(res == MT_OK && MTC_OLDV(q->slot[w->slot].timer) == MT_WQ_TIMER_EVERY);
    MTC_REACH(res == MT_OK && MTC_OLDV(q->slot[w->slot].timer) == MT_WQ_TIMER_ONCE);
    MTC_REACH(res == MT_E_STATE);
}
