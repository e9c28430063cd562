/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mission.c
 * @brief Mission-command sequencer: init, load and the control operations
 *        (see mt/mission.h for the operating rules).
 *
 * The module's files: mission_check.c validates a candidate list (the command
 * table, mt_mission_check); this file applies a checked list (mt_mission_load)
 * and holds the control operations (start, stop, resume, set-current, restart)
 * and the queries; mission_seq.c is the sequencer proper (the execution walk,
 * the nav advance, the update step), reached through mt_mission_int.h.
 */
#include "mt/mission.h"

#include "mt_mission_int.h"

void mt_mission_init(mt_mission_t *m, mt_mission_cmd_fn_t start_fn, mt_mission_cmd_fn_t verify_fn,
                     mt_mission_done_fn_t complete_fn, void *ctx)
{
    m->kind[0] = MT_MISSION_KIND_HOME;
    m->total = 0u;
    m->generation = 0u;
    m->state = MT_MISSION_STOPPED;
    m->do_done = 0u;
    m->nav = MT_MISSION_NONE;
    m->do_cmd = MT_MISSION_NONE;
    m->nav_idx = MT_MISSION_NONE;
    m->do_idx = MT_MISSION_NONE;
    m->prev_nav = MT_MISSION_NONE;
    m->completions = 0u;
    m->start_fn = start_fn;
    m->verify_fn = verify_fn;
    m->complete_fn = complete_fn;
    m->ctx = ctx;
}

/* Field by field (WP's typed model handles a structure assignment as one
 * opaque block; the fields give small goals). */
/*@ requires \valid(dst) && \valid_read(src) && \separated(dst, src);
    assigns dst->id, dst->frame, dst->options, dst->param[0 .. 3], dst->x, dst->y, dst->z;
    ensures MtMissionSameCmd(dst, src);
*/
static void copy_cmd(mt_mission_cmd_t *dst, const mt_mission_cmd_t *src)
{
    dst->id = src->id;
    dst->frame = src->frame;
    dst->options = src->options;
    dst->param[0] = src->param[0];
    dst->param[1] = src->param[1];
    dst->param[2] = src->param[2];
    dst->param[3] = src->param[3];
    dst->x = src->x;
    dst->y = src->y;
    dst->z = src->z;
}

/* Store checked command c as entry i of a list of n: its class, and for a
 * jump its resolved target and repeat count (the counter is keep_counts'). */
/*@ requires \valid(m) && 1 <= i < n <= MT_CFG_MISSION_MAX_CMDS;
    requires \valid_read(c) && \separated(c, m);
    requires MtMissionIsJumpId(c->id) ==> 1 <= tgt < n && MtMissionRepeatOk(c->param[1]);
    assigns m->cmd[i].id, m->cmd[i].frame, m->cmd[i].options, m->cmd[i].param[0 .. 3],
            m->cmd[i].x, m->cmd[i].y, m->cmd[i].z,
            m->kind[i], m->target[i], m->repeat[i];
    ensures kind: (m->kind[i] == MT_MISSION_KIND_NAV || m->kind[i] == MT_MISSION_KIND_DO ||
             m->kind[i] == MT_MISSION_KIND_JUMP || m->kind[i] == MT_MISSION_KIND_TAG) &&
            (m->kind[i] == MT_MISSION_KIND_JUMP <==> MtMissionIsJumpId(m->cmd[i].id)) &&
            (m->kind[i] == MT_MISSION_KIND_TAG <==> m->cmd[i].id == MT_MAV_CMD_JUMP_TAG);
    ensures jump: (m->kind[i] == MT_MISSION_KIND_JUMP ==>
                1 <= m->target[i] < n && m->repeat[i] == c->param[1] / MT_MISSION_MILLI &&
                -1 <= m->repeat[i] <= MT_MISSION_REPEAT_MAX);
    ensures MtMissionSameCmd(&m->cmd[i], c);
*/
static void put_cmd(mt_mission_t *m, uint16_t i, const mt_mission_cmd_t *c, uint16_t tgt, uint16_t n)
{
    uint8_t k = mt_mission_kind_of(c->id);

    (void)n; /* the contract's bound on tgt */
    if (k == MT_MISSION_KIND_HOME) {
        k = MT_MISSION_KIND_DO; /* unreachable after the check */
    }
    copy_cmd(&m->cmd[i], c);
    m->kind[i] = k;
    m->target[i] = 0u;
    m->repeat[i] = 0;
    if (k == MT_MISSION_KIND_JUMP) {
        m->target[i] = tgt;
        m->repeat[i] = (int16_t)(c->param[1] / MT_MISSION_MILLI);
    }
}

