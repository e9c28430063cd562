/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sched_validate against its ACSL contract (kernel/include/mt/sched.h), translated by
 * tools/acsl2cbmc into mt_sched_validate_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_sched_validate_contract.h"

void harness(void)
{
    uint32_t n = mtc_nondet_u32();                    /* 0, 1..MTC_TASKS_MAX, or above the table maximum */
    __CPROVER_assume(n <= MTC_TASKS_MAX || n > MT_CFG_SCHED_MAX_TASKS);
    mt_task_t *tasks = mtc_tasks(n >= 1u && n <= MTC_TASKS_MAX ? n : 1u);
    uint32_t rate = mtc_loop_rate(1);               /* valid and invalid rates (B13) */
    mtc_task_rates(tasks, n >= 1u && n <= MTC_TASKS_MAX ? n : 1u, rate);
    uint32_t *bad_index = (uint32_t *)mtc_alloc(1u, sizeof(uint32_t), MTC_K_BYTES);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sched_validate(tasks, n, rate, bad_index));
    mtc_snapshot();
    mt_status_t res = mt_sched_validate(tasks, n, rate, bad_index);
    mtc_post_mt_sched_validate(tasks, n, rate, bad_index, res);

    MTC_REACH(res == MT_OK && n == MTC_TASKS_MAX);
    MTC_REACH(res == MT_E_TASK_COUNT && n == 0xFFFFFFFFu);
    MTC_REACH(res == MT_E_TASK_ORDER && *bad_index == 2u);
}
