/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_topic_notify_add against its ACSL contract (kernel/include/mt/bus.h), translated by
 * tools/acsl2cbmc into mt_topic_notify_add_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. Configuration: BUS_CBMC_CFG
 * (proofs/cbmc/Makefile.common, assumption B7). */
#include "mtc_objects.h"
#include "mt_topic_notify_add_contract.h"

void harness(void)
{
    mt_topic_t *t = mtc_topic();
    mt_bus_notify_fn_t fn = mtc_nondet_bool() ? (mt_bus_notify_fn_t)0
                                              : (mt_bus_notify_fn_t)mtc_callback();
    void *arg = mtc_nondet_bool() ? (void *)0 : (void *)t;
    uint32_t min_updates = mtc_nondet_u32();
    uint32_t interval_us = mtc_nondet_u32();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_topic_notify_add(t, fn, arg, min_updates, interval_us));
    mtc_snapshot();
    mt_status_t res = mt_topic_notify_add(t, fn, arg, min_updates, interval_us);
    mtc_post_mt_topic_notify_add(t, fn, arg, min_updates, interval_us, res);

    MTC_REACH(res == MT_OK && t->nnotify == MT_CFG_BUS_MAX_NOTIFY && min_updates == 0xFFFFFFFFu &&
              interval_us == 0xFFFFFFFFu);
    MTC_REACH(res == MT_E_INVALID && fn != (mt_bus_notify_fn_t)0);
    MTC_REACH(res == MT_E_DUPLICATE && MTC_OLDV(t->nnotify) == MT_CFG_BUS_MAX_NOTIFY);
    MTC_REACH(res == MT_E_FULL);
}
