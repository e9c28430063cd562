/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_sem_valid (a C twin of an ACSL invariant) against its ACSL contract, translated by
 * tools/acsl2cbmc into mt_sem_valid_contract.h: the result is 1 exactly when the invariant holds.
 * Every field of the object is nondeterministic, corrupted values included; MTC_REACH lines
 * are coverage witnesses. */
#include "mtc_objects.h"
#include "mt_sem_valid_contract.h"

void harness(void)
{
    mt_sem_t *s = mtc_sem();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_sem_valid(s));
    mtc_snapshot();
    bool ok = mt_sem_valid(s);
    mtc_post_mt_sem_valid(s, ok);

    MTC_REACH(ok && s->token == 1u);
    MTC_REACH(!ok && s->token == 1u);
    MTC_REACH(!ok && s->token == 0xFFFFFFFFu);
}
