/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_update against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_update_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_update_contract.h"

void harness(void)
{
    mt_mission_t *m = mtc_mission();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_mission_update(m));
    mtc_snapshot();
    mt_status_t res = mt_mission_update(m);
    mtc_post_mt_mission_update(m, res);

    MTC_REACH(res == MT_E_STATE);
    /* a DO_JUMP taken: its counter moves up to its repeat count */
    MTC_REACH(res == MT_OK && m->kind[2] == MT_MISSION_KIND_JUMP && m->repeat[2] > 0 &&
              m->count[2] == m->repeat[2] && MTC_OLDV(m->count[2]) == m->repeat[2] - 1);
    /* a jump exhausted: falls through, counter reset */
    MTC_REACH(res == MT_OK && m->kind[2] == MT_MISSION_KIND_JUMP && m->repeat[2] > 0 &&
              MTC_OLDV(m->count[2]) == m->repeat[2] && m->count[2] == 0);
    /* a repeat-forever jump taken back to an earlier nav command */
    MTC_REACH(res == MT_OK && m->kind[2] == MT_MISSION_KIND_JUMP && m->repeat[2] == -1 &&
              m->nav == 1u && MTC_OLDV(m->nav) == 1u && m->prev_nav == 1u);
    /* mission complete (and with a saturated counter) */
    MTC_REACH(res == MT_OK && m->state == MT_MISSION_COMPLETE &&
              m->total == MT_CFG_MISSION_MAX_CMDS);
    MTC_REACH(res == MT_OK && m->state == MT_MISSION_COMPLETE &&
              MTC_OLDV(m->completions) == 0xFFFFFFFFu);
    /* a do command started, and one verified */
    MTC_REACH(res == MT_OK && MTC_OLDV(m->do_cmd) == MT_MISSION_NONE &&
              m->do_cmd != MT_MISSION_NONE);
    MTC_REACH(res == MT_OK && MTC_OLDV(m->do_cmd) != MT_MISSION_NONE &&
              m->do_cmd == MT_MISSION_NONE && m->nav == MTC_OLDV(m->nav));
    /* the do search reached the nav command */
    MTC_REACH(res == MT_OK && MTC_OLDV(m->do_done) == 0u && m->do_done == 1u);
    /* the do search started the next do command while the same nav command runs */
    MTC_REACH(res == MT_OK && MTC_OLDV(m->do_cmd) == MT_MISSION_NONE &&
              m->nav == MTC_OLDV(m->nav) && m->do_cmd != MT_MISSION_NONE &&
              m->do_cmd > MTC_OLDV(m->do_idx));
    /* the advance started a do command and the nav command after it */
    MTC_REACH(res == MT_OK && m->nav != MTC_OLDV(m->nav) && m->do_cmd != MT_MISSION_NONE &&
              m->do_cmd < m->nav);
    /* a trailing do command started, then the end */
    MTC_REACH(res == MT_OK && m->state == MT_MISSION_COMPLETE && m->do_idx != MT_MISSION_NONE &&
              m->do_idx > MTC_OLDV(m->nav));
    /* a JUMP_TAG in the do slot verifies without a callback */
    MTC_REACH(res == MT_OK && MTC_OLDV(m->do_cmd) != MT_MISSION_NONE &&
              m->kind[MTC_OLDV(m->do_cmd)] == MT_MISSION_KIND_TAG && m->do_cmd == MT_MISSION_NONE);
}
