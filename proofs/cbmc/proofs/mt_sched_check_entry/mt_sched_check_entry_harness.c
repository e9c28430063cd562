/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sched_check_entry against its ACSL contract (kernel/include/mt/sched.h), translated by
 * tools/acsl2cbmc into mt_sched_check_entry_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_sched_check_entry_contract.h"

void harness(void)
{
    uint32_t n = mtc_nondet_u32();
    __CPROVER_assume(n >= 1u && n <= MTC_TASKS_MAX);
    mt_task_t *tasks = mtc_tasks(n);
    uint32_t i = mtc_nondet_u32();
    uint32_t rate = mtc_loop_rate(1);               /* valid and invalid rates (B13) */
    mtc_task_rates(tasks, n >= 1u && n <= MTC_TASKS_MAX ? n : 1u, rate);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sched_check_entry(tasks, n, i, rate));
    mtc_snapshot();
    mt_status_t res = mt_sched_check_entry(tasks, n, i, rate);
    mtc_post_mt_sched_check_entry(tasks, n, i, rate, res);

    MTC_REACH(res == MT_OK && rate == MT_SCHED_RATE_MAX && tasks[i].rate_mhz == rate * 1000u);
    MTC_REACH(res == MT_E_TASK_ORDER);
}
