/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_wq_serve_once against its ACSL contract (kernel/include/mt/wq.h), translated by
 * tools/acsl2cbmc into mt_wq_serve_once_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_wq_serve_once_contract.h"

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_wq_serve_once(q));
    mtc_snapshot();
    mt_status_t res = mt_wq_serve_once(q);
    mtc_post_mt_wq_serve_once(q, res);

    MTC_REACH(res == MT_E_STATE);
    MTC_REACH(res == MT_OK && q->stats.runs > MTC_OLDV(q->stats.runs));
    MTC_REACH(res == MT_OK && MTC_OLDV(q->count) == 0u && MTC_OLDV(q->wake.token) == 1u);
    MTC_REACH(res == MT_E_BUSY);
}
