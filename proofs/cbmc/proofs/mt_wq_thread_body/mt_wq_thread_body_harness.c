/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_wq_thread_body against its ACSL contract (kernel/include/mt/wq.h), translated by
 * tools/acsl2cbmc into mt_wq_thread_body_contract.h. Shape: nondeterministic objects, assume the requires,
 * snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage witnesses that
 * the harness admits the extreme values named.
 *
 * The queue thread's loop ends only when another context requests a stop (no loop variant by
 * design). An environment stub bounds it (assumption B6): every call of the static
 * stop_requested (the round's stop check, once per round) goes to mtc_env_stop_check
 * (Makefile: REPLACE_CALLS), which does what stop_requested does (lock, read q->stop, unlock;
 * the lock and unlock are the port's contract stubs) after letting another context's
 * mt_wq_request_stop (stop = 1 and a signal of `wake`, under the lock) come first: at round 1's
 * check nondeterministically, at round 2's check always. So the loop runs at most one full round
 * of the real mt_wq_serve_once (run an item, or wait on `wake`, or be refused) and is then left
 * by the stop, or earlier by MT_E_STATE or MT_E_BUSY; the unwinding assertions check that
 * bound. A stop request that in reality comes during round 1 (while the item runs or the thread
 * waits) is seen by the thread only at round 2's check, so moving it there changes nothing the
 * loop observes but the `wake` token, which the semaphore's stubs admit either way. */
#include "mtc_objects.h"
#include "mt_wq_thread_body_contract.h"

static uint32_t mtc_env_rounds;
static bool mtc_env_stop_first;

uint32_t mtc_env_stop_check(const mt_wq_t *cq)
{
    mt_wq_t *q = (mt_wq_t *)(uintptr_t)cq;
    uint32_t v;

    mt_port_lock();
    mtc_env_rounds++;
    if (mtc_env_rounds >= 2u || mtc_env_stop_first) {
        /* another context's mt_wq_request_stop, ordered before this check */
        q->stop = 1u;
        mt_sem_signal_i(&q->wake);
    }
    v = q->stop;
    mt_port_unlock();
    return v;
}

void harness(void)
{
    mt_wq_t *q = mtc_wq();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_wq_thread_body((void *)q));
    mtc_env_rounds = 0u;
    mtc_env_stop_first = mtc_nondet_bool();
    mtc_snapshot();
    mt_wq_thread_body((void *)q);
    mtc_post_mt_wq_thread_body((void *)q);

    MTC_REACH(q->stop == 1u && MTC_OLDV(q->stop) == 0u && mtc_env_stop_first);
    MTC_REACH(q->stop == 1u && MTC_OLDV(q->stop) == 0u && q->stats.runs > MTC_OLDV(q->stats.runs));
    MTC_REACH(q->stop == 1u && MTC_OLDV(q->count) == 0u && MTC_OLDV(q->running) == MT_WQ_NONE);
    MTC_REACH(q->stop == 1u && MTC_OLDV(q->running) != MT_WQ_NONE && q->refused > MTC_OLDV(q->refused));
    MTC_REACH(MTC_OLDV(q->stop) == 1u);
}
