/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_wq_timer_proc against its ACSL contract (kernel/include/mt/wq_timer.h), translated by
 * tools/acsl2cbmc into mt_wq_timer_proc_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_wq_timer_proc_contract.h"

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    mtc_wq_periods(q);
    mtc_ghosts_nondet();
    /* Time window (assumption B9): the time before the call and every deadline lie in one
     * 2^20 us window at the bottom or the top of the 64-bit range, and the port's clock read
     * inside the proc (mt_port_now_us, replaced by mtc_now_in_window: Makefile REPLACE_CALLS)
     * advances by at most 2^20 us, saturating at UINT64_MAX. */
    mtc_wq_time_window(q, MtPortNow);

    __CPROVER_assume(mtc_pre_mt_wq_timer_proc((void *)q));
    mtc_snapshot();
    mt_wq_timer_proc((void *)q);
    mtc_post_mt_wq_timer_proc((void *)q);

    MTC_REACH(q->count == MT_CFG_WQ_MAX_ITEMS && MTC_OLDV(q->count) == 0u);
    MTC_REACH(MtPortNow == UINT64_MAX && q->slot[0].timer == MT_WQ_TIMER_OFF &&
              MTC_OLDV(q->slot[0].timer) == MT_WQ_TIMER_EVERY);
}
