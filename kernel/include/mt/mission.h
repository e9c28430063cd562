/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/mission.h
 * @brief Mission-command sequencer with AP_Mission's semantics, its known
 *        defects removed (ardupilot.md §1.5, §2 items 22-27, §3.5).
 *
 * Operating rules
 * - One thread owns a mission object (the vehicle's main loop); no function
 *   here takes the kernel lock or blocks. mt_mission_update runs at >= 10 Hz.
 * - Index 0 is home and is never executed. Commands are nav (move the vehicle;
 *   the nav cursor waits for verify), do/condition (run one at a time by the
 *   do cursor), jumps (DO_JUMP 177, DO_JUMP_TAG 601: resolved here, never
 *   given to a callback) and tags (JUMP_TAG 600: a marker, resolved here).
 * - The sequence executed is one walk over the list that follows jumps; a jump
 *   with repeat r >= 0 is taken r times, then falls through and its counter is
 *   reset to 0 (AP's default since PR #29763); r == -1 is taken forever.
 *   Counters live in RAM, one per command index (the table is sized from the
 *   mission, so it can never be full: A-6).
 * - Do ordering (AP): the do commands between nav N(k) and nav N(k+1) start
 *   when N(k) has completed, one after the other (each after the previous one
 *   verified), while N(k+1) is the active nav command; those not finished when
 *   N(k+1) completes are dropped. Do commands before the first nav command run
 *   while the first one is active; do commands after the last nav command are
 *   not started (the mission completes when the last nav command does).
 * - A nav command whose start callback returns false counts as completed at
 *   once (skipped); a do command whose start returns false counts as done.
 * - mt_mission_update performs at most one nav start and one do start per
 *   call, and every walk over the list is bounded by the command count (a
 *   validated mission has no loop without a nav command, so no walk can spin).
 * - Validation, then apply (seL4 style): mt_mission_load checks the whole
 *   candidate list first; on any problem it returns the status and the
 *   offending index and leaves the active mission untouched. Loading is
 *   refused while the mission runs (stop it first).
 * - Units: no floating point. Params 1..4 are fixed point with 3 decimals
 *   (MT_MISSION_MILLI); MT_MISSION_PARAM_NAN stands for a NaN param (allowed
 *   only where AP allows it). x/y are latitude/longitude in 1e-7 degrees for
 *   every command (other uses of x/y are limited to the same range), z is in
 *   centimetres. Converting a file's floats (and rejecting inf) is the file
 *   layer's job (mission/wpl.h).
 *
 * Reference defects fixed: A-1 the nav advance either loads a nav command or
 * completes the mission (no 255-iteration wrap); A-2 do-only loops are
 * rejected at load (MT_E_MISSION_LOOP) and every walk is bounded; A-3 the
 * look-ahead follows jumps exactly as execution does; A-5 bad jump targets are
 * rejected at load; A-6 no jump table to fill, look-ahead functions are pure;
 * A-7 there is no uncounted resume replay; A-11 mt_mission_get compares
 * indices; A-12 a failed call changes nothing; A-13 whole-mission validation.
 * A-9 (rewind resume, a division by the leg length) is not implemented: resume
 * restarts the current commands; the kernel module has no division by a
 * distance anywhere.
 */
#ifndef MT_MISSION_H
#define MT_MISSION_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/config.h"
#include "mt/status.h"
#include "mt_spec.h"

#ifdef __cplusplus
extern "C" {
#endif

/** MAVLink MAV_CMD numbers the module knows (the full list is mission.c's table). */
#define MT_MAV_CMD_WAYPOINT 16u
#define MT_MAV_CMD_LOITER_UNLIM 17u
#define MT_MAV_CMD_LOITER_TURNS 18u
#define MT_MAV_CMD_LOITER_TIME 19u
#define MT_MAV_CMD_RETURN_TO_LAUNCH 20u
#define MT_MAV_CMD_LAND 21u
#define MT_MAV_CMD_TAKEOFF 22u
#define MT_MAV_CMD_SPLINE_WAYPOINT 82u
#define MT_MAV_CMD_CONDITION_DELAY 112u
#define MT_MAV_CMD_CONDITION_DISTANCE 114u
#define MT_MAV_CMD_CONDITION_YAW 115u
#define MT_MAV_CMD_DO_JUMP 177u
#define MT_MAV_CMD_DO_CHANGE_SPEED 178u
#define MT_MAV_CMD_DO_SET_HOME 179u
#define MT_MAV_CMD_DO_SET_SERVO 183u
#define MT_MAV_CMD_DO_LAND_START 189u
#define MT_MAV_CMD_JUMP_TAG 600u
#define MT_MAV_CMD_DO_JUMP_TAG 601u

/** Fixed-point scale of params 1..4: 1.5 is stored as 1500. */
#define MT_MISSION_MILLI 1000
/** A NaN param (only where the command allows it). */
#define MT_MISSION_PARAM_NAN INT32_MIN
/** "No command" index. */
#define MT_MISSION_NONE 0xFFFFu
/** Largest finite repeat count of a jump. */
#define MT_MISSION_REPEAT_MAX 32767
/** Latitude / longitude limits in 1e-7 degrees. */
#define MT_MISSION_LAT_MAX 900000000
#define MT_MISSION_LON_MAX 1800000000

/** Command classes (derived from the id at load). */
#define MT_MISSION_KIND_HOME 0u
#define MT_MISSION_KIND_NAV 1u
#define MT_MISSION_KIND_DO 2u   /**< do and condition commands */
#define MT_MISSION_KIND_JUMP 3u /**< DO_JUMP, DO_JUMP_TAG */
#define MT_MISSION_KIND_TAG 4u  /**< JUMP_TAG */

/** Mission states (AP numbering). */
#define MT_MISSION_STOPPED 0u
#define MT_MISSION_RUNNING 1u
#define MT_MISSION_COMPLETE 2u

/** One mission command as the kernel stores it (32 bytes, no padding). */
typedef struct {
    uint16_t id;      /**< MAV_CMD number */
    uint8_t frame;    /**< MAV_FRAME number */
    uint8_t options;  /**< file-layer flags (autocontinue in bit 0); not interpreted */
    int32_t param[4]; /**< params 1..4, x MT_MISSION_MILLI, or MT_MISSION_PARAM_NAN */
    int32_t x;        /**< latitude, 1e-7 degree */
    int32_t y;        /**< longitude, 1e-7 degree */
    int32_t z;        /**< altitude, cm */
} mt_mission_cmd_t;

/** Start / verify callback: index of the command in the list and the command.
 *  Must not write the mission object (assumption A1, see mt_mission_invoke.h). */
typedef bool (*mt_mission_cmd_fn_t)(void *ctx, uint16_t index, const mt_mission_cmd_t *cmd);
/** Mission-complete callback. */
typedef void (*mt_mission_done_fn_t)(void *ctx);

typedef struct {
    /* active mission (written only by apply) */
    mt_mission_cmd_t cmd[MT_CFG_MISSION_MAX_CMDS];
    uint8_t kind[MT_CFG_MISSION_MAX_CMDS];     /**< MT_MISSION_KIND_* of cmd[i] */
    uint16_t target[MT_CFG_MISSION_MAX_CMDS];  /**< jumps: resolved target index */
    int16_t repeat[MT_CFG_MISSION_MAX_CMDS];   /**< jumps: repeat count, -1 forever */
    int16_t count[MT_CFG_MISSION_MAX_CMDS];    /**< jumps: times taken since the last reset */
    uint16_t total;                            /**< commands, home included (0: none) */
    uint32_t generation;                       /**< incremented by every successful load */
    /* cursors */
    uint8_t state;     /**< MT_MISSION_STOPPED / RUNNING / COMPLETE */
    uint8_t do_done;   /**< 1: the do walk has reached the active nav command */
    uint16_t nav;      /**< active nav command or MT_MISSION_NONE */
    uint16_t do_cmd;   /**< active do command or MT_MISSION_NONE */
    uint16_t wpos;     /**< next index the execution walk visits (total: end) */
    uint16_t prev_nav; /**< last nav command that completed, or MT_MISSION_NONE */
    uint32_t completions; /**< times the complete callback was called */
    /* vehicle callbacks */
    mt_mission_cmd_fn_t start_fn;
    mt_mission_cmd_fn_t verify_fn;
    mt_mission_done_fn_t complete_fn;
    void *ctx;
} mt_mission_t;

/** Validation work space of the module (not part of any mission object). */
extern uint8_t mt_mission_scratch_safe[MT_CFG_MISSION_MAX_CMDS];
extern uint16_t mt_mission_scratch_target[MT_CFG_MISSION_MAX_CMDS];

/*@ predicate MtMissionIsJumpId(integer id) = id == MT_MAV_CMD_DO_JUMP || id == MT_MAV_CMD_DO_JUMP_TAG;
    predicate MtMissionIsCallbackId(integer id) = !MtMissionIsJumpId(id) && id != MT_MAV_CMD_JUMP_TAG;

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

    predicate MtMissionCursors(mt_mission_t *m) =
        (m->state == MT_MISSION_STOPPED || m->state == MT_MISSION_RUNNING ||
         m->state == MT_MISSION_COMPLETE) &&
        MtMissionCursor(m, m->nav, MT_MISSION_KIND_NAV) &&
        MtMissionCursor(m, m->prev_nav, MT_MISSION_KIND_NAV) &&
        MtMissionCursor(m, m->do_cmd, MT_MISSION_KIND_DO) &&
        (m->do_cmd != MT_MISSION_NONE ==> m->nav != MT_MISSION_NONE) &&
        (m->do_done == 0 || m->do_done == 1) &&
        (m->state != MT_MISSION_STOPPED ==> m->total >= 2) &&
        (m->total == 0 ==> m->wpos == 0) &&
        (m->total >= 1 ==> 1 <= m->wpos <= m->total);

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

    predicate MtMissionActiveUnchanged{L1, L2}(mt_mission_t *m) =
        \at(m->total, L1) == \at(m->total, L2) &&
        \at(m->generation, L1) == \at(m->generation, L2) &&
        \at(m->state, L1) == \at(m->state, L2) &&
        \at(m->nav, L1) == \at(m->nav, L2) && \at(m->do_cmd, L1) == \at(m->do_cmd, L2) &&
        \at(m->wpos, L1) == \at(m->wpos, L2) && \at(m->do_done, L1) == \at(m->do_done, L2) &&
        \at(m->prev_nav, L1) == \at(m->prev_nav, L2) &&
        \at(m->completions, L1) == \at(m->completions, L2) &&
        \forall integer i; 0 <= i < MT_CFG_MISSION_MAX_CMDS ==>
            \at(m->kind[i], L1) == \at(m->kind[i], L2) &&
            \at(m->count[i], L1) == \at(m->count[i], L2) &&
            \at(m->target[i], L1) == \at(m->target[i], L2) &&
            \at(m->repeat[i], L1) == \at(m->repeat[i], L2) &&
            \at(m->cmd[i], L1) == \at(m->cmd[i], L2);
*/

/** Classify a command id: MT_MISSION_KIND_NAV / DO / JUMP / TAG; 0 (HOME) when
 *  the id is unknown. [any context, pure] */
/*@ assigns \nothing;
    ensures jump: \result == MT_MISSION_KIND_JUMP <==> MtMissionIsJumpId(id);
    ensures tag: \result == MT_MISSION_KIND_TAG <==> id == MT_MAV_CMD_JUMP_TAG;
    ensures range: \result <= MT_MISSION_KIND_TAG;
*/
uint8_t mt_mission_kind_of(uint16_t id);

/** Initialise an empty mission (no commands, STOPPED). */
/*@ requires valid: \valid(m);
    requires sep: \separated(m, mt_mission_scratch_safe + (0 .. MT_CFG_MISSION_MAX_CMDS - 1),
                             mt_mission_scratch_target + (0 .. MT_CFG_MISSION_MAX_CMDS - 1));
    requires callbacks: start_fn != \null && verify_fn != \null && complete_fn != \null;
    assigns *m;
    ensures inv: MtMissionInv(m);
    ensures empty: m->total == 0 && m->state == MT_MISSION_STOPPED && m->generation == 0;
    ensures no_cursor: m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE;
*/
void mt_mission_init(mt_mission_t *m, mt_mission_cmd_fn_t start_fn, mt_mission_cmd_fn_t verify_fn,
                     mt_mission_done_fn_t complete_fn, void *ctx);

/** Check one command of a candidate list (ids, params, NaN rules, frames,
 *  location ranges, jump target/repeat ranges). Pure.
 *  @retval MT_OK, MT_E_MISSION_CMD, MT_E_MISSION_PARAM, MT_E_MISSION_LOCATION,
 *          MT_E_MISSION_FRAME, MT_E_MISSION_JUMP */
/*@ requires cmds: MtMissionCmdsIn(cmds, n);
    requires index: 0 <= i < n;
    assigns \nothing;
    ensures jump_ok: \result == MT_OK ==> MtMissionJumpCmdOk(cmds, n, i);
    ensures target_ok: \result == MT_OK ==> i >= 1 ==> cmds[i].id == MT_MAV_CMD_DO_JUMP ==>
        1 <= cmds[i].param[0] / MT_MISSION_MILLI < n && cmds[i].param[0] % MT_MISSION_MILLI == 0;
    ensures status: \result == MT_OK || \result == MT_E_MISSION_CMD || \result == MT_E_MISSION_PARAM ||
                    \result == MT_E_MISSION_LOCATION || \result == MT_E_MISSION_FRAME ||
                    \result == MT_E_MISSION_JUMP;
*/
mt_status_t mt_mission_check_cmd(const mt_mission_cmd_t *cmds, uint16_t n, uint16_t i);

/** Check a whole candidate list: size, every command (mt_mission_check_cmd),
 *  jump tags, and that every loop contains a nav command. The mission object
 *  is only read (its active mission is untouched); the work space is the
 *  module's validation scratch, so checks and loads must not run in two
 *  threads at once.
 *  @retval MT_OK (*bad = MT_MISSION_NONE)
 *  @retval MT_E_MISSION_SIZE (*bad = 0), or any status of mt_mission_check_cmd,
 *          or MT_E_MISSION_JUMP (unknown tag), MT_E_MISSION_LOOP, with *bad
 *          the offending index. */
/*@ requires inv: MtMissionInv(m);
    requires cmds: n < 1 || n > MT_CFG_MISSION_MAX_CMDS || MtMissionCmdsIn(cmds, n);
    requires sep: \separated(cmds + (0 .. n - 1), m) && \separated(bad, m, cmds + (0 .. n - 1));
    requires sep_scratch: \separated(bad, mt_mission_scratch_safe + (0 .. MT_CFG_MISSION_MAX_CMDS - 1),
                                      mt_mission_scratch_target + (0 .. MT_CFG_MISSION_MAX_CMDS - 1)) &&
        \separated(cmds + (0 .. n - 1), mt_mission_scratch_safe + (0 .. MT_CFG_MISSION_MAX_CMDS - 1),
                   mt_mission_scratch_target + (0 .. MT_CFG_MISSION_MAX_CMDS - 1));
    requires bad: \valid(bad);
    assigns mt_mission_scratch_safe[0 .. MT_CFG_MISSION_MAX_CMDS - 1],
            mt_mission_scratch_target[0 .. MT_CFG_MISSION_MAX_CMDS - 1], *bad;
    ensures inv: MtMissionInv(m);
    ensures untouched: MtMissionActiveUnchanged{Pre, Post}(m);
    behavior ok:
      assumes 1 <= n <= MT_CFG_MISSION_MAX_CMDS;
      ensures located: \result == MT_OK <==> *bad == MT_MISSION_NONE;
      ensures in_range: \result != MT_OK ==> *bad < n;
      ensures targets: \result == MT_OK ==> MtMissionStaged(&mt_mission_scratch_target[0], cmds, n);
    behavior bad_size:
      assumes n < 1 || n > MT_CFG_MISSION_MAX_CMDS;
      ensures status: \result == MT_E_MISSION_SIZE && *bad == 0;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_mission_check(const mt_mission_t *m, const mt_mission_cmd_t *cmds, uint16_t n, uint16_t *bad);

/** Validate cmds[0 .. n-1], then make it the active mission (STOPPED, cursors
 *  at the start, counters zero, generation + 1).
 *  @retval MT_OK
 *  @retval MT_E_STATE the mission is running (nothing changes)
 *  @retval any status of mt_mission_check, with *bad the offending index;
 *          the active mission is untouched. */
/*@ requires inv: MtMissionInv(m);
    requires cmds: n < 1 || n > MT_CFG_MISSION_MAX_CMDS || MtMissionCmdsIn(cmds, n);
    requires sep: \separated(cmds + (0 .. n - 1), m) && \separated(bad, m, cmds + (0 .. n - 1));
    requires sep_scratch: \separated(bad, mt_mission_scratch_safe + (0 .. MT_CFG_MISSION_MAX_CMDS - 1),
                                      mt_mission_scratch_target + (0 .. MT_CFG_MISSION_MAX_CMDS - 1)) &&
        \separated(cmds + (0 .. n - 1), mt_mission_scratch_safe + (0 .. MT_CFG_MISSION_MAX_CMDS - 1),
                   mt_mission_scratch_target + (0 .. MT_CFG_MISSION_MAX_CMDS - 1));
    requires bad: \valid(bad);
    assigns *m, *bad, mt_mission_scratch_safe[0 .. MT_CFG_MISSION_MAX_CMDS - 1],
            mt_mission_scratch_target[0 .. MT_CFG_MISSION_MAX_CMDS - 1];
    ensures inv: MtMissionInv(m);
    behavior running:
      assumes m->state == MT_MISSION_RUNNING;
      ensures status: \result == MT_E_STATE;
      ensures untouched: MtMissionActiveUnchanged{Pre, Post}(m);
    behavior not_running:
      assumes m->state != MT_MISSION_RUNNING;
      ensures loaded: \result == MT_OK ==> m->total == n && m->state == MT_MISSION_STOPPED &&
          m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE && m->wpos == 1 &&
          (m->generation == \old(m->generation) + 1 || \old(m->generation) == 0xFFFFFFFF);
      ensures rejected: \result != MT_OK ==> MtMissionActiveUnchanged{Pre, Post}(m);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_mission_load(mt_mission_t *m, const mt_mission_cmd_t *cmds, uint16_t n, uint16_t *bad);

/** Start from the first command: counters reset, RUNNING, and one start
 *  attempt on the first nav command (if its start callback refuses, it counts
 *  as completed and the next update loads the following one; with no nav
 *  command at all the mission completes at once).
 *  @retval MT_OK
 *  @retval MT_E_EMPTY no command besides home (nothing changes) */
/*@ requires inv: MtMissionInv(m);
    assigns *m, MtPortNow;
    ensures inv: MtMissionInv(m);
    behavior empty:
      assumes m->total < 2;
      ensures status: \result == MT_E_EMPTY;
      ensures untouched: MtMissionActiveUnchanged{Pre, Post}(m);
    behavior started:
      assumes m->total >= 2;
      ensures status: \result == MT_OK;
      ensures state: m->state == MT_MISSION_RUNNING || m->state == MT_MISSION_COMPLETE;
      ensures same_mission: m->total == \old(m->total) && m->generation == \old(m->generation);
      ensures complete_once: m->completions == \old(m->completions) + (m->state == MT_MISSION_COMPLETE ? 1 : 0) ||
          \old(m->completions) == 0xFFFFFFFF;
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_mission_start(mt_mission_t *m);

/** RUNNING -> STOPPED, cursors kept.
 *  @retval MT_OK
 *  @retval MT_E_STATE not running (nothing changes) */
/*@ requires inv: MtMissionInv(m);
    assigns m->state;
    ensures inv: MtMissionInv(m);
    behavior running:
      assumes m->state == MT_MISSION_RUNNING;
      ensures status: \result == MT_OK && m->state == MT_MISSION_STOPPED;
    behavior other:
      assumes m->state != MT_MISSION_RUNNING;
      ensures status: \result == MT_E_STATE && m->state == \old(m->state);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_mission_stop(mt_mission_t *m);

/** STOPPED -> RUNNING: the active nav and do commands are started again (a new
 *  load of each); without an active nav command the next update advances from
 *  the current position. COMPLETE -> mt_mission_start.
 *  @retval MT_OK
 *  @retval MT_E_STATE already running (nothing changes)
 *  @retval MT_E_EMPTY no command besides home (nothing changes) */
/*@ requires inv: MtMissionInv(m);
    assigns *m, MtPortNow;
    ensures inv: MtMissionInv(m);
    behavior running:
      assumes m->state == MT_MISSION_RUNNING;
      ensures status: \result == MT_E_STATE;
      ensures untouched: MtMissionActiveUnchanged{Pre, Post}(m);
    behavior empty:
      assumes m->state != MT_MISSION_RUNNING && m->total < 2;
      ensures status: \result == MT_E_EMPTY;
      ensures untouched: MtMissionActiveUnchanged{Pre, Post}(m);
    behavior resumed:
      assumes m->state != MT_MISSION_RUNNING && m->total >= 2;
      ensures status: \result == MT_OK;
      ensures state: m->state == MT_MISSION_RUNNING || m->state == MT_MISSION_COMPLETE;
      ensures same_mission: m->total == \old(m->total) && m->generation == \old(m->generation);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_mission_resume(mt_mission_t *m);

/** Make index i the next command to execute (AP set_current_cmd). i == 0
 *  means 1 with jump counters reset; a COMPLETE mission also resets them.
 *  RUNNING: the active commands are dropped and the nav command at or after
 *  i is started now. Otherwise: the position is set and the state becomes
 *  STOPPED; mt_mission_resume continues from there.
 *  @retval MT_OK
 *  @retval MT_E_EMPTY no command besides home (nothing changes)
 *  @retval MT_E_INVALID i >= count (nothing changes) */
/*@ requires inv: MtMissionInv(m);
    assigns *m, MtPortNow;
    ensures inv: MtMissionInv(m);
    behavior empty:
      assumes m->total < 2;
      ensures status: \result == MT_E_EMPTY;
      ensures untouched: MtMissionActiveUnchanged{Pre, Post}(m);
    behavior bad_index:
      assumes m->total >= 2 && i >= m->total;
      ensures status: \result == MT_E_INVALID;
      ensures untouched: MtMissionActiveUnchanged{Pre, Post}(m);
    behavior running:
      assumes m->total >= 2 && i < m->total && m->state == MT_MISSION_RUNNING;
      ensures status: \result == MT_OK;
      ensures state: m->state == MT_MISSION_RUNNING || m->state == MT_MISSION_COMPLETE;
      ensures same_mission: m->total == \old(m->total) && m->generation == \old(m->generation);
    behavior not_running:
      assumes m->total >= 2 && i < m->total && m->state != MT_MISSION_RUNNING;
      ensures status: \result == MT_OK;
      ensures state: m->state == MT_MISSION_STOPPED;
      ensures position: m->wpos == (i == 0 ? 1 : i) && m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE;
      ensures same_mission: m->total == \old(m->total) && m->generation == \old(m->generation);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_mission_set_current(mt_mission_t *m, uint16_t i);

/** Start the active nav command again (after a mission change or a mode
 *  switch); the do cursor is kept. A refused start completes the command.
 *  @retval MT_OK
 *  @retval MT_E_STATE not running, or no active nav command (nothing changes) */
/*@ requires inv: MtMissionInv(m);
    assigns *m, MtPortNow;
    ensures inv: MtMissionInv(m);
    behavior active:
      assumes m->state == MT_MISSION_RUNNING && m->nav != MT_MISSION_NONE;
      ensures status: \result == MT_OK;
      ensures same_mission: m->total == \old(m->total) && m->generation == \old(m->generation);
    behavior other:
      assumes !(m->state == MT_MISSION_RUNNING && m->nav != MT_MISSION_NONE);
      ensures status: \result == MT_E_STATE;
      ensures untouched: MtMissionActiveUnchanged{Pre, Post}(m);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_mission_restart_current(mt_mission_t *m);

/** One sequencing step: verify the active nav command (advance when it
 *  completed, or load one when none is active), then verify the active do
 *  command or start the next one. At most one nav start and one do start.
 *  @retval MT_OK
 *  @retval MT_E_STATE not running (nothing changes) */
/*@ requires inv: MtMissionInv(m);
    assigns *m, MtPortNow;
    ensures inv: MtMissionInv(m);
    behavior running:
      assumes m->state == MT_MISSION_RUNNING;
      ensures status: \result == MT_OK;
      ensures state: m->state == MT_MISSION_RUNNING || m->state == MT_MISSION_COMPLETE;
      ensures same_mission: m->total == \old(m->total) && m->generation == \old(m->generation);
      ensures complete_once: m->completions == \old(m->completions) + (m->state == MT_MISSION_COMPLETE ? 1 : 0) ||
          \old(m->completions) == 0xFFFFFFFF;
    behavior other:
      assumes m->state != MT_MISSION_RUNNING;
      ensures status: \result == MT_E_STATE;
      ensures untouched: MtMissionActiveUnchanged{Pre, Post}(m);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_mission_update(mt_mission_t *m);

/** The nav command the execution walk reaches first from index `from` with
 *  the current jump counters (from == the execution position gives the nav
 *  command that is or will be active next). Pure; visits at most `count`
 *  commands.
 *  @retval MT_OK *out = that index
 *  @retval MT_E_EMPTY the walk reaches the end (*out = MT_MISSION_NONE)
 *  @retval MT_E_INVALID from is 0 or >= count (*out = MT_MISSION_NONE)
 *  @retval MT_E_MISSION_LOOP the bound was hit (impossible for a validated
 *          mission; *out = MT_MISSION_NONE) */
/*@ requires inv: MtMissionInv(m);
    requires out: \valid(out) && \separated(out, m);
    assigns *out;
    ensures found: \result == MT_OK ==> MtMissionIdx(m, *out) && m->kind[*out] == MT_MISSION_KIND_NAV;
    ensures none: \result != MT_OK ==> *out == MT_MISSION_NONE;
    ensures status: \result == MT_OK || \result == MT_E_EMPTY || \result == MT_E_INVALID ||
                    \result == MT_E_MISSION_LOOP;
    ensures bad_from: (from < 1 || from >= m->total) ==> \result == MT_E_INVALID;
*/
mt_status_t mt_mission_next_nav(const mt_mission_t *m, uint16_t from, uint16_t *out);

/** Copy command i (0 = home) and say whether it is the active nav command.
 *  @retval MT_OK
 *  @retval MT_E_INVALID i >= count (nothing written) */
/*@ requires inv: MtMissionInv(m);
    requires out: \valid(out) && \valid(is_current) && \separated(out, is_current, m);
    assigns *out, *is_current;
    behavior ok:
      assumes i < m->total;
      ensures status: \result == MT_OK;
      ensures copy: MtMissionSameCmd(out, &m->cmd[i]);
      ensures current: *is_current == (i == m->nav);
    behavior bad:
      assumes i >= m->total;
      ensures status: \result == MT_E_INVALID;
      ensures untouched: *out == \old(*out) && *is_current == \old(*is_current);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_mission_get(const mt_mission_t *m, uint16_t i, mt_mission_cmd_t *out, bool *is_current);

/** Times the jump at index i was taken since its last reset (0 for others). Pure. */
/*@ requires inv: MtMissionInv(m);
    assigns \nothing;
    ensures bounded: MtMissionIdx(m, i) && m->kind[i] == MT_MISSION_KIND_JUMP && m->repeat[i] >= 0 ==>
        0 <= \result <= m->repeat[i];
    ensures other: !(MtMissionIdx(m, i) && m->kind[i] == MT_MISSION_KIND_JUMP) ==> \result == 0;
*/
int32_t mt_mission_jump_count(const mt_mission_t *m, uint16_t i);

#ifdef __cplusplus
}
#endif

#endif /* MT_MISSION_H */
