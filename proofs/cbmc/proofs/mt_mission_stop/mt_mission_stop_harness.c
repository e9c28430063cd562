/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_stop against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_stop_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_mission_stop_contract.h"

void harness(void)
{
    mt_mission_t *m = mtc_mission();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_mission_stop(m));
    mtc_snapshot();
    mt_status_t res = mt_mission_stop(m);
    mtc_post_mt_mission_stop(m, res);

    MTC_REACH(res == MT_OK && m->nav != MT_MISSION_NONE && m->do_cmd != MT_MISSION_NONE);
    MTC_REACH(res == MT_E_STATE && m->state == MT_MISSION_COMPLETE);
    MTC_REACH(res == MT_E_STATE && m->state == MT_MISSION_STOPPED);
}
