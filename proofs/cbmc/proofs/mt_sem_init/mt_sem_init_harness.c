/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sem_init against its ACSL contract (kernel/include/mt/sem.h), translated by
 * tools/acsl2cbmc into mt_sem_init_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_sem_init_contract.h"

void harness(void)
{
    mt_sem_t *s = mtc_sem();
    bool available = mtc_nondet_bool();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sem_init(s, available));
    mtc_snapshot();
    mt_sem_init(s, available);
    mtc_post_mt_sem_init(s, available);

    MTC_REACH(s->token == 1u);
}
