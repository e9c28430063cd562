/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_resume against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_resume_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_resume_contract.h"

void harness(void)
{
    mt_mission_t *m = mtc_mission();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_mission_resume(m));
    mtc_snapshot();
    mt_status_t res = mt_mission_resume(m);
    mtc_post_mt_mission_resume(m, res);

    MTC_REACH(res == MT_E_STATE);
    MTC_REACH(res == MT_E_EMPTY);
    /* COMPLETE -> start again */
    MTC_REACH(res == MT_OK && MTC_OLDV(m->state) == MT_MISSION_COMPLETE &&
              m->state == MT_MISSION_RUNNING);
    /* the active nav and do commands started again */
    MTC_REACH(res == MT_OK && MTC_OLDV(m->state) == MT_MISSION_STOPPED &&
              m->nav == MTC_OLDV(m->nav) && m->do_cmd != MT_MISSION_NONE);
    /* set-current at the do command: the nav command after it refused, the walk went on */
    MTC_REACH(res == MT_OK && MTC_OLDV(m->do_cmd) != MT_MISSION_NONE &&
              m->nav != MTC_OLDV(m->nav) && m->nav != MT_MISSION_NONE);
    /* the nav command refused its restart and the mission completed */
    MTC_REACH(res == MT_OK && MTC_OLDV(m->nav) != MT_MISSION_NONE &&
              m->state == MT_MISSION_COMPLETE);
    /* no nav command ever set: start */
    MTC_REACH(res == MT_OK && MTC_OLDV(m->nav) == MT_MISSION_NONE &&
              MTC_OLDV(m->state) == MT_MISSION_STOPPED && m->nav != MT_MISSION_NONE);
    /* a nav command set but none active: RUNNING, the next update advances */
    MTC_REACH(res == MT_OK && MTC_OLDV(m->nav) == MT_MISSION_NONE &&
              MTC_OLDV(m->nav_idx) != MT_MISSION_NONE && m->state == MT_MISSION_RUNNING &&
              m->nav == MT_MISSION_NONE);
}
