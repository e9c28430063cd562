/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mission_seq.c
 * @brief Mission-command sequencer: the execution walk, the nav advance and the
 *        update step (see mt/mission.h for the operating rules).
 *
 * The sequencer follows AP_Mission's update step function by function (the
 * header states the rules): advance = advance_current_nav_cmd, do_search =
 * advance_current_do_cmd, take_cmd / peek_cmd = get_next_cmd with and without
 * counting, mt_mission_preload = the stopped branch of set_current_cmd.
 * Validation guarantees that no loop lacks a nav command, so a walk to the
 * next nav command passes each jump at most once: set-current's look-ahead
 * (mt_mission_look_nav) and the counting walk after it decide every jump the
 * same way.
 *
 * The control operations (mission.c) reach it through the kernel-internal
 * functions of mt_mission_int.h: mt_mission_look_nav, mt_mission_drop_both,
 * mt_mission_advance_or_finish and mt_mission_preload.
 */
#include "mt_mission_int.h"

#include "mt_mission_invoke.h"

/* ------------------------------------------------------------ execution walk */

/* Where a resolution goes from a jump at p, without counting; fresh: as if
 * every counter were 0 (set-current's look-ahead when it resets them). */
/*@ requires MtMissionInv(m);
    requires MtMissionIdx(m, p) && m->kind[p] == MT_MISSION_KIND_JUMP;
    assigns \nothing;
    ensures 1 <= \result <= m->total;
*/
static uint16_t jump_peek(const mt_mission_t *m, uint16_t p, int fresh)
{
    int16_t used = m->count[p];

    if (fresh != 0) {
        used = 0;
    }

    if ((m->repeat[p] < 0) || (used < m->repeat[p])) {
        return m->target[p];
    }
    return (uint16_t)(p + 1u);
}

/* Where the nav advance goes from a jump at p, counting: taken r times, then
 * fall through and reset. */
/*@ requires MtMissionInv(m);
    requires MtMissionIdx(m, p) && m->kind[p] == MT_MISSION_KIND_JUMP;
    assigns m->count[p];
    ensures MtMissionInv(m);
    ensures 1 <= \result <= m->total;
*/
static uint16_t jump_take(mt_mission_t *m, uint16_t p)
{
    if (m->repeat[p] < 0) {
        return m->target[p];
    }
    if (m->count[p] < m->repeat[p]) {
        m->count[p]++;
        return m->target[p];
    }
    m->count[p] = 0;
    return (uint16_t)(p + 1u);
}

/* First command at or after p that is not a jump, jumps followed without
 * counting; total at the end (or when the bound is hit: impossible for a
 * validated mission, whose jump-only paths are acyclic). */
/*@ requires MtMissionInv(m) && 1 <= p <= m->total;
    assigns \nothing;
    ensures 1 <= \result <= m->total;
    ensures \result < m->total ==> m->kind[\result] != MT_MISSION_KIND_JUMP;
*/
static uint16_t peek_cmd(const mt_mission_t *m, uint16_t p)
{
    uint16_t q = p;
    uint32_t steps;

    /*@ loop invariant 0 <= steps <= m->total;
        loop invariant 1 <= q <= m->total;
        loop assigns steps, q;
        loop variant m->total - steps;
    */
    for (steps = 0u; steps < m->total; steps++) {
        if ((q >= m->total) || (m->kind[q] != MT_MISSION_KIND_JUMP)) {
            return q;
        }
        q = jump_peek(m, q, 0);
    }
    return m->total;
}

