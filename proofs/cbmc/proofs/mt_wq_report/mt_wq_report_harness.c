/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_wq_report against its ACSL contract (kernel/include/mt/wq.h), translated by
 * tools/acsl2cbmc into mt_wq_report_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_wq_report_contract.h"

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    mt_wq_report_t *r = MTC_NEW(mt_wq_report_t, 1u);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_wq_report(q, r));
    mtc_snapshot();
    mt_wq_report(q, r);
    mtc_post_mt_wq_report(q, r);

    MTC_REACH(r->mean_run_us == 0xFFFFFFFFu && r->runs == 1u);
    MTC_REACH(r->mean_interval_us == 0xFFFFFFFFu && r->starts == 2u);
    MTC_REACH(r->items == MT_CFG_WQ_MAX_ITEMS && r->depth == MT_CFG_WQ_MAX_ITEMS &&
              r->refused == 0xFFFFFFFFu);
}
