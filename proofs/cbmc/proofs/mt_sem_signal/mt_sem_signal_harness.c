/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sem_signal against its ACSL contract (kernel/include/mt/sem.h), translated by
 * tools/acsl2cbmc into mt_sem_signal_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_sem_signal_contract.h"

void harness(void)
{
    mt_sem_t *s = mtc_sem();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sem_signal(s));
    mtc_snapshot();
    mt_sem_signal(s);
    mtc_post_mt_sem_signal(s);

    MTC_REACH(s->merged == 0xFFFFFFFFu && s->token == 1u);
}
