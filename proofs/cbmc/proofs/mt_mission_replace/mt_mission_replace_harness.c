/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_replace against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_replace_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_replace_contract.h"

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

    __CPROVER_assume(mtc_pre_mt_mission_replace(m, cmds, n, bad));
    mtc_snapshot();
    mt_status_t res = mt_mission_replace(m, cmds, n, bad);
    mtc_post_mt_mission_replace(m, cmds, n, bad, res);

    MTC_REACH(res == MT_E_STATE);
    MTC_REACH(res == MT_E_MISSION_LOOP);
    MTC_REACH(res == MT_E_MISSION_SIZE);
    /* continued: the nav command now at the same index started */
    MTC_REACH(res == MT_OK && m->state == MT_MISSION_RUNNING && m->nav == MTC_OLDV(m->nav_idx));
    /* continued past a do command now at that index, which is active */
    MTC_REACH(res == MT_OK && m->state == MT_MISSION_RUNNING && m->do_cmd == MTC_OLDV(m->nav_idx));
    /* continued to the end: the mission completes */
    MTC_REACH(res == MT_OK && m->state == MT_MISSION_COMPLETE);
    /* held: the index is gone */
    MTC_REACH(res == MT_OK && m->state == MT_MISSION_STOPPED && n >= 2u);
    /* a jump counter kept (both lists have a jump at 2, clamped to the new repeat count) */
    MTC_REACH(res == MT_OK && m->state == MT_MISSION_STOPPED &&
              m->kind[2] == MT_MISSION_KIND_JUMP && m->count[2] > 0 &&
              m->count[2] == m->repeat[2] && MTC_OLDV(m->count[2]) > m->repeat[2]);
}
