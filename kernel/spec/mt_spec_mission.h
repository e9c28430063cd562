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

    // mt_mission_check_cmd's rules, one predicate per status it reports; c is one command
    // (params and the location in the fixed point of mt/mission.h; the per-id flags are the
    // command table's, MtMissionFlag*)
    predicate MtMissionFrameOk(mt_mission_cmd_t *c) =
        !MtMissionFlagLoc(c->id) || c->frame == 0 || c->frame == 2 || c->frame == 3 ||
        c->frame == 5 || c->frame == 6 || c->frame == 10 || c->frame == 11;

    predicate MtMissionParamsOk(mt_mission_cmd_t *c) =
        c->param[0] != MT_MISSION_PARAM_NAN && c->param[1] != MT_MISSION_PARAM_NAN &&
        (c->param[2] != MT_MISSION_PARAM_NAN || MtMissionFlagNan3(c->id)) &&
        (c->param[3] != MT_MISSION_PARAM_NAN || MtMissionFlagNan4(c->id)) &&
        (MtMissionFlagNn1(c->id) ==> c->param[0] >= 0) &&
        (MtMissionFlagNn2(c->id) ==> c->param[1] >= 0) &&
        (MtMissionFlagInt1(c->id) ==> c->param[0] % MT_MISSION_MILLI == 0) &&
        (MtMissionFlagInt2(c->id) ==> c->param[1] % MT_MISSION_MILLI == 0);

    // the rules of single commands: yaw angle, direction and relative flag; speed type and
    // speed; set-home's current flag; servo channel and pwm; the tag number
    predicate MtMissionSpecialOk(mt_mission_cmd_t *c) =
        (c->id == MT_MAV_CMD_CONDITION_YAW ==>
            0 <= c->param[0] <= 360 * MT_MISSION_MILLI &&
            (c->param[2] == -MT_MISSION_MILLI || c->param[2] == 0 ||
             c->param[2] == MT_MISSION_MILLI) &&
            (c->param[3] == 0 || c->param[3] == MT_MISSION_MILLI)) &&
        (c->id == MT_MAV_CMD_DO_CHANGE_SPEED ==>
            0 <= c->param[0] <= 3 * MT_MISSION_MILLI && c->param[1] >= -2 * MT_MISSION_MILLI) &&
        (c->id == MT_MAV_CMD_DO_SET_HOME ==>
            c->param[0] == 0 || c->param[0] == MT_MISSION_MILLI) &&
        (c->id == MT_MAV_CMD_DO_SET_SERVO ==>
            MT_MISSION_MILLI <= c->param[0] <= 32 * MT_MISSION_MILLI &&
            c->param[1] <= 65535 * MT_MISSION_MILLI) &&
        (c->id == MT_MAV_CMD_JUMP_TAG ==> c->param[0] <= 65535 * MT_MISSION_MILLI);

    predicate MtMissionLocationOk(mt_mission_cmd_t *c) =
        MtMissionFlagLoc(c->id) ==>
            -MT_MISSION_LAT_MAX <= c->x <= MT_MISSION_LAT_MAX &&
            -MT_MISSION_LON_MAX <= c->y <= MT_MISSION_LON_MAX;

    // a jump's repeat count and whole-number target: DO_JUMP an index after home of an
    // n-command list, DO_JUMP_TAG a 16-bit tag number
    predicate MtMissionJumpArgsOk(mt_mission_cmd_t *c, integer n) =
        MtMissionIsJumpId(c->id) ==>
            MtMissionRepeatOk(c->param[1]) && c->param[0] % MT_MISSION_MILLI == 0 &&
            (c->id == MT_MAV_CMD_DO_JUMP ==> 1 <= c->param[0] / MT_MISSION_MILLI < n) &&
            (c->id == MT_MAV_CMD_DO_JUMP_TAG ==> 0 <= c->param[0] <= 65535 * MT_MISSION_MILLI);

    // st is the status of command i of the n-command list c: the first rule it breaks, in
    // the order id (home must be a waypoint), frame, params, location, jump arguments
    predicate MtMissionCmdStatus(mt_mission_cmd_t *c, integer n, integer i, integer st) =
        (!MtMissionIsKnownId(c[i].id) || (i == 0 && c[i].id != MT_MAV_CMD_WAYPOINT))
            ? st == MT_E_MISSION_CMD
        : !MtMissionFrameOk(&c[i]) ? st == MT_E_MISSION_FRAME
        : (!MtMissionParamsOk(&c[i]) || !MtMissionSpecialOk(&c[i])) ? st == MT_E_MISSION_PARAM
        : !MtMissionLocationOk(&c[i]) ? st == MT_E_MISSION_LOCATION
        : !MtMissionJumpArgsOk(&c[i], n) ? st == MT_E_MISSION_JUMP
        : st == MT_OK;

    // a JUMP_TAG after home carries the tag of command i (a DO_JUMP_TAG)
    predicate MtMissionTagFound(mt_mission_cmd_t *c, integer n, integer i) =
        \exists integer j; 1 <= j < n && c[j].id == MT_MAV_CMD_JUMP_TAG &&
            c[j].param[0] == c[i].param[0];

    // st is the status of entry i in the whole-list check: its command's, then
    // MT_E_MISSION_JUMP for a DO_JUMP_TAG after home whose tag no JUMP_TAG carries
    predicate MtMissionEntryStatus(mt_mission_cmd_t *c, integer n, integer i, integer st) =
        MtMissionCmdStatus(c, n, i, MT_OK)
            ? ((i >= 1 && c[i].id == MT_MAV_CMD_DO_JUMP_TAG && !MtMissionTagFound(c, n, i))
                   ? st == MT_E_MISSION_JUMP : st == MT_OK)
            : MtMissionCmdStatus(c, n, i, st);

    // each entry has one status (proved by WP)
    lemma MtMissionCmdStatus_unique: \forall mt_mission_cmd_t *c, integer n, i, a, b;
        MtMissionCmdStatus(c, n, i, a) ==> MtMissionCmdStatus(c, n, i, b) ==> a == b;
    lemma MtMissionEntryStatus_unique: \forall mt_mission_cmd_t *c, integer n, i, a, b;
        MtMissionEntryStatus(c, n, i, a) ==> MtMissionEntryStatus(c, n, i, b) ==> a == b;

    predicate MtMissionEntriesOk(mt_mission_cmd_t *c, integer n, integer k) =
        \forall integer j; 0 <= j < k ==> MtMissionEntryStatus(c, n, j, MT_OK);

    // c[0 .. n-1] holds the same values at L1 and L2 in every field the list check reads; the
    // lemmas after it (proved by WP) carry the check's verdicts across such states, which WP
    // needs because the check's scratch writes share C types with the list's fields
    predicate MtMissionCmdsKept{L1, L2}(mt_mission_cmd_t *c, integer n) =
        \forall integer j; 0 <= j < n ==>
            \at(c[j].id, L1) == \at(c[j].id, L2) && \at(c[j].frame, L1) == \at(c[j].frame, L2) &&
            \at(c[j].param[0], L1) == \at(c[j].param[0], L2) &&
            \at(c[j].param[1], L1) == \at(c[j].param[1], L2) &&
            \at(c[j].param[2], L1) == \at(c[j].param[2], L2) &&
            \at(c[j].param[3], L1) == \at(c[j].param[3], L2) &&
            \at(c[j].x, L1) == \at(c[j].x, L2) && \at(c[j].y, L1) == \at(c[j].y, L2);
    lemma MtMissionCmdStatus_kept{L1, L2}: \forall mt_mission_cmd_t *c, integer n, i, st;
        0 <= i < n ==> MtMissionCmdsKept{L1, L2}(c, n) ==> MtMissionCmdStatus{L1}(c, n, i, st) ==>
        MtMissionCmdStatus{L2}(c, n, i, st);
    lemma MtMissionTagFound_kept{L1, L2}: \forall mt_mission_cmd_t *c, integer n, i;
        0 <= i < n ==> MtMissionCmdsKept{L1, L2}(c, n) ==> MtMissionTagFound{L1}(c, n, i) ==>
        MtMissionTagFound{L2}(c, n, i);
    lemma MtMissionEntryStatus_kept{L1, L2}: \forall mt_mission_cmd_t *c, integer n, i, st;
        0 <= i < n ==> MtMissionCmdsKept{L1, L2}(c, n) ==> MtMissionCmdsKept{L2, L1}(c, n) ==>
        MtMissionEntryStatus{L1}(c, n, i, st) ==> MtMissionEntryStatus{L2}(c, n, i, st);
    lemma MtMissionEntriesOk_kept{L1, L2}: \forall mt_mission_cmd_t *c, integer n, k;
        k <= n ==> MtMissionCmdsKept{L1, L2}(c, n) ==> MtMissionEntriesOk{L1}(c, n, k) ==>
        MtMissionEntriesOk{L2}(c, n, k);

    // what the whole-list check of c[0 .. n-1] reports (status r, index bad) before its loop
    // rule: the first faulty entry, with its status; with no faulty entry, MT_OK or the loop
    // rule's MT_E_MISSION_LOOP
    predicate MtMissionListReported(mt_mission_cmd_t *c, integer n, integer r, integer bad) =
        MtMissionEntriesOk(c, n, n)
            ? (r == MT_OK || r == MT_E_MISSION_LOOP)
            : (0 <= bad < n && r != MT_OK && MtMissionEntryStatus(c, n, bad, r) &&
               MtMissionEntriesOk(c, n, bad));

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