/* The jump counters of checked list cmds over the list of `before`
 * commands it replaces (0: none), read before any entry is overwritten: a
 * counter is kept where both lists have a jump at the index, at most the new
 * repeat count (AP keys its jump tracking by index; a count above the repeat
 * count falls through and resets exactly as one equal to it does); every
 * other counter is 0. */
/*@ requires \valid(m) && 1 <= n <= MT_CFG_MISSION_MAX_CMDS && before <= MT_CFG_MISSION_MAX_CMDS;
    requires \valid_read(cmds + (0 .. n - 1)) && \separated(cmds + (0 .. n - 1), m);
    requires reps: \forall integer j; 1 <= j < n ==> MtMissionIsJumpId(cmds[j].id) ==>
        MtMissionRepeatOk(cmds[j].param[1]);
    assigns m->count[1 .. n - 1];
    ensures kept: \forall integer j; 1 <= j < n ==>
        MtMissionKeptFor(\old(m->kind[j]), \old(m->count[j]), j, before, &cmds[j], m->count[j]);
    ensures fits: \forall integer j; 1 <= j < n ==> MtMissionCountFits(m->count[j], &cmds[j]);
*/
static void keep_counts(mt_mission_t *m, const mt_mission_cmd_t *cmds, uint16_t n, uint16_t before)
{
    uint16_t i;

    /*@ loop invariant 1 <= i <= n;
        loop invariant kept: \forall integer j; 1 <= j < i ==>
            MtMissionKeptFor(\at(m->kind[j], Pre), \at(m->count[j], Pre), j, before, &cmds[j], m->count[j]);
        loop invariant fits: \forall integer j; 1 <= j < i ==> MtMissionCountFits(m->count[j], &cmds[j]);
        loop invariant ahead: \forall integer j; i <= j < n ==> m->count[j] == \at(m->count[j], Pre);
        loop assigns i, m->count[1 .. n - 1];
        loop variant n - i;
    */
    for (i = 1u; i < n; i++) {
        int16_t c = 0;
        if ((i < before) && (m->kind[i] == MT_MISSION_KIND_JUMP) && (m->count[i] > 0) &&
            (mt_mission_kind_of(cmds[i].id) == MT_MISSION_KIND_JUMP) && (cmds[i].param[1] >= 0)) {
            int32_t r = cmds[i].param[1] / MT_MISSION_MILLI;
            if ((int32_t)m->count[i] < r) {
                c = m->count[i];
            } else {
                c = (int16_t)r;
            }
        }
        m->count[i] = c;
    }
}

/* Cursors of a freshly applied list of n commands (entries already stored,
 * from cmds). */
