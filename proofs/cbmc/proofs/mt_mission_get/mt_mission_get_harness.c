/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_get against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_get_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_get_contract.h"

void harness(void)
{
    mt_mission_t *m = mtc_mission();
    uint16_t i = mtc_nondet_u16();
    mt_mission_cmd_t *out = mtc_mission_cmds(1u);
    bool *is_current = (bool *)mtc_alloc(sizeof(bool), 1u, MTC_K_BYTES);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_mission_get(m, i, out, is_current));
    mtc_snapshot();
    mt_status_t res = mt_mission_get(m, i, out, is_current);
    mtc_post_mt_mission_get(m, i, out, is_current, res);

    MTC_REACH(res == MT_OK && *is_current);
    MTC_REACH(res == MT_OK && i == 0u && !*is_current);
    MTC_REACH(res == MT_OK && i == MT_CFG_MISSION_MAX_CMDS - 1u);
    MTC_REACH(res == MT_E_INVALID && i == 0xFFFFu);
    MTC_REACH(res == MT_E_INVALID && m->total == 0u);
}
