/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sem_wait against its ACSL contract (kernel/include/mt/sem.h), translated by
 * tools/acsl2cbmc into mt_sem_wait_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_sem_wait_contract.h"

void harness(void)
{
    mt_sem_t *s = mtc_sem();
    uint64_t timeout_us = mtc_nondet_u64();           /* 0, MT_WAIT_FOREVER, anything */
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sem_wait(s, timeout_us));
    mtc_snapshot();
    mt_status_t res = mt_sem_wait(s, timeout_us);
    mtc_post_mt_sem_wait(s, timeout_us, res);

    MTC_REACH(res == MT_OK && timeout_us == MT_WAIT_FOREVER && mtc_old_MtLocked == MtLocked);
    MTC_REACH(res == MT_E_BUSY);
    MTC_REACH(res == MT_E_TIMEOUT && timeout_us > 0u);
}
