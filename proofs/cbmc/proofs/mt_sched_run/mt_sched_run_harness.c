/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sched_run against its ACSL contract (kernel/include/mt/sched.h), translated by
 * tools/acsl2cbmc into mt_sched_run_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named.
 * Built twice, each time asserting part of the clauses (CLAUSES in the Makefile): here and in
 * ../mt_sched_run__tasks (assumption B17). */
#include "mtc_objects.h"
#include "mt_sched_run_contract.h"

void harness(void)
{
    mt_sched_t *s = mtc_sched(MTC_TASKS_MAX);
    uint32_t avail = mtc_nondet_u32();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sched_run(s, avail));
    mtc_snapshot();
    uint32_t res = mt_sched_run(s, avail);
    mtc_post_mt_sched_run(s, avail, res);
    MTC_REACH(s->ntasks == MTC_TASKS_MAX && s->st[0].runs == s->tick && s->tick > 0xFFFFFFFF00000000ull);
    MTC_REACH(s->st[2].budget_skips == UINT64_MAX);
    MTC_REACH(s->st[1].slips == UINT64_MAX && s->st[1].runs == s->tick);
}
