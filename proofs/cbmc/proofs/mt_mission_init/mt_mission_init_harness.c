/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_init against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc.py into mt_mission_init_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_init_contract.h"

void harness(void)
{
    mt_mission_t *m = mtc_mission();
    mt_mission_cmd_fn_t start_fn = mtc_nondet_bool() ? (mt_mission_cmd_fn_t)mtc_callback() : 0;
    mt_mission_cmd_fn_t verify_fn = mtc_nondet_bool() ? (mt_mission_cmd_fn_t)mtc_callback() : 0;
    mt_mission_done_fn_t complete_fn = mtc_nondet_bool() ? (mt_mission_done_fn_t)mtc_callback() : 0;
    void *ctx = mtc_nondet_bool() ? mtc_callback() : (void *)0;
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_mission_init(m, start_fn, verify_fn, complete_fn, ctx));
    mtc_snapshot();
    mt_mission_init(m, start_fn, verify_fn, complete_fn, ctx);
    mtc_post_mt_mission_init(m, start_fn, verify_fn, complete_fn, ctx);

    MTC_REACH(ctx == (void *)0 && MTC_OLDV(m->state) == MT_MISSION_RUNNING);
}
