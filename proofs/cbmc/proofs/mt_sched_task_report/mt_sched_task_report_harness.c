/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sched_task_report against its ACSL contract (kernel/include/mt/sched.h), translated by
 * tools/acsl2cbmc into mt_sched_task_report_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_sched_task_report_contract.h"

void harness(void)
{
    mt_sched_t *s = mtc_sched(MTC_TASKS_MAX);
    uint32_t i = mtc_nondet_u32();
    mt_task_report_t *r = MTC_NEW(mt_task_report_t, 1u);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sched_task_report(s, i, r));
    mtc_snapshot();
    mt_sched_task_report(s, i, r);
    mtc_post_mt_sched_task_report(s, i, r);
    MTC_REACH(r->mean_us == 0xFFFFFFFFu && r->pending > 0xFFFFFFFFull);
}
