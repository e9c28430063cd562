/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sub_updated against its ACSL contract (kernel/include/mt/bus_sub.h), translated by
 * tools/acsl2cbmc into mt_sub_updated_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. Configuration: BUS_CBMC_CFG
 * (proofs/cbmc/Makefile.common, assumption B7). */
#include "mtc_objects.h"
#include "mt_sub_updated_contract.h"

void harness(void)
{
    mt_topic_t *t = mtc_topic();
    mt_sub_t *s = mtc_sub(t);
    uint64_t now_us = mtc_nondet_u64();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sub_updated(s, now_us));
    mtc_snapshot();
    bool res = mt_sub_updated(s, now_us);
    mtc_post_mt_sub_updated(s, now_us, res);

    MTC_REACH(res && s->interval_us == 0xFFFFFFFFu && now_us == UINT64_MAX && s->last_us == 0u);
    MTC_REACH(res && s->interval_us == 0u && t->gen == 0u && s->gen == 0xFFFFFFFFu);
    MTC_REACH(!res && t->gen != s->gen && now_us < s->last_us);     /* time before the last update */
    MTC_REACH(!res && t->gen != s->gen && now_us >= s->last_us && s->interval_us != 0u &&
              now_us - s->last_us == (uint64_t)s->interval_us - 1u);     /* one microsecond early */
}
