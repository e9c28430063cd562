/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_work_init against its ACSL contract (kernel/include/mt/wq.h), translated by
 * tools/acsl2cbmc into mt_work_init_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_work_init_contract.h"

void harness(void)
{
    mt_work_t *w = MTC_NEW(mt_work_t, 1u);
    mt_work_fn_t fn = mtc_nondet_bool() ? (mt_work_fn_t)0 : (mt_work_fn_t)mtc_callback();
    void *arg = mtc_nondet_bool() ? (void *)0 : mtc_callback();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_work_init(w, fn, arg));
    mtc_snapshot();
    mt_work_init(w, fn, arg);
    mtc_post_mt_work_init(w, fn, arg);

    MTC_REACH(fn != (mt_work_fn_t)0 && MTC_OLDV(w->slot) == 0xFFFFFFFFu);
}
