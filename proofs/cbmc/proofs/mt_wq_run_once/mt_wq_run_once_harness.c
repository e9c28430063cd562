/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_wq_run_once against its ACSL contract (kernel/include/mt/wq.h), translated by
 * tools/acsl2cbmc into mt_wq_run_once_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_wq_run_once_contract.h"

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_wq_run_once(q));
    mtc_snapshot();
    mt_status_t res = mt_wq_run_once(q);
    mtc_post_mt_wq_run_once(q, res);

    MTC_REACH(res == MT_E_BUSY && q->refused == 0xFFFFFFFFu);
    MTC_REACH(res == MT_E_EMPTY);
    MTC_REACH(res == MT_OK && q->stats.runs == UINT64_MAX && q->stats.total_run_us == UINT64_MAX &&
              q->stats.max_run_us == 0xFFFFFFFFu);
    MTC_REACH(res == MT_OK && q->stats.starts == UINT64_MAX && q->stats.max_interval_us == 0xFFFFFFFFu &&
              q->stats.max_latency_us == 0xFFFFFFFFu);
    MTC_REACH(res == MT_OK && MTC_OLDV(q->head) == MT_CFG_WQ_MAX_ITEMS - 1u && q->head == 0u);
    MTC_REACH(res == MT_OK && q->slot[MTC_OLDV(q->order[MTC_OLDV(q->head)])].shot == MT_WQ_SHOT_DONE);
}
