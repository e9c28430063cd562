/* SPDX-License-Identifier: Apache-2.0 */
/* CBMC proof: mt_proc_note_missed against its ACSL contract (kernel/include/mt/proc.h), translated by
 * tools/acsl2cbmc into mt_proc_note_missed_contract.h. Shape: nondeterministic objects, assume the
 * requires, snapshot, call, assert ensures/behaviours/assigns; MTC_REACH lines are coverage
 * witnesses that the harness admits the extreme values named. */
#include "mtc_objects.h"
#include "mt_proc_note_missed_contract.h"

void harness(void)
{
    mt_proc_set_t *p = mtc_proc_set();
    uint32_t missed = mtc_nondet_u32();
    mtc_ghosts_nondet();

    __CPROVER_assume(mtc_pre_mt_proc_note_missed(p, missed));
    mtc_snapshot();
    mt_proc_note_missed(p, missed);
    mtc_post_mt_proc_note_missed(p, missed);

    MTC_REACH(p->periods_missed == 0xFFFFFFFFu && missed > 0u);
}