/* The same, counting every jump passed [get_next_cmd with increment]. */
/*@ requires MtMissionInv(m) && m->total >= 2 && 1 <= p <= m->total;
    assigns m->count[0 .. m->total - 1];
    ensures MtMissionInv(m);
    ensures 1 <= \result <= m->total;
    ensures \result < m->total ==> m->kind[\result] != MT_MISSION_KIND_JUMP;
*/
static uint16_t take_cmd(mt_mission_t *m, uint16_t p)
{
    uint16_t q = p;
    uint32_t steps;

    /*@ loop invariant 0 <= steps <= m->total;
        loop invariant 1 <= q <= m->total;
        loop invariant MtMissionInv(m);
        loop assigns steps, q, m->count[0 .. m->total - 1];
        loop variant m->total - steps;
    */
    for (steps = 0u; steps < m->total; steps++) {
        if ((q >= m->total) || (m->kind[q] != MT_MISSION_KIND_JUMP)) {
            return q;
        }
        q = jump_take(m, q);
    }
    return m->total;
}

/* The look-ahead (contract: mt_mission_int.h). */
uint16_t mt_mission_look_nav(const mt_mission_t *m, uint16_t p, int fresh)
{
    uint16_t q = p;
    uint32_t steps;

    /*@ loop invariant 0 <= steps <= m->total;
        loop invariant 1 <= q <= m->total;
        loop assigns steps, q;
        loop variant m->total - steps;
    */
    for (steps = 0u; steps < m->total; steps++) {
        if (q >= m->total) {
            return m->total;
        }
        if (m->kind[q] == MT_MISSION_KIND_NAV) {
            return q;
        }
        if (m->kind[q] == MT_MISSION_KIND_JUMP) {
            q = jump_peek(m, q, fresh);
        } else {
            q++;
        }
    }
    return MT_MISSION_NONE;
}

mt_status_t mt_mission_next_nav(const mt_mission_t *m, uint16_t from, uint16_t *out)
{
    uint16_t n;

    *out = MT_MISSION_NONE;
    if ((from < 1u) || (from >= m->total)) {
        return MT_E_INVALID;
    }
    n = mt_mission_look_nav(m, from, 0);
    if (n == MT_MISSION_NONE) {
        return MT_E_MISSION_LOOP;
    }
    if (n >= m->total) {
        return MT_E_EMPTY;
    }
    *out = n;
    return MT_OK;
}

/* Transition into COMPLETE: the only call of the complete callback. */
/*@ requires MtMissionInv(m) && m->state == MT_MISSION_RUNNING;
    assigns m->state, m->nav, m->do_cmd, m->do_done, m->completions, MtPortNow, MtPortWakes;
    ensures MtMissionInv(m);
    ensures m->state == MT_MISSION_COMPLETE && m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE;
    ensures complete_once: m->completions == \old(m->completions) + 1 || \old(m->completions) == 0xFFFFFFFF;
*/
static void finish(mt_mission_t *m)
{
    m->state = MT_MISSION_COMPLETE;
    m->nav = MT_MISSION_NONE;
    m->do_cmd = MT_MISSION_NONE;
    m->do_done = 0u;
    if (m->completions < 0xFFFFFFFFu) {
        m->completions++;
    }
    mt_mission_invoke_done(m->complete_fn, m->ctx);
}

/* Both commands dropped (contract: mt_mission_int.h). */
void mt_mission_drop_both(mt_mission_t *m)
{
    m->do_cmd = MT_MISSION_NONE;
    m->do_idx = MT_MISSION_NONE;
    m->do_done = 0u;
    m->nav = MT_MISSION_NONE;
}

/* Do command (or JUMP_TAG) d becomes the active one, without a start. */
/*@ requires MtMissionInv(m) && MtMissionIdx(m, d);
    requires m->kind[d] == MT_MISSION_KIND_DO || m->kind[d] == MT_MISSION_KIND_TAG;
    requires m->nav != MT_MISSION_NONE;
    assigns m->do_cmd, m->do_idx;
    ensures MtMissionInv(m) && m->do_cmd == d && m->do_idx == d;
*/
static void set_do(mt_mission_t *m, uint16_t d)
{
    m->do_idx = d;
    m->do_cmd = d;
}

/* Start the active do command: a JUMP_TAG is handled here (no callback); the
 * start result of a do command is ignored [start_command]. */
