/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sched_note_sample against its ACSL contract (kernel/include/mt/sched.h), translated by
 * tools/acsl2cbmc into mt_sched_note_sample_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_sched_note_sample_contract.h"

void harness(void)
{
    mt_sched_t *s = mtc_sched(MTC_TASKS_MAX);
    uint64_t t = mtc_nondet_u64();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sched_note_sample(s, t));
    mtc_snapshot();
    mt_sched_note_sample(s, t);
    mtc_post_mt_sched_note_sample(s, t);
    MTC_REACH(t == UINT64_MAX && s->loops == UINT64_MAX);
}
