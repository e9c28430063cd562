/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sched_end_loop against its ACSL contract (kernel/include/mt/sched.h), translated by
 * tools/acsl2cbmc into mt_sched_end_loop_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_sched_end_loop_contract.h"

void harness(void)
{
    mt_sched_t *s = mtc_sched(MTC_TASKS_MAX);
    uint32_t spare = mtc_nondet_u32();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sched_end_loop(s, spare));
    mtc_snapshot();
    mt_sched_end_loop(s, spare);
    mtc_post_mt_sched_end_loop(s, spare);
    MTC_REACH(s->extra_us == MT_SCHED_EXTRA_MAX_US && spare == 0xFFFFFFFFu);
}
