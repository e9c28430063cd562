/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sched_reset_stats against its ACSL contract (kernel/include/mt/sched.h), translated by
 * tools/acsl2cbmc into mt_sched_reset_stats_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_sched_reset_stats_contract.h"

void harness(void)
{
    mt_sched_t *s = mtc_sched(MTC_TASKS_MAX);

    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sched_reset_stats(s));
    mtc_snapshot();
    mt_sched_reset_stats(s);
    mtc_post_mt_sched_reset_stats(s);
    MTC_REACH(s->st[0].interval == MT_SCHED_RATE_MAX * 1000u && s->st[0].runs == 0u);
}
