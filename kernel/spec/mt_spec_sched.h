/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_spec_sched.h
 * @brief ACSL lemmas of the tick scheduler (ghost functions, proved by WP in each file that
 *        includes this header, called only from annotations of sched.c and sched_loop.c). The set-up's own logic is
 *        in mt_spec_sched_init.h.
 */
#ifndef MT_SPEC_SCHED_H
#define MT_SPEC_SCHED_H

#include "mt/sched.h"

/* Lemma (ghost function, proved by WP): MtSchedInv from its parts. A function that
 * changes *s calls it at its end: each part is then a goal of its own, in the final
 * memory state, and the solvers unfold the invariant once, in a small context. */
/*@ ghost
  /@ requires core: MtSchedCore(s);
     requires window: s->extra_us <= MT_SCHED_EXTRA_MAX_US && s->spare_ticks < MT_SCHED_SPARE_WINDOW &&
                      s->clean_loops <= MT_SCHED_CLEAN_LOOPS;
     requires spare: s->spare_us <= (integer)MT_SCHED_SPARE_WINDOW * 2 * 0xFFFFFFFF &&
                     s->spare_us <= ((integer)s->spare_ticks + MT_SCHED_SPARE_WINDOW) * 0xFFFFFFFF;
     requires ticks: s->tick < 0xFFFFFFFFFFFFFFFF && s->run_tick <= s->tick;
     requires states: \forall integer j; 0 <= j < s->ntasks ==>
        s->st[j].last_run <= s->run_tick && s->st[j].runs <= s->run_tick;
     assigns \nothing;
     ensures MtSchedInv(s);
  @/
  static void sched_inv_intro(mt_sched_t *s) { }
*/

#endif /* MT_SPEC_SCHED_H */
