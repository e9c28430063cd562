/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_jump_count against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_jump_count_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_jump_count_contract.h"

void harness(void)
{
    mt_mission_t *m = mtc_mission();
    uint16_t i = mtc_nondet_u16();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_mission_jump_count(m, i));
    mtc_snapshot();
    int32_t res = mt_mission_jump_count(m, i);
    mtc_post_mt_mission_jump_count(m, i, res);

    MTC_REACH(res == MT_MISSION_REPEAT_MAX); /* a counter at the largest repeat count */
    MTC_REACH(res > 0 && i == MT_CFG_MISSION_MAX_CMDS - 1u);
    MTC_REACH(res == 0 && i == 0u);
    MTC_REACH(res == 0 && i >= 1u && i < m->total && m->kind[i] == MT_MISSION_KIND_JUMP &&
              m->repeat[i] == -1);
}
