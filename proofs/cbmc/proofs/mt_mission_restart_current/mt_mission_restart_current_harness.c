/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_restart_current against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_restart_current_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_restart_current_contract.h"

void harness(void)
{
    mt_mission_t *m = mtc_mission();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_mission_restart_current(m));
    mtc_snapshot();
    mt_status_t res = mt_mission_restart_current(m);
    mtc_post_mt_mission_restart_current(m, res);

    MTC_REACH(res == MT_E_STATE && m->state == MT_MISSION_RUNNING);
    MTC_REACH(res == MT_E_STATE && m->nav != MT_MISSION_NONE);
    /* refused, the loop brought the walk back to it past a do command */
    MTC_REACH(res == MT_OK && m->nav == MTC_OLDV(m->nav) && m->do_cmd != MT_MISSION_NONE);
    /* the plain restart: the same nav command, no do command left before it */
    MTC_REACH(res == MT_OK && m->nav == MTC_OLDV(m->nav_idx) && m->do_cmd == MT_MISSION_NONE &&
              m->do_done == 1u);
    /* refused: the command completes and the next one is loaded */
    MTC_REACH(res == MT_OK && m->prev_nav == MTC_OLDV(m->nav) && m->nav != MT_MISSION_NONE);
    /* refused, and it was the last one: mission complete */
    MTC_REACH(res == MT_OK && m->state == MT_MISSION_COMPLETE);
}
