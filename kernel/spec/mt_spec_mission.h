/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_spec_mission.h
 * @brief ACSL logic for the mission sequencer (mt/mission.h): the invariant of a
 *        mission object and its parts, the staged candidate list, and the clauses the
 *        load and replace contracts share.
 *
 * Only ACSL lives here: to a C compiler this header is empty. mt/mission.h includes it
 * after its types and the validation scratch (the predicates read mt_mission_t and the
 * scratch arrays). The nav and do ids (MtMissionIsNavId, MtMissionIsDoId) are generated
 * with the command table into mt_spec_mission_cmds.h.
 */
#ifndef MT_SPEC_MISSION_H
#define MT_SPEC_MISSION_H

#include "mt_spec_mission_cmds.h"

/*@ predicate MtMissionIsJumpId(integer id) = id == MT_MAV_CMD_DO_JUMP || id == MT_MAV_CMD_DO_JUMP_TAG;
    predicate MtMissionIsCallbackId(integer id) = !MtMissionIsJumpId(id) && id != MT_MAV_CMD_JUMP_TAG;
    // an id of the command table: nav, do, jump or JUMP_TAG (any other id is unknown)
    predicate MtMissionIsKnownId(integer id) =
        MtMissionIsNavId(id) || MtMissionIsDoId(id) || MtMissionIsJumpId(id) ||
        id == MT_MAV_CMD_JUMP_TAG;

    predicate MtMissionIdx(mt_mission_t *m, integer i) = 1 <= i < m->total;

    predicate MtMissionCursor(mt_mission_t *m, integer i, integer k) =
        i == MT_MISSION_NONE || (MtMissionIdx(m, i) && m->kind[i] == k);

    predicate MtMissionKinds(mt_mission_t *m) =
        m->kind[0] == MT_MISSION_KIND_HOME &&
        \forall integer i; 1 <= i < m->total ==>
            (m->kind[i] == MT_MISSION_KIND_NAV || m->kind[i] == MT_MISSION_KIND_DO ||
             m->kind[i] == MT_MISSION_KIND_JUMP || m->kind[i] == MT_MISSION_KIND_TAG) &&
            (m->kind[i] == MT_MISSION_KIND_JUMP <==> MtMissionIsJumpId(m->cmd[i].id)) &&
            (m->kind[i] == MT_MISSION_KIND_TAG <==> m->cmd[i].id == MT_MAV_CMD_JUMP_TAG);

    predicate MtMissionJumps(mt_mission_t *m) =
        \forall integer i; 1 <= i < m->total ==> m->kind[i] == MT_MISSION_KIND_JUMP ==>
            1 <= m->target[i] < m->total && -1 <= m->repeat[i] <= MT_MISSION_REPEAT_MAX;

    predicate MtMissionCounters(mt_mission_t *m) =
        \forall integer i; 1 <= i < m->total ==> m->kind[i] == MT_MISSION_KIND_JUMP ==>
            (m->repeat[i] >= 0 ==> 0 <= m->count[i] <= m->repeat[i]) &&
            (m->repeat[i] < 0 ==> m->count[i] == 0);

    predicate MtMissionDoCursor(mt_mission_t *m, integer i) =
        i == MT_MISSION_NONE ||
        (MtMissionIdx(m, i) && (m->kind[i] == MT_MISSION_KIND_DO || m->kind[i] == MT_MISSION_KIND_TAG));

    predicate MtMissionCursors(mt_mission_t *m) =
        (m->state == MT_MISSION_STOPPED || m->state == MT_MISSION_RUNNING ||
         m->state == MT_MISSION_COMPLETE) &&
        MtMissionCursor(m, m->nav_idx, MT_MISSION_KIND_NAV) &&
        MtMissionCursor(m, m->prev_nav, MT_MISSION_KIND_NAV) &&
        MtMissionDoCursor(m, m->do_idx) &&
        (m->nav == MT_MISSION_NONE || m->nav == m->nav_idx) &&
        (m->do_cmd == MT_MISSION_NONE || m->do_cmd == m->do_idx) &&
        (m->do_cmd != MT_MISSION_NONE ==> m->nav != MT_MISSION_NONE) &&
        (m->do_done == 0 || m->do_done == 1) &&
        (m->state != MT_MISSION_STOPPED ==> m->total >= 2);

    predicate MtMissionInv(mt_mission_t *m) =
        \valid(m) && 0 <= m->total <= MT_CFG_MISSION_MAX_CMDS &&
        \separated(m, mt_mission_scratch_safe + (0 .. MT_CFG_MISSION_MAX_CMDS - 1),
                   mt_mission_scratch_target + (0 .. MT_CFG_MISSION_MAX_CMDS - 1)) &&
        m->start_fn != \null && m->verify_fn != \null && m->complete_fn != \null &&
        MtMissionKinds(m) && MtMissionJumps(m) && MtMissionCounters(m) && MtMissionCursors(m);

    predicate MtMissionCmdsIn(mt_mission_cmd_t *c, integer n) =
        1 <= n <= MT_CFG_MISSION_MAX_CMDS && \valid_read(c + (0 .. n - 1));

    predicate MtMissionRepeatOk(integer p) =
        p % 1000 == 0 && -1000 <= p <= 32767000;

    predicate MtMissionJumpCmdOk(mt_mission_cmd_t *c, integer n, integer i) =
        MtMissionIsJumpId(c[i].id) ==> MtMissionRepeatOk(c[i].param[1]);

    predicate MtMissionStaged(uint16_t *tgt, mt_mission_cmd_t *c, integer n) =
        MtMissionCmdsIn(c, n) &&
        \forall integer i; 1 <= i < n ==> MtMissionIsJumpId(c[i].id) ==>
            1 <= tgt[i] < n && MtMissionRepeatOk(c[i].param[1]);

    predicate MtMissionSameCmd(mt_mission_cmd_t *a, mt_mission_cmd_t *b) =
        a->id == b->id && a->frame == b->frame && a->options == b->options &&
        a->param[0] == b->param[0] && a->param[1] == b->param[1] &&
        a->param[2] == b->param[2] && a->param[3] == b->param[3] &&
        a->x == b->x && a->y == b->y && a->z == b->z;

    // the list's commands after home (1 .. n-1) are c's; home is copied
    // too, but a proof of that is not attempted (WP's goal across put_all's
    // 700-entry frame does not finish)
    predicate MtMissionCopied(mt_mission_t *m, mt_mission_cmd_t *c, integer n) =
        \forall integer j; 1 <= j < n ==> MtMissionSameCmd(&m->cmd[j], &c[j]);

    // a counter that fits command c: between 0 and c's repeat count for a
    // finite jump, 0 for any other command
    predicate MtMissionCountFits(integer cnt, mt_mission_cmd_t *c) =
        (MtMissionIsJumpId(c->id) && c->param[1] >= 0) ? 0 <= cnt <= c->param[1] / MT_MISSION_MILLI
                                                       : cnt == 0;

    // the jump counter nc at index i of a new list whose command there is c,
    // over the list of `before` commands it replaces (class ok, counter oc at
    // i): kept where both have a jump at i, at most c's repeat count; else 0
    predicate MtMissionKeptFor(integer ok, integer oc, integer i, integer before,
                               mt_mission_cmd_t *c, integer nc) =
        (MtMissionIsJumpId(c->id) && c->param[1] >= 0 && i < before && ok == MT_MISSION_KIND_JUMP &&
         oc > 0)
            ? nc == (oc < c->param[1] / MT_MISSION_MILLI ? oc : c->param[1] / MT_MISSION_MILLI)
            : nc == 0;

    predicate MtMissionActiveUnchanged{L1, L2}(mt_mission_t *m) =
        \at(m->total, L1) == \at(m->total, L2) &&
        \at(m->generation, L1) == \at(m->generation, L2) &&
        \at(m->state, L1) == \at(m->state, L2) &&
        \at(m->nav, L1) == \at(m->nav, L2) && \at(m->do_cmd, L1) == \at(m->do_cmd, L2) &&
        \at(m->nav_idx, L1) == \at(m->nav_idx, L2) && \at(m->do_idx, L1) == \at(m->do_idx, L2) &&
        \at(m->do_done, L1) == \at(m->do_done, L2) &&
        \at(m->prev_nav, L1) == \at(m->prev_nav, L2) &&
        \at(m->completions, L1) == \at(m->completions, L2) &&
        \forall integer i; 0 <= i < MT_CFG_MISSION_MAX_CMDS ==>
            \at(m->kind[i], L1) == \at(m->kind[i], L2) &&
            \at(m->count[i], L1) == \at(m->count[i], L2) &&
            \at(m->target[i], L1) == \at(m->target[i], L2) &&
            \at(m->repeat[i], L1) == \at(m->repeat[i], L2) &&
            \at(m->cmd[i], L1) == \at(m->cmd[i], L2);
*/

#endif /* MT_SPEC_MISSION_H */