/*@ requires MtMissionInv(m) && m->do_cmd != MT_MISSION_NONE;
    assigns MtPortNow, MtPortWakes;
*/
static void start_do(mt_mission_t *m)
{
    if (m->kind[m->do_cmd] == MT_MISSION_KIND_DO) {
        (void)mt_mission_invoke_cmd(m->start_fn, m->ctx, m->do_cmd, &m->cmd[m->do_cmd]);
    }
}

/* Verify the active do command: a JUMP_TAG verifies at once [verify_command]. */
/*@ requires MtMissionInv(m) && m->do_cmd != MT_MISSION_NONE;
    assigns MtPortNow, MtPortWakes;
*/
static bool verify_do(mt_mission_t *m)
{
    if (m->kind[m->do_cmd] != MT_MISSION_KIND_DO) {
        return true;
    }
    return mt_mission_invoke_cmd(m->verify_fn, m->ctx, m->do_cmd, &m->cmd[m->do_cmd]);
}

/* Nav command p is set (nav_idx) and, when start is true, active. */
/*@ requires MtMissionInv(m) && MtMissionIdx(m, p) && m->kind[p] == MT_MISSION_KIND_NAV;
    requires m->nav == MT_MISSION_NONE;
    assigns m->nav, m->nav_idx, m->prev_nav;
    ensures MtMissionInv(m) && m->nav_idx == p;
    ensures started ==> m->nav == p;
    ensures !started ==> m->nav == MT_MISSION_NONE;
*/
static void set_nav(mt_mission_t *m, uint16_t p, bool started)
{
    m->prev_nav = m->nav_idx;
    m->nav_idx = p;
    if (started) {
        m->nav = p;
    }
}

/* Do command (or JUMP_TAG) r is the one the walk passed first: recorded, not yet active. */
/*@ requires MtMissionInv(m) && MtMissionIdx(m, r);
    requires m->kind[r] != MT_MISSION_KIND_NAV && m->kind[r] != MT_MISSION_KIND_JUMP;
    requires m->do_cmd == MT_MISSION_NONE;
    assigns m->do_idx;
    ensures MtMissionInv(m) && m->do_idx == r;
*/
static void note_do(mt_mission_t *m, uint16_t r)
{
    m->do_idx = r;
}

/* No nav command is set (the stopped walk found none). */
/*@ requires MtMissionInv(m) && m->nav == MT_MISSION_NONE;
    assigns m->nav_idx;
    ensures MtMissionInv(m) && m->nav_idx == MT_MISSION_NONE;
*/
static void forget_nav(mt_mission_t *m)
{
    m->nav_idx = MT_MISSION_NONE;
}

/* Nav command p becomes the active one without a start (the stopped walk). */
/*@ requires MtMissionInv(m) && MtMissionIdx(m, p) && m->kind[p] == MT_MISSION_KIND_NAV;
    requires m->nav == MT_MISSION_NONE;
    assigns m->nav, m->nav_idx;
    ensures MtMissionInv(m) && m->nav == p && m->nav_idx == p;
*/
static void load_nav(mt_mission_t *m, uint16_t p)
{
    m->nav_idx = p;
    m->nav = p;
}

/* A nav command has just become active: the do command d recorded on the way (do_idx)
 * becomes active with it; with none, there is no do command left before it. */
/*@ requires MtMissionInv(m) && m->nav != MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE;
    requires d == MT_MISSION_NONE || d == m->do_idx;
    assigns m->do_cmd, m->do_done;
    ensures MtMissionInv(m);
    ensures d != MT_MISSION_NONE ==> m->do_cmd == d;
    ensures d == MT_MISSION_NONE ==> m->do_cmd == MT_MISSION_NONE && m->do_done == 1;
*/
static void attach_do(mt_mission_t *m, uint16_t d)
{
    if (d != MT_MISSION_NONE) {
        m->do_cmd = d;
    } else {
        m->do_done = 1u;
    }
}

