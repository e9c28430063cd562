/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_mission_init against its ACSL contract (kernel/include/mt/mission.h), translated by
 * tools/acsl2cbmc into mt_mission_init_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. The callbacks and ctx are
 * each NULL or one of three distinct addresses (mtc_callback() gives one address for every
 * callback), so equal, distinct and swapped arguments are all admitted and a body that
 * stores one argument in another's field fails the `callbacks` clause. */
#include "mtc_objects.h"
#include "mt_mission_init_contract.h"

static char mtc_code_a;
static char mtc_code_b;
static char mtc_code_c;

/* NULL or one of the three code addresses. */
static void *mtc_any_code(void)
{
    void *const codes[4] = {(void *)0, &mtc_code_a, &mtc_code_b, &mtc_code_c};
    uint32_t k = mtc_nondet_u32();

    __CPROVER_assume(k < 4u);
    return codes[k];
}

void harness(void)
{
    mt_mission_t *m = mtc_mission();
    mt_mission_cmd_fn_t start_fn = (mt_mission_cmd_fn_t)mtc_any_code();
    mt_mission_cmd_fn_t verify_fn = (mt_mission_cmd_fn_t)mtc_any_code();
    mt_mission_done_fn_t complete_fn = (mt_mission_done_fn_t)mtc_any_code();
    void *ctx = mtc_any_code();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_mission_init(m, start_fn, verify_fn, complete_fn, ctx));
    mtc_snapshot();
    mt_mission_init(m, start_fn, verify_fn, complete_fn, ctx);
    mtc_post_mt_mission_init(m, start_fn, verify_fn, complete_fn, ctx);

    MTC_REACH(ctx == (void *)0 && MTC_OLDV(m->state) == MT_MISSION_RUNNING);
    MTC_REACH(ctx != (void *)0 && (void *)start_fn != (void *)verify_fn &&
              (void *)verify_fn != (void *)complete_fn && (void *)start_fn != (void *)complete_fn);
}
