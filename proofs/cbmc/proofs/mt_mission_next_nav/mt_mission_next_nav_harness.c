/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_next_nav against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_next_nav_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_next_nav_contract.h"

void harness(void)
{
    mt_mission_t *m = mtc_mission();
    uint16_t from = mtc_nondet_u16();
    uint16_t *out = (uint16_t *)mtc_alloc(sizeof(uint16_t), 1u, MTC_K_BYTES);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_mission_next_nav(m, from, out));
    mtc_snapshot();
    mt_status_t res = mt_mission_next_nav(m, from, out);
    mtc_post_mt_mission_next_nav(m, from, out, res);

    /* found through a jump that is taken (target before from) */
    MTC_REACH(res == MT_OK && *out < from);
    MTC_REACH(res == MT_OK && *out == m->total - 1u && m->total == MT_CFG_MISSION_MAX_CMDS);
    MTC_REACH(res == MT_E_EMPTY);
    MTC_REACH(res == MT_E_INVALID && from == 0u);
    MTC_REACH(res == MT_E_INVALID && from == 0xFFFFu);
    /* a jump loop without a nav command (MtMissionInv allows it; load rejects it) */
    MTC_REACH(res == MT_E_MISSION_LOOP);
}
