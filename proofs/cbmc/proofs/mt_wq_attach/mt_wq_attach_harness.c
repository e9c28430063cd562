/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_wq_attach against its ACSL contract (kernel/include/mt/wq.h), translated by
 * tools/acsl2cbmc into mt_wq_attach_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_wq_attach_contract.h"

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    mt_wq_t *other = MTC_NEW(mt_wq_t, 1u);
    mt_work_t *w = MTC_NEW(mt_work_t, 1u);
    uint8_t sel = mtc_nondet_u8();
    w->fn = mtc_nondet_bool() ? (mt_work_fn_t)0 : (mt_work_fn_t)mtc_callback();
    w->wq = sel == 0u ? (mt_wq_t *)0 : (sel == 1u ? q : other);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_wq_attach(q, w));
    mtc_snapshot();
    mt_status_t res = mt_wq_attach(q, w);
    mtc_post_mt_wq_attach(q, w, res);

    MTC_REACH(res == MT_OK && q->nitems == MT_CFG_WQ_MAX_ITEMS);
    MTC_REACH(res == MT_E_FULL);
    MTC_REACH(res == MT_E_DUPLICATE && w->wq == other);
    MTC_REACH(res == MT_E_INVALID);
}