/* The nav advance visits at most the command count plus MT_CFG_MISSION_ADVANCE_EXTRA (255)
 * commands. AP's guard is 255 commands in all (max_loops), which a do stretch of 255
 * commands before a nav command already exhausts (AP then stays RUNNING with nothing
 * loaded: A-1). A walk with no refused start reaches a nav command within the command count
 * (no loop lacks one), so the extra commands are for nav starts refused inside a loop. */
#define ADVANCE_EXTRA MT_CFG_MISSION_ADVANCE_EXTRA

/* The nav advance from p [advance_current_nav_cmd]: returns 1 when a nav
 * command is active, 0 at the end of the list or when the bound is reached
 * without one (the caller completes the mission: A-1). The first do
 * command passed is started at once and becomes active with the nav command
 * (the invariant ties an active do command to an active nav command). */
/*@ requires MtMissionInv(m) && m->total >= 2 && m->state == MT_MISSION_RUNNING;
    requires 1 <= p <= m->total;
    assigns m->nav, m->nav_idx, m->prev_nav, m->do_cmd, m->do_idx, m->do_done,
            m->count[0 .. m->total - 1], MtPortNow, MtPortWakes;
    ensures MtMissionInv(m);
    ensures \result == 0 || \result == 1;
    ensures \result == 1 ==> m->nav != MT_MISSION_NONE;
    ensures \result == 0 ==> m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE;
*/
static int advance(mt_mission_t *m, uint16_t p)
{
    uint16_t q = p;
    uint16_t d = MT_MISSION_NONE;
    uint32_t k;

    mt_mission_drop_both(m);
    /*@ loop invariant 0 <= k <= m->total + ADVANCE_EXTRA;
        loop invariant 1 <= q <= m->total;
        loop invariant MtMissionInv(m) && m->state == MT_MISSION_RUNNING;
        loop invariant m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE && m->do_done == 0;
        loop invariant d == MT_MISSION_NONE || (d == m->do_idx && MtMissionIdx(m, d));
        loop assigns k, q, d, m->nav, m->nav_idx, m->prev_nav, m->do_cmd, m->do_idx, m->do_done,
                     m->count[0 .. m->total - 1], MtPortNow, MtPortWakes;
        loop variant m->total + ADVANCE_EXTRA - k;
    */
    for (k = 0u; k < ((uint32_t)m->total + ADVANCE_EXTRA); k++) {
        const uint16_t r = take_cmd(m, q);

        if (r >= m->total) {
            return 0;
        }
        if (m->kind[r] == MT_MISSION_KIND_NAV) {
            const bool ok = mt_mission_invoke_cmd(m->start_fn, m->ctx, r, &m->cmd[r]);
            set_nav(m, r, ok);
            if (ok) {
                attach_do(m, d);
                return 1;
            }
        } else if (d == MT_MISSION_NONE) {
            d = r;
            note_do(m, r);
            if (m->kind[r] == MT_MISSION_KIND_DO) {
                (void)mt_mission_invoke_cmd(m->start_fn, m->ctx, r, &m->cmd[r]);
            }
        } else {
            /* a later do command: passed, not started */
        }
        q = (uint16_t)(r + 1u);
    }
    return 0;
}

/* The nav advance or the end (contract: mt_mission_int.h). */
void mt_mission_advance_or_finish(mt_mission_t *m, uint16_t p)
{
    if (advance(m, p) == 0) {
        finish(m);
    }
}