/*@ requires \valid(m) && 1 <= n <= MT_CFG_MISSION_MAX_CMDS;
    requires \valid_read(cmds + (0 .. n - 1)) && \separated(cmds + (0 .. n - 1), m);
    requires copied: MtMissionCopied(m, cmds, n);
    requires home: m->kind[0] == MT_MISSION_KIND_HOME;
    requires kinds: \forall integer j; 1 <= j < n ==>
            (m->kind[j] == MT_MISSION_KIND_NAV || m->kind[j] == MT_MISSION_KIND_DO ||
             m->kind[j] == MT_MISSION_KIND_JUMP || m->kind[j] == MT_MISSION_KIND_TAG) &&
            (m->kind[j] == MT_MISSION_KIND_JUMP <==> MtMissionIsJumpId(m->cmd[j].id)) &&
            (m->kind[j] == MT_MISSION_KIND_TAG <==> m->cmd[j].id == MT_MAV_CMD_JUMP_TAG);
    requires jumps: \forall integer j; 1 <= j < n ==> (m->kind[j] == MT_MISSION_KIND_JUMP ==>
                1 <= m->target[j] < n && -1 <= m->repeat[j] <= MT_MISSION_REPEAT_MAX);
    requires counters: \forall integer j; 1 <= j < n ==> (m->kind[j] == MT_MISSION_KIND_JUMP ==>
                (m->repeat[j] >= 0 ==> 0 <= m->count[j] <= m->repeat[j]) &&
                (m->repeat[j] < 0 ==> m->count[j] == 0));
    assigns m->total, m->generation, m->state, m->do_done, m->nav, m->do_cmd, m->nav_idx, m->do_idx,
            m->prev_nav;
    ensures m->total == n && m->state == MT_MISSION_STOPPED && m->do_done == 0;
    ensures m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE && m->prev_nav == MT_MISSION_NONE;
    ensures m->nav_idx == MT_MISSION_NONE && m->do_idx == MT_MISSION_NONE;
    ensures m->generation == \old(m->generation) + 1 || \old(m->generation) == 0xFFFFFFFF;
    ensures tables: MtMissionKinds(m) && MtMissionJumps(m) && MtMissionCounters(m);
    ensures copied: MtMissionCopied(m, cmds, n);
    ensures counts: \forall integer j; 0 <= j < MT_CFG_MISSION_MAX_CMDS ==> m->count[j] == \old(m->count[j]);
*/
static void reset_cursors(mt_mission_t *m, uint16_t n, const mt_mission_cmd_t *cmds)
{
    (void)cmds; /* the contract's list, passed through */
    m->total = n;
    if (m->generation < 0xFFFFFFFFu) {
        m->generation++;
    }
    m->state = MT_MISSION_STOPPED;
    m->do_done = 0u;
    m->nav = MT_MISSION_NONE;
    m->do_cmd = MT_MISSION_NONE;
    m->nav_idx = MT_MISSION_NONE;
    m->do_idx = MT_MISSION_NONE;
    m->prev_nav = MT_MISSION_NONE;
}

/* Entries 1 .. n-1 from the checked list (home is stored by apply, the
 * counters by keep_counts, which put_all keeps). */
