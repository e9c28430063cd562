/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_start against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_start_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_start_contract.h"

void harness(void)
{
    mt_mission_t *m = mtc_mission();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_mission_start(m));
    mtc_snapshot();
    mt_status_t res = mt_mission_start(m);
    mtc_post_mt_mission_start(m, res);

    MTC_REACH(res == MT_E_EMPTY);
    MTC_REACH(res == MT_OK && m->state == MT_MISSION_RUNNING && m->nav == m->total - 1u &&
              m->total == MT_CFG_MISSION_MAX_CMDS);
    /* no nav command at all: complete at once (also with a saturated counter) */
    MTC_REACH(res == MT_OK && m->state == MT_MISSION_COMPLETE);
    MTC_REACH(res == MT_OK && MTC_OLDV(m->completions) == 0xFFFFFFFFu);
    /* the first nav command refused: the walk goes on and starts the next one */
    MTC_REACH(res == MT_OK && m->state == MT_MISSION_RUNNING && m->prev_nav != MT_MISSION_NONE &&
              m->nav != MT_MISSION_NONE);
    /* the first do command started before the first nav command */
    MTC_REACH(res == MT_OK && m->do_cmd != MT_MISSION_NONE && m->do_cmd < m->nav);
    /* every nav start refused in a repeat-forever loop: the bound completes the mission */
    MTC_REACH(res == MT_OK && m->state == MT_MISSION_COMPLETE &&
              m->kind[2] == MT_MISSION_KIND_JUMP && m->repeat[2] == -1 && m->nav_idx == 1u);
    /* a trailing do command started, then the end */
    MTC_REACH(res == MT_OK && m->state == MT_MISSION_COMPLETE && m->do_idx != MT_MISSION_NONE);
    /* a jump taken on the way to the first nav command */
    MTC_REACH(res == MT_OK && m->kind[1] == MT_MISSION_KIND_JUMP && m->count[1] == 1);
}