/* The stopped walk (contract: mt_mission_int.h). */
void mt_mission_preload(mt_mission_t *m, uint16_t p)
{
    uint16_t q = p;
    uint16_t d = MT_MISSION_NONE;
    uint32_t k;

    mt_mission_drop_both(m);
    /*@ loop invariant 0 <= k <= m->total;
        loop invariant 1 <= q <= m->total;
        loop invariant MtMissionInv(m);
        loop invariant m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE && m->do_done == 0;
        loop invariant d == MT_MISSION_NONE || (d == m->do_idx && MtMissionIdx(m, d));
        loop assigns k, q, d, m->nav, m->nav_idx, m->do_cmd, m->do_idx, m->do_done,
                     m->count[0 .. m->total - 1];
        loop variant m->total - k;
    */
    for (k = 0u; k < m->total; k++) {
        const uint16_t r = take_cmd(m, q);

        if (r >= m->total) {
            break;
        }
        if (m->kind[r] == MT_MISSION_KIND_NAV) {
            load_nav(m, r);
            attach_do(m, d);
            return;
        }
        if (d == MT_MISSION_NONE) {
            d = r;
            note_do(m, r);
        }
        q = (uint16_t)(r + 1u);
    }
    forget_nav(m);
}

/* The do search [advance_current_do_cmd]: the next command after do_idx,
 * jumps followed without counting, starts if it is a do command (or is a
 * JUMP_TAG); a nav command or the end sets do_done. */
/*@ requires MtMissionInv(m) && m->total >= 2 && m->nav != MT_MISSION_NONE;
    requires m->do_cmd == MT_MISSION_NONE;
    assigns m->do_cmd, m->do_idx, m->do_done, MtPortNow, MtPortWakes;
    ensures MtMissionInv(m);
*/
static void do_search(mt_mission_t *m)
{
    uint16_t from = (uint16_t)((m->do_idx == MT_MISSION_NONE) ? 1u : (m->do_idx + 1u));
    uint16_t r;

    if (m->do_done != 0u) {
        return;
    }
    r = peek_cmd(m, from);
    if ((r >= m->total) || (m->kind[r] == MT_MISSION_KIND_NAV)) {
        m->do_done = 1u;
        return;
    }
    set_do(m, r);
    start_do(m);
}

/* The nav part of an update: verify the active nav command and advance when it verified (or
 * advance when none is active); 0 when the mission completed. */
/*@ requires MtMissionInv(m) && m->total >= 2 && m->state == MT_MISSION_RUNNING;
    assigns m->state, m->nav, m->nav_idx, m->prev_nav, m->do_cmd, m->do_idx, m->do_done,
            m->completions, m->count[0 .. m->total - 1], MtPortNow, MtPortWakes;
    ensures MtMissionInv(m);
    ensures \result == 0 || \result == 1;
    ensures \result == 1 ==> m->state == MT_MISSION_RUNNING && m->nav != MT_MISSION_NONE &&
        m->completions == \old(m->completions);
    ensures \result == 0 ==> m->state == MT_MISSION_COMPLETE &&
        (m->completions == \old(m->completions) + 1 || \old(m->completions) == 0xFFFFFFFF);
*/
static int nav_step(mt_mission_t *m)
{
    uint16_t from;

    if (m->nav != MT_MISSION_NONE) {
        if (!mt_mission_invoke_cmd(m->verify_fn, m->ctx, m->nav, &m->cmd[m->nav])) {
            return 1;
        }
    }
    from = (uint16_t)((m->nav_idx == MT_MISSION_NONE) ? 1u : (m->nav_idx + 1u));
    if (advance(m, from) == 0) {
        finish(m);
        return 0;
    }
    return 1;
}

/* The do part of an update: verify the active do command, or run the do search. */
/*@ requires MtMissionInv(m) && m->total >= 2 && m->nav != MT_MISSION_NONE;
    assigns m->do_cmd, m->do_idx, m->do_done, MtPortNow, MtPortWakes;
    ensures MtMissionInv(m);
*/
static void do_step(mt_mission_t *m)
{
    if (m->do_cmd == MT_MISSION_NONE) {
        do_search(m);
    } else if (verify_do(m)) {
        m->do_cmd = MT_MISSION_NONE;
    } else {
        /* the active do command is still running */
    }
}

mt_status_t mt_mission_update(mt_mission_t *m)
{
    if (m->state != MT_MISSION_RUNNING) {
        return MT_E_STATE;
    }
    if (nav_step(m) != 0) {
        do_step(m);
    }
    return MT_OK;
}
