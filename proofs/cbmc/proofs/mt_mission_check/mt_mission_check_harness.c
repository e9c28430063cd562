/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_check against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_check_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_check_contract.h"

void harness(void)
{
    mt_mission_t *m = mtc_mission();
    /* a candidate list of 1..MT_CFG_MISSION_MAX_CMDS commands, every field nondeterministic;
     * n is any count (a size error when it is 0 or above the capacity) */
    uint32_t len = mtc_nondet_u32();
    __CPROVER_assume(len >= 1u && len <= MT_CFG_MISSION_MAX_CMDS);
    mt_mission_cmd_t *cmds = mtc_mission_cmds(len);
    uint16_t n = mtc_nondet_u16();
    uint16_t *bad = (uint16_t *)mtc_alloc(sizeof(uint16_t), 1u, MTC_K_BYTES);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_mission_check(m, cmds, n, bad));
    mtc_snapshot();
    mt_status_t res = mt_mission_check(m, cmds, n, bad);
    mtc_post_mt_mission_check(m, cmds, n, bad, res);

    /* a full table with a jump in it */
    MTC_REACH(res == MT_OK && n == MT_CFG_MISSION_MAX_CMDS &&
              cmds[MT_CFG_MISSION_MAX_CMDS - 1u].id == MT_MAV_CMD_DO_JUMP);
    /* a repeat-forever jump back over a nav command: [home, nav, jump to 1 forever] */
    MTC_REACH(res == MT_OK && n == 3u && cmds[2].id == MT_MAV_CMD_DO_JUMP &&
              cmds[2].param[1] == -1000 && cmds[2].param[0] == 1000);
    /* a tag jump resolved: [home, tag, nav, jump to the tag] */
    MTC_REACH(res == MT_OK && n == 4u && cmds[3].id == MT_MAV_CMD_DO_JUMP_TAG);
    MTC_REACH(res == MT_E_MISSION_LOOP);
    MTC_REACH(res == MT_E_MISSION_JUMP && *bad == 3u); /* unknown tag, or bad target */
    MTC_REACH(res == MT_E_MISSION_CMD && *bad == 3u);
    MTC_REACH(res == MT_E_MISSION_SIZE && n > MT_CFG_MISSION_MAX_CMDS);
    MTC_REACH(res == MT_E_MISSION_SIZE && n == 0u);
}
