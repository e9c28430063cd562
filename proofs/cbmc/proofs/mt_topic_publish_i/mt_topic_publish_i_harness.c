/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_topic_publish_i against its ACSL contract (kernel/include/mt/bus.h), translated by
 * tools/acsl2cbmc into mt_topic_publish_i_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. Configuration: BUS_CBMC_CFG
 * (proofs/cbmc/Makefile.common, assumption B7).
 * Built twice, each time asserting part of the clauses (CLAUSES in the Makefile): here and in
 * ../mt_topic_publish_i__notify (assumption B17). */
#include "mtc_objects.h"
#include "mt_topic_publish_i_contract.h"

void harness(void)
{
    mt_topic_t *t = mtc_topic();
    uint32_t size = mtc_nondet_u32();
    uint8_t *msg = mtc_bytes(t->size);
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_topic_publish_i(t, msg, size));
    mtc_snapshot();
    mt_status_t res = mt_topic_publish_i(t, msg, size);
    mtc_post_mt_topic_publish_i(t, msg, size, res);

    MTC_REACH(res == MT_OK && MTC_OLDV(t->gen) == 0xFFFFFFFFu && t->gen == 0u);  /* the wrap */
    MTC_REACH(res == MT_OK && t->publishes == 0xFFFFFFFFu && t->size == MT_CFG_BUS_MAX_MSG &&
              t->qlen == MT_CFG_BUS_MAX_QUEUE);
    MTC_REACH(res == MT_OK && t->nnotify == MT_CFG_BUS_MAX_NOTIFY &&
              t->notify_calls[0] == 0xFFFFFFFFu && t->notified == 0xFFFFFFFFu);
    MTC_REACH(res == MT_OK && t->notify_interval_us[0] != 0u &&
              t->notify_calls[0] != MTC_OLDV(t->notify_calls[0]));      /* interval gate open */
    MTC_REACH(res == MT_OK && t->notify_gated[1] == 0xFFFFFFFFu && t->nnotify == 2u);
    MTC_REACH(res == MT_E_BUS_BEHIND && t->nrel == MT_CFG_BUS_MAX_RELIABLE &&
              t->rejected == 0xFFFFFFFFu);
    MTC_REACH(res == MT_E_BUS_MSG_SIZE && size == 0xFFFFFFFFu);
}