/*@ requires \valid(m) && 1 <= n <= MT_CFG_MISSION_MAX_CMDS;
    requires \separated(m, mt_mission_scratch_target + (0 .. MT_CFG_MISSION_MAX_CMDS - 1));
    requires MtMissionStaged(&mt_mission_scratch_target[0], cmds, n);
    requires \separated(cmds + (0 .. n - 1), m);
    requires fits: \forall integer j; 1 <= j < n ==> MtMissionCountFits(m->count[j], &cmds[j]);
    assigns m->cmd[1 .. n - 1], m->kind[1 .. n - 1], m->target[1 .. n - 1], m->repeat[1 .. n - 1];
    ensures kinds: \forall integer j; 1 <= j < n ==>
            (m->kind[j] == MT_MISSION_KIND_NAV || m->kind[j] == MT_MISSION_KIND_DO ||
             m->kind[j] == MT_MISSION_KIND_JUMP || m->kind[j] == MT_MISSION_KIND_TAG) &&
            (m->kind[j] == MT_MISSION_KIND_JUMP <==> MtMissionIsJumpId(m->cmd[j].id)) &&
            (m->kind[j] == MT_MISSION_KIND_TAG <==> m->cmd[j].id == MT_MAV_CMD_JUMP_TAG);
    ensures jumps: \forall integer j; 1 <= j < n ==> (m->kind[j] == MT_MISSION_KIND_JUMP ==>
                1 <= m->target[j] < n && -1 <= m->repeat[j] <= MT_MISSION_REPEAT_MAX);
    ensures counters: \forall integer j; 1 <= j < n ==> (m->kind[j] == MT_MISSION_KIND_JUMP ==>
                (m->repeat[j] >= 0 ==> 0 <= m->count[j] <= m->repeat[j]) &&
                (m->repeat[j] < 0 ==> m->count[j] == 0));
    ensures copied: MtMissionCopied(m, cmds, n);
*/
static void put_all(mt_mission_t *m, const mt_mission_cmd_t *cmds, uint16_t n)
{
    uint16_t i;

    /*@ loop invariant 1 <= i <= n;
        loop invariant kinds: \forall integer j; 1 <= j < i ==>
            (m->kind[j] == MT_MISSION_KIND_NAV || m->kind[j] == MT_MISSION_KIND_DO ||
             m->kind[j] == MT_MISSION_KIND_JUMP || m->kind[j] == MT_MISSION_KIND_TAG) &&
            (m->kind[j] == MT_MISSION_KIND_JUMP <==> MtMissionIsJumpId(m->cmd[j].id)) &&
            (m->kind[j] == MT_MISSION_KIND_TAG <==> m->cmd[j].id == MT_MAV_CMD_JUMP_TAG);
        loop invariant jumps: \forall integer j; 1 <= j < i ==> (m->kind[j] == MT_MISSION_KIND_JUMP ==>
                1 <= m->target[j] < n && -1 <= m->repeat[j] <= MT_MISSION_REPEAT_MAX);
        loop invariant counters: \forall integer j; 1 <= j < i ==> (m->kind[j] == MT_MISSION_KIND_JUMP ==>
                (m->repeat[j] >= 0 ==> 0 <= m->count[j] <= m->repeat[j]) &&
                (m->repeat[j] < 0 ==> m->count[j] == 0));
        loop invariant copied: \forall integer j; 1 <= j < i ==> MtMissionSameCmd(&m->cmd[j], &cmds[j]);
        loop assigns i, m->cmd[1 .. n - 1], m->kind[1 .. n - 1], m->target[1 .. n - 1],
                     m->repeat[1 .. n - 1];
        loop variant n - i;
    */
    for (i = 1u; i < n; i++) {
        put_cmd(m, i, &cmds[i], mt_mission_scratch_target[i], n);
    }
    /*@ assert at_end: i == n; */
}

/* Make the checked list the active mission over a list of `before`
 * commands (0: keep no jump counter). Cannot fail. (Only the parts of the
 * invariant it keeps are required: small contexts keep the goals fast.) */
/*@ requires \valid(m) && \separated(m, mt_mission_scratch_safe + (0 .. MT_CFG_MISSION_MAX_CMDS - 1),
                                     mt_mission_scratch_target + (0 .. MT_CFG_MISSION_MAX_CMDS - 1));
    requires m->start_fn != \null && m->verify_fn != \null && m->complete_fn != \null;
    requires MtMissionStaged(&mt_mission_scratch_target[0], cmds, n);
    requires \separated(cmds + (0 .. n - 1), m);
    requires before <= MT_CFG_MISSION_MAX_CMDS;
    assigns m->cmd[0 .. n - 1], m->kind[0 .. n - 1], m->target[0 .. n - 1], m->repeat[0 .. n - 1],
            m->count[0 .. n - 1], m->total, m->generation, m->state, m->do_done, m->nav,
            m->do_cmd, m->nav_idx, m->do_idx, m->prev_nav;
    ensures MtMissionInv(m);
    ensures m->total == n && m->state == MT_MISSION_STOPPED && m->nav_idx == MT_MISSION_NONE;
    ensures m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE;
    ensures m->do_idx == MT_MISSION_NONE && m->prev_nav == MT_MISSION_NONE && m->do_done == 0;
    ensures m->generation == \old(m->generation) + 1 || \old(m->generation) == 0xFFFFFFFF;
    ensures copied: MtMissionCopied(m, cmds, n);
*/
static void apply(mt_mission_t *m, const mt_mission_cmd_t *cmds, uint16_t n, uint16_t before)
{
    keep_counts(m, cmds, n, before);
    copy_cmd(&m->cmd[0], &cmds[0]);
    m->kind[0] = MT_MISSION_KIND_HOME;
    m->target[0] = 0u;
    m->repeat[0] = 0;
    m->count[0] = 0;
    put_all(m, cmds, n);
    reset_cursors(m, n, cmds);
    /*@ assert home: m->kind[0] == MT_MISSION_KIND_HOME; */
    /*@ assert tables: MtMissionKinds(m) && MtMissionJumps(m) && MtMissionCounters(m); */
    /*@ assert cursors: MtMissionCursors(m); */
}

