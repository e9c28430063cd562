/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_check_cmd against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_check_cmd_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_check_cmd_contract.h"

void harness(void)
{
    /* a candidate list of 1..MT_CFG_MISSION_MAX_CMDS commands, every field nondeterministic */
    uint32_t len = mtc_nondet_u32();
    __CPROVER_assume(len >= 1u && len <= MT_CFG_MISSION_MAX_CMDS);
    mt_mission_cmd_t *cmds = mtc_mission_cmds(len);
    uint16_t n = mtc_nondet_u16();
    uint16_t i = mtc_nondet_u16();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_mission_check_cmd(cmds, n, i));
    mtc_snapshot();
    mt_status_t res = mt_mission_check_cmd(cmds, n, i);
    mtc_post_mt_mission_check_cmd(cmds, n, i, res);

    MTC_REACH(res == MT_OK && i == 0u);
    MTC_REACH(res == MT_OK && cmds[i].id == MT_MAV_CMD_DO_JUMP && cmds[i].param[1] == -1000);
    MTC_REACH(res == MT_OK && cmds[i].id == MT_MAV_CMD_DO_JUMP_TAG &&
              cmds[i].param[1] == 32767000 && cmds[i].param[0] == 65535000);
    MTC_REACH(res == MT_OK && cmds[i].id == MT_MAV_CMD_CONDITION_YAW);
    MTC_REACH(res == MT_OK && cmds[i].id == MT_MAV_CMD_WAYPOINT && cmds[i].x == -900000000 &&
              cmds[i].y == 1800000000 && cmds[i].param[3] == MT_MISSION_PARAM_NAN);
    MTC_REACH(res == MT_E_MISSION_CMD && i == 0u && cmds[0].id == MT_MAV_CMD_TAKEOFF);
    MTC_REACH(res == MT_E_MISSION_CMD && i > 0u);
    MTC_REACH(res == MT_E_MISSION_PARAM && cmds[i].id == MT_MAV_CMD_DO_SET_SERVO);
    MTC_REACH(res == MT_E_MISSION_PARAM && cmds[i].param[0] == MT_MISSION_PARAM_NAN);
    MTC_REACH(res == MT_E_MISSION_LOCATION);
    MTC_REACH(res == MT_E_MISSION_FRAME);
    MTC_REACH(res == MT_E_MISSION_JUMP && cmds[i].id == MT_MAV_CMD_DO_JUMP);
    MTC_REACH(res == MT_E_MISSION_JUMP && cmds[i].id == MT_MAV_CMD_DO_JUMP_TAG);
}
