/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_mission_int.h
 * @brief The mission module's internal functions (kernel-private): the parts of
 *        the sequencer (mission_seq.c) that the control operations (mission.c)
 *        call. Defined in mission_seq.c; each contract is stated here once.
 *
 * Same rules as the public functions: one thread owns a mission object, nothing
 * here takes the kernel lock or blocks, and every walk is bounded (mt/mission.h).
 */
#ifndef MT_MISSION_INT_H
#define MT_MISSION_INT_H

#include <stdint.h>

#include "mt/mission.h"
#include "mt_spec.h"

/* The nav command the walk from p reaches first, jumps followed without
 * counting (fresh: with every counter 0); total at the end; MT_MISSION_NONE
 * when the bound is hit. Visits at most total commands. */
/*@ requires MtMissionInv(m) && 1 <= p < m->total;
    assigns \nothing;
    ensures \result == m->total || \result == MT_MISSION_NONE ||
            (MtMissionIdx(m, \result) && m->kind[\result] == MT_MISSION_KIND_NAV);
*/
uint16_t mt_mission_look_nav(const mt_mission_t *m, uint16_t p, int fresh);

/* No active nav or do command; the do search starts over. */
/*@ requires MtMissionInv(m);
    assigns m->nav, m->do_cmd, m->do_idx, m->do_done;
    ensures MtMissionInv(m);
    ensures m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE && m->do_idx == MT_MISSION_NONE;
    ensures m->do_done == 0;
*/
void mt_mission_drop_both(mt_mission_t *m);

/* Drop both commands and run the nav advance from p; the end completes the
 * mission [set_current_cmd while running]. */
/*@ requires MtMissionInv(m) && m->total >= 2 && m->state == MT_MISSION_RUNNING;
    requires 1 <= p <= m->total;
    assigns m->state, m->nav, m->nav_idx, m->prev_nav, m->do_cmd, m->do_idx, m->do_done,
            m->completions, m->count[0 .. m->total - 1], MtPortNow, MtPortWakes;
    ensures MtMissionInv(m);
    ensures m->state == MT_MISSION_RUNNING || m->state == MT_MISSION_COMPLETE;
    ensures complete_once: m->completions == \old(m->completions) + (m->state == MT_MISSION_COMPLETE ? 1 : 0) ||
        \old(m->completions) == 0xFFFFFFFF;
*/
void mt_mission_advance_or_finish(mt_mission_t *m, uint16_t p);

/* Not running: walk from p, counting jumps, to the first nav command; it and
 * the first do command passed become active without a start [the stopped
 * branch of set_current_cmd]. The caller has seen a nav command ahead; if the
 * walk still ends, nothing is active and no nav command is set. */
/*@ requires MtMissionInv(m) && m->total >= 2 && m->state != MT_MISSION_RUNNING;
    requires 1 <= p < m->total;
    assigns m->nav, m->nav_idx, m->do_cmd, m->do_idx, m->do_done, m->count[0 .. m->total - 1];
    ensures MtMissionInv(m);
*/
void mt_mission_preload(mt_mission_t *m, uint16_t p);

#endif /* MT_MISSION_INT_H */
