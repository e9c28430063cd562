/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_status_str against its ACSL contract (kernel/src/status.c), translated by
 * tools/acsl2cbmc into mt_status_str_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_status_str_contract.h"

void harness(void)
{
    mt_status_t st = (mt_status_t)mtc_nondet_i32();   /* any value, in range or not */
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_status_str(st));
    mtc_snapshot();
    const char *res = mt_status_str(st);
    mtc_post_mt_status_str(st, res);

    MTC_REACH(st == MT_W_DROPPED_OLDEST);
    MTC_REACH((int)st < 0);
}
