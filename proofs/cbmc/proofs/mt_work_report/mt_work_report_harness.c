/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_work_report against its ACSL contract (kernel/include/mt/wq.h), translated by
 * tools/acsl2cbmc into mt_work_report_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_work_report_contract.h"

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    mt_work_t *w = mtc_work(q);
    mtc_ghosts_nondet();
    mt_work_report_t *r = MTC_NEW(mt_work_report_t, 1u);

    __CPROVER_assume(mtc_pre_mt_work_report(w, r));
    mtc_snapshot();
    mt_work_report(w, r);
    mtc_post_mt_work_report(w, r);

    MTC_REACH(r->mean_run_us == 0xFFFFFFFFu && r->runs == 1u);
    MTC_REACH(r->mean_interval_us == 0xFFFFFFFFu && r->rate_mhz == 0u);
    MTC_REACH(r->rate_mhz == 1000000000u && r->starts == UINT64_MAX);
    MTC_REACH(r->queued == 1u && r->running == 1u && r->period_us == 0xFFFFFFFFu);
}
