/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_load against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_load_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_load_contract.h"

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

    __CPROVER_assume(mtc_pre_mt_mission_load(m, cmds, n, bad));
    mtc_snapshot();
    mt_status_t res = mt_mission_load(m, cmds, n, bad);
    mtc_post_mt_mission_load(m, cmds, n, bad, res);

    /* a full table with a jump, over a mission that had run to completion */
    MTC_REACH(res == MT_OK && n == MT_CFG_MISSION_MAX_CMDS && m->kind[n - 1u] == MT_MISSION_KIND_JUMP &&
              MTC_OLDV(m->state) == MT_MISSION_COMPLETE);
    MTC_REACH(res == MT_OK && MTC_OLDV(m->generation) == 0xFFFFFFFFu); /* saturated */
    MTC_REACH(res == MT_OK && m->repeat[2] == -1 && m->kind[2] == MT_MISSION_KIND_JUMP);
    MTC_REACH(res == MT_E_STATE);
    MTC_REACH(res == MT_E_MISSION_LOOP);
    MTC_REACH(res == MT_E_MISSION_PARAM);
    MTC_REACH(res == MT_E_MISSION_SIZE);
}
