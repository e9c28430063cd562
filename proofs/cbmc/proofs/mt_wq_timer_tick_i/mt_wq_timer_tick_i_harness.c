/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_wq_timer_tick_i against its ACSL contract (kernel/include/mt/wq_timer.h), translated by
 * tools/acsl2cbmc into mt_wq_timer_tick_i_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_wq_timer_tick_i_contract.h"

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    mtc_wq_periods(q);
    uint64_t now = mtc_nondet_u64();
    mtc_ghosts_nondet();
    /* Time window (assumption B9): now and every deadline lie in one 2^20 us window at the
     * bottom or at the top of the 64-bit range, so the division by the interval in
     * mt_proc_period_next is over 21-bit distances. */
    mtc_wq_time_window(q, now);

    __CPROVER_assume(mtc_pre_mt_wq_timer_tick_i(q, now));
    mtc_snapshot();
    uint32_t res = mt_wq_timer_tick_i(q, now);
    mtc_post_mt_wq_timer_tick_i(q, now, res);

    MTC_REACH(res == MT_CFG_WQ_MAX_ITEMS && q->count == MT_CFG_WQ_MAX_ITEMS);
    MTC_REACH(res >= 1u && q->slot[0].stats.missed == 0xFFFFFFFFu && MTC_OLDV(q->slot[0].stats.missed) < 0xFFFFFFFFu);
    MTC_REACH(res >= 1u && MTC_OLDV(q->slot[1].timer) == MT_WQ_TIMER_EVERY && q->slot[1].timer == MT_WQ_TIMER_OFF);
    MTC_REACH(now == UINT64_MAX && res == MT_CFG_WQ_MAX_ITEMS);
    MTC_REACH(res == 0u && q->slot[0].timer == MT_WQ_TIMER_EVERY && q->slot[0].deadline_us == UINT64_MAX);
}