mt_status_t mt_mission_load(mt_mission_t *m, const mt_mission_cmd_t *cmds, uint16_t n, uint16_t *bad)
{
    mt_status_t st;

    if (m->state == MT_MISSION_RUNNING) {
        *bad = MT_MISSION_NONE;
        /*@ assert kept: MtMissionActiveUnchanged{Pre, Here}(m); */
        /*@ assert kinds: MtMissionKinds(m); */
        /*@ assert jumps: MtMissionJumps(m); */
        /*@ assert counters: MtMissionCounters(m); */
        /*@ assert cursors: MtMissionCursors(m); */
        return MT_E_STATE;
    }
    st = mt_mission_check(m, cmds, n, bad);
    if (st != MT_OK) {
        return st;
    }
    apply(m, cmds, n, 0u);
    return MT_OK;
}

/* ------------------------------------------------------------ control operations */

/* Every jump counter back to 0. */
/*@ requires MtMissionInv(m) && m->total >= 2;
    assigns m->count[0 .. m->total - 1];
    ensures MtMissionInv(m);
*/
static void zero_counts(mt_mission_t *m)
{
    uint16_t i;

    /*@ loop invariant 0 <= i <= m->total;
        loop invariant \forall integer j; 0 <= j < i ==> m->count[j] == 0;
        loop assigns i, m->count[0 .. m->total - 1];
        loop variant m->total - i;
    */
    for (i = 0u; i < m->total; i++) {
        m->count[i] = 0;
    }
}

/* Counters and cursors back to the top [reset]. */
/*@ requires MtMissionInv(m) && m->total >= 2;
    assigns m->count[0 .. m->total - 1], m->nav, m->nav_idx, m->do_cmd, m->do_idx, m->do_done,
            m->prev_nav;
    ensures MtMissionInv(m);
    ensures m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE && m->nav_idx == MT_MISSION_NONE;
*/
static void rewind_walk(mt_mission_t *m)
{
    zero_counts(m);
    mt_mission_drop_both(m);
    m->nav_idx = MT_MISSION_NONE;
    m->prev_nav = MT_MISSION_NONE;
}

mt_status_t mt_mission_start(mt_mission_t *m)
{
    if (m->total < 2u) {
        return MT_E_EMPTY;
    }
    rewind_walk(m);
    m->state = MT_MISSION_RUNNING;
    mt_mission_advance_or_finish(m, 1u);
    return MT_OK;
}

mt_status_t mt_mission_stop(mt_mission_t *m)
{
    if (m->state != MT_MISSION_RUNNING) {
        return MT_E_STATE;
    }
    m->state = MT_MISSION_STOPPED;
    return MT_OK;
}

/* A state change that keeps the invariant (COMPLETE is entered by finish only). */
/*@ requires MtMissionInv(m) && m->total >= 2;
    requires st == MT_MISSION_STOPPED || st == MT_MISSION_RUNNING;
    assigns m->state;
    ensures MtMissionInv(m) && m->state == st;
*/
static void set_state(mt_mission_t *m, uint8_t st)
{
    m->state = st;
}

