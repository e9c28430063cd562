/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_topic_init against its ACSL contract (kernel/include/mt/bus.h), translated by
 * tools/acsl2cbmc into mt_topic_init_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. Configuration: BUS_CBMC_CFG
 * (proofs/cbmc/Makefile.common, assumption B7). */
#include "mtc_objects.h"
#include "mt_topic_init_contract.h"

static const char mtc_name[] = "t";

void harness(void)
{
    mt_topic_t *t = MTC_NEW(mt_topic_t, 1u);
    mt_topic_desc_t *d = MTC_NEW(mt_topic_desc_t, 1u);
    uint32_t n = mtc_nondet_u32();
    uint8_t *mem;
    void *storage;
    uint32_t storage_bytes;

    __CPROVER_assume(n <= MT_CFG_BUS_MAX_MSG * MT_CFG_BUS_MAX_QUEUE + 1u);
    mem = mtc_bytes(n);
    storage = mtc_nondet_bool() ? (void *)0 : (void *)mem;
    storage_bytes = (storage == (void *)0) ? mtc_nondet_u32() : n;
    d->name = mtc_nondet_bool() ? (const char *)0 : mtc_name;
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_topic_init(t, d, storage, storage_bytes));
    mtc_snapshot();
    mt_status_t res = mt_topic_init(t, d, storage, storage_bytes);
    mtc_post_mt_topic_init(t, d, storage, storage_bytes, res);

    MTC_REACH(res == MT_OK && d->msg_size == MT_CFG_BUS_MAX_MSG && d->queue_len == MT_CFG_BUS_MAX_QUEUE);
    MTC_REACH(res == MT_OK && d->first_gen == 0xFFFFFFFFu && d->flags == MT_TOPIC_RELIABLE);
    MTC_REACH(res == MT_E_INVALID && d->name != (const char *)0 && d->flags == 0xFFFFFFFFu);
    MTC_REACH(res == MT_E_BUS_MSG_SIZE && d->msg_size == MT_CFG_BUS_MAX_MSG + 1u);
    MTC_REACH(res == MT_E_BUS_QUEUE_LEN && d->queue_len == 0xFFFFFFFFu);
    MTC_REACH(res == MT_E_BUS_STORAGE && storage != (void *)0 &&
              storage_bytes + 1u == d->msg_size * d->queue_len);
    MTC_REACH(res == MT_E_BUS_STORAGE && storage == (void *)0 && storage_bytes == 0xFFFFFFFFu);
}
