/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_set_current against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_set_current_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_set_current_contract.h"

void harness(void)
{
    mt_mission_t *m = mtc_mission();
    uint16_t i = mtc_nondet_u16();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_mission_set_current(m, i));
    mtc_snapshot();
    mt_status_t res = mt_mission_set_current(m, i);
    mtc_post_mt_mission_set_current(m, i, res);

    MTC_REACH(res == MT_E_EMPTY && m->total < 2u);
    /* stopped, no nav command at or after i: nothing changes */
    MTC_REACH(res == MT_E_EMPTY && m->total >= 2u && i > 0u);
    /* stopped: the walk made the first do command and the nav command after it active */
    MTC_REACH(res == MT_OK && MTC_OLDV(m->state) != MT_MISSION_RUNNING &&
              m->do_cmd != MT_MISSION_NONE && m->do_cmd < m->nav);
    MTC_REACH(res == MT_E_INVALID && i == 0xFFFFu);
    /* running: the nav command at or after i started now */
    MTC_REACH(res == MT_OK && MTC_OLDV(m->state) == MT_MISSION_RUNNING && i > 1u &&
              m->nav == i);
    /* running: nothing after i, the mission completes */
    MTC_REACH(res == MT_OK && MTC_OLDV(m->state) == MT_MISSION_RUNNING &&
              m->state == MT_MISSION_COMPLETE);
    /* i == 0: counters reset, position 1 */
    MTC_REACH(res == MT_OK && i == 0u && MTC_OLDV(m->count[1]) > 0 && m->count[1] == 0 &&
              m->state == MT_MISSION_STOPPED);
    /* a COMPLETE mission also resets the counters */
    MTC_REACH(res == MT_OK && MTC_OLDV(m->state) == MT_MISSION_COMPLETE &&
              i == MT_CFG_MISSION_MAX_CMDS - 1u);
}
