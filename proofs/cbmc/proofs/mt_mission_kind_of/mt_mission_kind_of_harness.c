/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_kind_of against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_kind_of_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_kind_of_contract.h"

void harness(void)
{
    uint16_t id = mtc_nondet_u16(); /* any id, known or not */
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_mission_kind_of(id));
    mtc_snapshot();
    uint8_t res = mt_mission_kind_of(id);
    mtc_post_mt_mission_kind_of(id, res);

    MTC_REACH(res == MT_MISSION_KIND_NAV && id == 42703u); /* last entry of the table */
    MTC_REACH(res == MT_MISSION_KIND_DO);
    MTC_REACH(res == MT_MISSION_KIND_JUMP && id == MT_MAV_CMD_DO_JUMP_TAG);
    MTC_REACH(res == MT_MISSION_KIND_TAG);
    MTC_REACH(res == MT_MISSION_KIND_HOME && id == 0xFFFFu); /* unknown id */
}