mt_status_t mt_mission_resume(mt_mission_t *m)
{
    if (m->state == MT_MISSION_RUNNING) {
        return MT_E_STATE;
    }
    if (m->total < 2u) {
        return MT_E_EMPTY;
    }
    if ((m->state == MT_MISSION_COMPLETE) || (m->nav_idx == MT_MISSION_NONE)) {
        return mt_mission_start(m);
    }
    set_state(m, MT_MISSION_RUNNING);
    if (m->do_cmd != MT_MISSION_NONE) {
        mt_mission_advance_or_finish(m, m->do_cmd);
    } else if (m->nav != MT_MISSION_NONE) {
        mt_mission_advance_or_finish(m, m->nav);
    } else {
        /* no active command: the next update advances past nav_idx */
    }
    return MT_OK;
}

mt_status_t mt_mission_set_current(mt_mission_t *m, uint16_t i)
{
    uint16_t p = (uint16_t)((i == 0u) ? 1u : i);
    int fresh = 0;

    if ((i == 0u) || (m->state == MT_MISSION_COMPLETE)) {
        fresh = 1;
    }

    if (m->total < 2u) {
        return MT_E_EMPTY;
    }
    if (i >= m->total) {
        return MT_E_INVALID;
    }
    if ((m->state != MT_MISSION_RUNNING) && (mt_mission_look_nav(m, p, fresh) >= m->total)) {
        return MT_E_EMPTY;
    }
    if (fresh != 0) {
        zero_counts(m);
        m->prev_nav = MT_MISSION_NONE;
    }
    if (m->state == MT_MISSION_RUNNING) {
        mt_mission_advance_or_finish(m, p);
    } else {
        mt_mission_preload(m, p);
        set_state(m, MT_MISSION_STOPPED);
    }
    return MT_OK;
}

mt_status_t mt_mission_restart_current(mt_mission_t *m)
{
    if ((m->state != MT_MISSION_RUNNING) || (m->nav_idx == MT_MISSION_NONE)) {
        return MT_E_STATE;
    }
    mt_mission_advance_or_finish(m, m->nav_idx);
    return MT_OK;
}

mt_status_t mt_mission_replace(mt_mission_t *m, const mt_mission_cmd_t *cmds, uint16_t n, uint16_t *bad)
{
    mt_status_t st;
    uint16_t at;

    if (m->state != MT_MISSION_RUNNING) {
        *bad = MT_MISSION_NONE;
        /*@ assert kept: MtMissionActiveUnchanged{Pre, Here}(m); */
        /*@ assert kinds: MtMissionKinds(m); */
        /*@ assert jumps: MtMissionJumps(m); */
        /*@ assert counters: MtMissionCounters(m); */
        /*@ assert cursors: MtMissionCursors(m); */
        return MT_E_STATE;
    }
    st = mt_mission_check(m, cmds, n, bad);
    if (st != MT_OK) {
        return st;
    }
    at = m->nav_idx;
    apply(m, cmds, n, m->total);
    /*@ assert applied: MtMissionInv(m); */
    if (at < n) {
        /* the index exists: start what is there now [restart_current_nav_cmd] */
        set_state(m, MT_MISSION_RUNNING);
        mt_mission_advance_or_finish(m, at);
        /*@ assert continued: MtMissionInv(m); */
    }
    return MT_OK;
}

mt_status_t mt_mission_get(const mt_mission_t *m, uint16_t i, mt_mission_cmd_t *out, bool *is_current)
{
    if (i >= m->total) {
        return MT_E_INVALID;
    }
    copy_cmd(out, &m->cmd[i]);
    *is_current = (i == m->nav);
    return MT_OK;
}

int32_t mt_mission_jump_count(const mt_mission_t *m, uint16_t i)
{
    if ((i < 1u) || (i >= m->total) || (m->kind[i] != MT_MISSION_KIND_JUMP)) {
        return 0;
    }
    return (int32_t)m->count[i];
}
