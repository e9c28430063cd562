/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sched_loop_once against its ACSL contract (kernel/include/mt/sched.h), translated by
 * tools/acsl2cbmc into mt_sched_loop_once_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_sched_loop_once_contract.h"

void harness(void)
{
    mt_sched_t *s = mtc_sched(MTC_TASKS_MAX);
    mt_sample_wait_fn_t wait = (mt_sample_wait_fn_t)mtc_callback();
    void *ctx = (void *)0;
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sched_loop_once(s, wait, ctx));
    mtc_snapshot();
    mt_sched_loop_once(s, wait, ctx);
    mtc_post_mt_sched_loop_once(s, wait, ctx);
    MTC_REACH(s->tick == 0xFFFFFFFFFFFFFFFEull && s->st[0].runs == s->tick);
}
