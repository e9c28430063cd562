/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_spec_sched_init.h
 * @brief ACSL logic of the tick scheduler's set-up, used by sched.c alone (mt_sched_init and
 *        its store groups). Apart from mt_spec_sched.h so that its lemma is not a hypothesis of
 *        every goal of sched_loop.c.
 */
#ifndef MT_SPEC_SCHED_INIT_H
#define MT_SPEC_SCHED_INIT_H

#include "mt/sched.h"

/* What mt_sched_init() establishes before it sets the scalars, kept by each group of stores. */
/*@ predicate MtInitFacts(mt_sched_t *s, mt_task_t *tasks, integer n, integer rate_hz) =
        MtTableOk(tasks, n, rate_hz) &&
        (\forall integer j; 0 <= j < n ==>
            s->st[j].interval == MtInterval(tasks + j, rate_hz) && s->st[j].interval >= 1 &&
            s->st[j].last_run == 0 && s->st[j].runs == 0 && s->st[j].slips == 0 && s->st[j].overruns == 0);
*/

/* The locations MtInitFacts reads are the same at L1 and L2. */
/*@ predicate MtInitKept{L1, L2}(mt_sched_t *s, mt_task_t *tasks, integer n) =
        MtTableKept{L1, L2}(tasks, n) &&
        (\forall integer j; 0 <= j < n ==>
            \at(s->st[j].interval, L1) == \at(s->st[j].interval, L2) &&
            \at(s->st[j].last_run, L1) == \at(s->st[j].last_run, L2) &&
            \at(s->st[j].runs, L1) == \at(s->st[j].runs, L2) &&
            \at(s->st[j].slips, L1) == \at(s->st[j].slips, L2) &&
            \at(s->st[j].overruns, L1) == \at(s->st[j].overruns, L2));

    lemma MtInitFacts_kept{L1, L2}: \forall mt_sched_t *s, mt_task_t *tasks, integer n, r;
        MtInitFacts{L1}(s, tasks, n, r) ==> MtInitKept{L1, L2}(s, tasks, n) ==>
        \valid_read{L2}(tasks + (0 .. n - 1)) ==> MtInitFacts{L2}(s, tasks, n, r);
*/

/* Lemma (ghost function, proved by WP): the invariant of a freshly set up scheduler. */
/*@ ghost
  /@ requires valid: \valid(s);
     requires facts: MtInitFacts(s, tasks, n, rate_hz);
     requires sep: \separated(s, tasks + (0 .. n - 1));
     requires fields: s->tasks == tasks && s->ntasks == n && s->loop_rate_hz == rate_hz &&
                      s->period_us == 1000000 / rate_hz && s->tick == 0 && s->run_tick == 0 &&
                      s->extra_us == 0 && s->clean_loops == 0 && s->spare_us == 0 && s->spare_ticks == 0;
     assigns \nothing;
     ensures MtSchedInv(s);
  @/
  static void sched_inv_fresh(mt_sched_t *s, const mt_task_t *tasks, uint32_t n, uint32_t rate_hz) { }
*/

#endif /* MT_SPEC_SCHED_INIT_H */
