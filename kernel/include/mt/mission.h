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
 * Sequencing (ArduPilot's AP_Mission: update, advance_current_nav_cmd,
 * advance_current_do_cmd, get_next_cmd, get_next_do_cmd, set_current_cmd,
 * resume, restart_current_nav_cmd; AP's names in brackets)
 * - Jump resolution [get_next_cmd]: from an index, jumps are followed until a
 *   command that is not a jump. A jump with repeat r >= 0 is taken while its
 *   counter is below r; otherwise the walk falls through. The nav advance
 *   counts: each jump taken increments its counter, and a jump that falls
 *   through resets its counter to 0 (AP's default since PR #29763). The do
 *   search and the look-ahead do not count. r == -1 is taken forever.
 *   Counters live in RAM, one per command index (the table is sized from the
 *   mission, so it can never be full: A-6).
 * - Nav advance [advance_current_nav_cmd], when the active nav command has
 *   verified (or none is active): the active do command is dropped; the walk
 *   starts one past the last nav command set (nav_idx), or at a given index.
 *   Each command it reaches: a nav command becomes nav_idx and is started; if
 *   its start callback returns true it is the active nav command and the walk
 *   stops, if false it is skipped and the walk goes on in the same call. A do
 *   command (or a JUMP_TAG) is started only if no do command is active yet:
 *   so the first do command between two nav commands starts before the next
 *   nav command, in the same call; the others are passed. Reaching the end of
 *   the list completes the mission, also after a do command was started there
 *   (a trailing DO_PARACHUTE starts, then the mission completes). With no do
 *   command started, do_done is set.
 * - Do search [advance_current_do_cmd, get_next_do_cmd], once per update when
 *   no do command is active and do_done is clear: the next command after
 *   do_idx (jumps followed with the counters the advance left) starts if it
 *   is a do command; a nav command or the end sets do_done. So the do commands
 *   between two nav commands start one at a time, each at the update after the
 *   previous one verified, while the later nav command runs (a condition holds
 *   back the do commands behind it, never the nav command; those not started
 *   when that nav command verifies, or cut off by a refused nav start, are
 *   dropped; behind a finite jump the search sees the counter, AP #30376).
 * - mt_mission_update [update]: verify the active nav command, and when it
 *   verifies, advance (the end completes the mission and ends the call);
 *   with no active nav command, advance. Then the do part: verify the active
 *   do command (a verified one is no longer active), or run the do search.
 *   A do command started by the advance is verified in the same call.
 * - Callbacks: nav and do commands go to the start/verify callbacks; a do
 *   command's start result is ignored (it stays active until it verifies).
 *   Jumps (DO_JUMP 177, DO_JUMP_TAG 601) are resolved here and never passed
 *   to a callback. JUMP_TAG 600 takes the do slot like a do command but is
 *   handled here (AP's library starts it itself and verifies it true at once):
 *   no callback, verified at the first verify. AP's library also starts and
 *   verifies some do commands itself (servo, relay, camera, parachute...);
 *   here the vehicle's callbacks do that part.
 * - Start [start]: counters and cursors reset, RUNNING, advance from index 1.
 *   Resume [resume]: from COMPLETE, or with no nav command ever set, start;
 *   from STOPPED: RUNNING, then set_current at the active do command if any,
 *   else at the active nav command (both start again; jumps between them are
 *   counted again, as AP does). Set-current [set_current_cmd] at i: i == 0
 *   (and any i on a COMPLETE mission) resets the counters; RUNNING: drop both
 *   commands and advance from i; otherwise walk from i, counting, to the
 *   first nav command and make it (and the first do command passed) active
 *   without starting them, and STOP; resume starts them.
 * - Every walk is bounded: a resolution by the command count, the nav advance
 *   by the command count plus 255 (AP: 255 in all, so a stretch of 255 do
 *   commands stalls it, A-1), the stopped walk by the command count. A
 *   validated mission reaches a nav command within the command count; only
 *   nav starts refused in a loop can exhaust the advance, which then
 *   completes the mission.
 * - Validation, then apply (seL4 style): mt_mission_load checks the whole
 *   candidate list first; on any problem it returns the status and the
 *   offending index and leaves the active mission untouched. Loading is
 *   refused while the mission runs; mt_mission_replace swaps a running
 *   mission (validated the same way) and continues at the same index, or
 *   stops when that index is gone.
 * - Units: no floating point. Params 1..4 are fixed point with 3 decimals
 *   (MT_MISSION_MILLI); MT_MISSION_PARAM_NAN stands for a NaN param (allowed
 *   only where AP allows it). x/y are latitude/longitude in 1e-7 degrees for
 *   every command (other uses of x/y are limited to the same range), z is in
 *   centimetres. Converting a file's floats (and rejecting inf) is the file
 *   layer's job (mission/wpl.h).
 *
 * Reference defects fixed: A-1 the nav advance either loads a nav command or
 * completes the mission (AP's 255-iteration guard leaves it running with
 * nothing loaded); A-2 do-only loops are
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

/** MAVLink MAV_CMD numbers the module knows (the full list is mission_check.c's table). */
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
    uint8_t kind[MT_CFG_MISSION_MAX_CMDS];    /**< MT_MISSION_KIND_* of cmd[i] */
    uint16_t target[MT_CFG_MISSION_MAX_CMDS]; /**< jumps: resolved target index */
    int16_t repeat[MT_CFG_MISSION_MAX_CMDS];  /**< jumps: repeat count, -1 forever */
    int16_t count[MT_CFG_MISSION_MAX_CMDS];   /**< jumps: times taken since the last reset */
    uint16_t total;                           /**< commands, home included (0: none) */
    uint32_t generation;                      /**< incremented by every successful load */
    /* cursors (AP_Mission's names in brackets) */
    uint8_t state;   /**< MT_MISSION_STOPPED / RUNNING / COMPLETE */
    uint8_t do_done; /**< 1: no do command left before the active nav command [do_cmd_all_done] */
    uint16_t nav;    /**< active nav command or MT_MISSION_NONE [_nav_cmd, when loaded] */
    uint16_t
        do_cmd; /**< active do command (or JUMP_TAG) or MT_MISSION_NONE [_do_cmd, when loaded] */
    uint16_t nav_idx;     /**< last nav command set, started or refused, or NONE [_nav_cmd.index] */
    uint16_t do_idx;      /**< last do command set, or NONE [_do_cmd.index] */
    uint16_t prev_nav;    /**< nav_idx before the advance last set it, or NONE [_prev_nav_cmd_index] */
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

/* The sequencer's ACSL logic and predicates (empty to a C compiler), after the types they read. */
// cppcheck-suppress misra-c2012-20.1 ; D-107 ACSL only, included after the types it names
#include "mt_spec_mission.h"

/** Classify a command id: MT_MISSION_KIND_NAV / DO / JUMP / TAG; 0 (HOME) when
 *  the id is unknown (not in the command table; the ids of each class are in
 *  mt_spec_mission_cmds.h, generated with the table). [any context, pure] */
/*@ assigns \nothing;
    ensures jump: \result == MT_MISSION_KIND_JUMP <==> MtMissionIsJumpId(id);
    ensures tag: \result == MT_MISSION_KIND_TAG <==> id == MT_MAV_CMD_JUMP_TAG;
    ensures nav: \result == MT_MISSION_KIND_NAV <==> MtMissionIsNavId(id);
    ensures do_cmd: \result == MT_MISSION_KIND_DO <==> MtMissionIsDoId(id);
    ensures unknown: \result == MT_MISSION_KIND_HOME <==> !MtMissionIsKnownId(id);
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
    ensures no_index: m->nav_idx == MT_MISSION_NONE && m->do_idx == MT_MISSION_NONE &&
        m->prev_nav == MT_MISSION_NONE && m->do_done == 0;
    ensures never_completed: m->completions == 0;
    ensures callbacks: m->start_fn == start_fn && m->verify_fn == verify_fn &&
        m->complete_fn == complete_fn && m->ctx == ctx;
*/
void mt_mission_init(mt_mission_t *m, mt_mission_cmd_fn_t start_fn, mt_mission_cmd_fn_t verify_fn,
                     mt_mission_done_fn_t complete_fn, void *ctx);

/** Check one command of a candidate list (ids, params, NaN rules, frames,
 *  location ranges, jump target/repeat ranges). Pure.
 *  @retval MT_OK when the command passes every rule, else the status of the first rule
 *          it breaks, in this order (MtMissionCmdStatus): MT_E_MISSION_CMD (unknown id,
 *          or a home that is not a waypoint), MT_E_MISSION_FRAME, MT_E_MISSION_PARAM,
 *          MT_E_MISSION_LOCATION, MT_E_MISSION_JUMP */
/*@ requires cmds: MtMissionCmdsIn(cmds, n);
    requires index: 0 <= i < n;
    assigns \nothing;
    ensures exact: MtMissionCmdStatus(cmds, n, i, \result);
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
          m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE && m->nav_idx == MT_MISSION_NONE &&
          (m->generation == \old(m->generation) + 1 || \old(m->generation) == 0xFFFFFFFF);
      ensures copied: \result == MT_OK ==> MtMissionCopied(m, cmds, n);
      ensures rejected: \result != MT_OK ==> MtMissionActiveUnchanged{Pre, Post}(m);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_mission_load(mt_mission_t *m, const mt_mission_cmd_t *cmds, uint16_t n, uint16_t *bad);

/** Replace the mission while it runs, between two updates (a ground
 *  station's upload in flight: AP writes the upload into the stored mission,
 *  then Copter's AUTO calls restart_current_nav_cmd). The candidate list is
 *  validated whole first (mt_mission_check); on any problem nothing changes.
 *  Applied, the new list is the active mission (generation + 1); a jump
 *  counter is kept where both lists have a jump at the same index (AP keys
 *  its jump tracking by index), at most the new repeat count; every other
 *  counter is 0. Then, when the index of the last nav command set (nav_idx)
 *  exists in the new list, the nav advance runs from it as
 *  mt_mission_restart_current's does: the command now at that index starts
 *  (a do command there starts and the walk goes on to the next nav command;
 *  the end completes the mission). Otherwise the mission is STOPPED with no
 *  command set: the vehicle holds, and mt_mission_start or
 *  mt_mission_set_current continue it.
 *  AP differs in two ways: AUTO restarts the command only when its change
 *  detector sees the current or next nav commands change, and a restart that
 *  fails (the index beyond the new list) leaves the old command flying from
 *  RAM, a command that is no longer in the mission.
 *  @retval MT_OK (RUNNING or COMPLETE: continued; STOPPED: held)
 *  @retval MT_E_STATE not running (nothing changes; use mt_mission_load)
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
            mt_mission_scratch_target[0 .. MT_CFG_MISSION_MAX_CMDS - 1], MtPortNow, MtPortWakes;
    ensures inv: MtMissionInv(m);
    behavior not_running:
      assumes m->state != MT_MISSION_RUNNING;
      ensures status: \result == MT_E_STATE && *bad == MT_MISSION_NONE;
      ensures untouched: MtMissionActiveUnchanged{Pre, Post}(m);
    behavior running:
      assumes m->state == MT_MISSION_RUNNING;
      ensures located: \result == MT_OK <==> *bad == MT_MISSION_NONE;
      ensures rejected: \result != MT_OK ==> MtMissionActiveUnchanged{Pre, Post}(m);
      ensures replaced: \result == MT_OK ==> m->total == n && MtMissionCopied(m, cmds, n) &&
          (m->generation == \old(m->generation) + 1 || \old(m->generation) == 0xFFFFFFFF);
      ensures continued: \result == MT_OK ==> \old(m->nav_idx) < n ==>
          (m->state == MT_MISSION_RUNNING || m->state == MT_MISSION_COMPLETE) &&
          (m->completions == \old(m->completions) + (m->state == MT_MISSION_COMPLETE ? 1 : 0) ||
           \old(m->completions) == 0xFFFFFFFF);
      ensures held: \result == MT_OK ==> \old(m->nav_idx) >= n ==>
          m->state == MT_MISSION_STOPPED && m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE &&
          m->nav_idx == MT_MISSION_NONE && m->completions == \old(m->completions);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_mission_replace(mt_mission_t *m, const mt_mission_cmd_t *cmds, uint16_t n, uint16_t *bad);

/** Start from the first command: counters and cursors reset, RUNNING, and
 *  the nav advance from index 1 (the first do command before the first nav
 *  command starts, then the first nav command whose start succeeds; with no
 *  such nav command the mission completes at once).
 *  @retval MT_OK
 *  @retval MT_E_EMPTY no command besides home (nothing changes) */
/*@ requires inv: MtMissionInv(m);
    assigns *m, MtPortNow, MtPortWakes;
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

/** STOPPED -> RUNNING: set-current at the active do command if there is one,
 *  else at the active nav command (both are started again); with neither, the
 *  next update advances. COMPLETE, or no nav command ever set ->
 *  mt_mission_start.
 *  @retval MT_OK
 *  @retval MT_E_STATE already running (nothing changes)
 *  @retval MT_E_EMPTY no command besides home (nothing changes) */
/*@ requires inv: MtMissionInv(m);
    assigns *m, MtPortNow, MtPortWakes;
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
 *  RUNNING: the active commands are dropped and the nav advance runs from i
 *  (the end of the list completes the mission). Otherwise: the walk from i
 *  (counting jumps) makes the first nav command and the first do command it
 *  passes active without starting them, and the state becomes STOPPED;
 *  mt_mission_resume starts them.
 *  @retval MT_OK
 *  @retval MT_E_EMPTY no command besides home, or (not running) no nav
 *          command at or after i (nothing changes)
 *  @retval MT_E_INVALID i >= count (nothing changes) */
/*@ requires inv: MtMissionInv(m);
    assigns *m, MtPortNow, MtPortWakes;
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
      ensures status: \result == MT_OK || \result == MT_E_EMPTY;
      ensures state: \result == MT_OK ==> m->state == MT_MISSION_STOPPED;
      ensures none: \result == MT_E_EMPTY ==> MtMissionActiveUnchanged{Pre, Post}(m);
      ensures same_mission: m->total == \old(m->total) && m->generation == \old(m->generation);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_mission_set_current(mt_mission_t *m, uint16_t i);

/** Start the last nav command set again (after a mission change or a mode
 *  switch): set-current at nav_idx (AP restart_current_nav_cmd); the active
 *  do command is dropped. A refused start walks on as the nav advance does.
 *  @retval MT_OK
 *  @retval MT_E_STATE not running, or no nav command set (nothing changes) */
/*@ requires inv: MtMissionInv(m);
    assigns *m, MtPortNow, MtPortWakes;
    ensures inv: MtMissionInv(m);
    behavior active:
      assumes m->state == MT_MISSION_RUNNING && m->nav_idx != MT_MISSION_NONE;
      ensures status: \result == MT_OK;
      ensures state: m->state == MT_MISSION_RUNNING || m->state == MT_MISSION_COMPLETE;
      ensures same_mission: m->total == \old(m->total) && m->generation == \old(m->generation);
    behavior other:
      assumes !(m->state == MT_MISSION_RUNNING && m->nav_idx != MT_MISSION_NONE);
      ensures status: \result == MT_E_STATE;
      ensures untouched: MtMissionActiveUnchanged{Pre, Post}(m);
    complete behaviors;
    disjoint behaviors;
*/
mt_status_t mt_mission_restart_current(mt_mission_t *m);

/** One sequencing step (AP update): verify the active nav command and
 *  advance when it verified (or advance when none is active); the end of the
 *  list completes the mission. Then verify the active do command, or run the
 *  do search. See the rules at the top.
 *  @retval MT_OK
 *  @retval MT_E_STATE not running (nothing changes) */
/*@ requires inv: MtMissionInv(m);
    assigns *m, MtPortNow, MtPortWakes;
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

/** Times the jump at index i was taken since its last reset: its counter
 *  m->count[i] (0 for any other index, home and i >= count included). Pure. */
/*@ requires inv: MtMissionInv(m);
    assigns \nothing;
    ensures counter: MtMissionIdx(m, i) && m->kind[i] == MT_MISSION_KIND_JUMP ==>
        \result == m->count[i];
    ensures bounded: MtMissionIdx(m, i) && m->kind[i] == MT_MISSION_KIND_JUMP && m->repeat[i] >= 0 ==>
        0 <= \result <= m->repeat[i];
    ensures other: !(MtMissionIdx(m, i) && m->kind[i] == MT_MISSION_KIND_JUMP) ==> \result == 0;
*/
int32_t mt_mission_jump_count(const mt_mission_t *m, uint16_t i);

#ifdef __cplusplus
}
#endif

#endif /* MT_MISSION_H */
