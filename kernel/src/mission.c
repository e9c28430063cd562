/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mission.c
 * @brief Mission-command sequencer (see mt/mission.h for the operating rules).
 *
 * The sequencer follows AP_Mission's update step function by function (the
 * header states the rules): advance = advance_current_nav_cmd, do_search =
 * advance_current_do_cmd, take_cmd / peek_cmd = get_next_cmd with and without
 * counting, preload = the stopped branch of set_current_cmd. Validation
 * guarantees that no loop lacks a nav command, so a walk to the next nav
 * command passes each jump at most once: set-current's look-ahead (look_nav)
 * and the counting walk after it decide every jump the same way.
 */
#include "mt/mission.h"

#include "mt_mission_invoke.h"

/* The command table's rows (MT_MISSION_CMD_ROWS, sorted by id), N_CMDS and the F_* flags,
 * generated from MAVLink's definitions by tools/mavcmd/gen_mav_cmds.py: every command
 * ArduPilot's mission loader accepts. */
#include "mt_mission_cmds.h"

typedef struct {
    uint16_t id;
    uint8_t kind;
    uint8_t flags;
} cmd_info_t;

uint8_t mt_mission_scratch_safe[MT_CFG_MISSION_MAX_CMDS];
uint16_t mt_mission_scratch_target[MT_CFG_MISSION_MAX_CMDS];

static const cmd_info_t k_cmds[N_CMDS] = {MT_MISSION_CMD_ROWS};

#if !defined(__FRAMAC__)
_Static_assert((sizeof(k_cmds) / sizeof(k_cmds[0])) == N_CMDS, "N_CMDS must match the table");
#endif

/* Position of id in the table, or N_CMDS. Bounded by the table size. */
/*@ assigns \nothing;
    ensures range: 0 <= \result <= N_CMDS;
    ensures found: \result < N_CMDS ==> k_cmds[\result].id == id;
    ensures absent: \result == N_CMDS ==> \forall integer t; 0 <= t < N_CMDS ==> k_cmds[t].id != id;
*/
static uint32_t find_cmd(uint16_t id)
{
    uint32_t t;

    /*@ loop invariant 0 <= t <= N_CMDS;
        loop invariant \forall integer u; 0 <= u < t ==> k_cmds[u].id != id;
        loop assigns t;
        loop variant N_CMDS - t;
    */
    for (t = 0u; t < N_CMDS; t++) {
        if (k_cmds[t].id == id) {
            return t;
        }
    }
    return N_CMDS;
}

uint8_t mt_mission_kind_of(uint16_t id)
{
    uint32_t t;

    if ((id == MT_MAV_CMD_DO_JUMP) || (id == MT_MAV_CMD_DO_JUMP_TAG)) {
        return MT_MISSION_KIND_JUMP;
    }
    if (id == MT_MAV_CMD_JUMP_TAG) {
        return MT_MISSION_KIND_TAG;
    }
    t = find_cmd(id);
    if ((t < N_CMDS) && (k_cmds[t].kind == MT_MISSION_KIND_NAV)) {
        return MT_MISSION_KIND_NAV;
    }
    if (t < N_CMDS) {
        return MT_MISSION_KIND_DO;
    }
    return MT_MISSION_KIND_HOME;
}

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

/* ------------------------------------------------------------ validation */

/* Frames ArduPilot's loader accepts for a command it stores as a location (F_LOC): 0 GLOBAL,
 * 2 MISSION (read as GLOBAL: altitude above mean sea level), 5 GLOBAL_INT, 3 and 6 relative to
 * home, 10 and 11 above terrain. The frame of any other command is not looked at (AP ignores
 * it; the file layer warns). */
/*@ assigns \nothing; */
static int frame_ok(uint8_t frame, uint8_t flags)
{
    if ((flags & F_LOC) == 0u) {
        return 1;
    }
    return ((frame == 0u) || (frame == 2u) || (frame == 3u) || (frame == 5u) || (frame == 6u) ||
            (frame == 10u) || (frame == 11u))
               ? 1
               : 0;
}

/*@ assigns \nothing;
    ensures bool: \result == 0 || \result == 1;
    ensures \result == 1 <==> v % MT_MISSION_MILLI == 0;
*/
static int is_int(int32_t v)
{
    return ((v % MT_MISSION_MILLI) == 0) ? 1 : 0;
}

/*@ assigns \nothing;
    ensures bool: \result == 0 || \result == 1;
    ensures \result == 1 <==> MtMissionRepeatOk(v);
*/
static int repeat_ok(int32_t v)
{
    if ((v < -1000) || (v > 32767000)) {
        return 0;
    }
    return is_int(v);
}

/* Generic param rules from the table flags (params are never NaN here unless allowed). */
/*@ requires \valid_read(c);
    assigns \nothing;
    ensures \result == MT_OK || \result == MT_E_MISSION_PARAM;
*/
static mt_status_t params_ok(const mt_mission_cmd_t *c, uint8_t flags)
{
    if ((c->param[0] == MT_MISSION_PARAM_NAN) || (c->param[1] == MT_MISSION_PARAM_NAN)) {
        return MT_E_MISSION_PARAM;
    }
    if ((c->param[2] == MT_MISSION_PARAM_NAN) && ((flags & F_NAN3) == 0u)) {
        return MT_E_MISSION_PARAM;
    }
    if ((c->param[3] == MT_MISSION_PARAM_NAN) && ((flags & F_NAN4) == 0u)) {
        return MT_E_MISSION_PARAM;
    }
    if (((flags & F_NN1) != 0u) && (c->param[0] < 0)) {
        return MT_E_MISSION_PARAM;
    }
    if (((flags & F_NN2) != 0u) && (c->param[1] < 0)) {
        return MT_E_MISSION_PARAM;
    }
    if (((flags & F_INT1) != 0u) && (is_int(c->param[0]) == 0)) {
        return MT_E_MISSION_PARAM;
    }
    if (((flags & F_INT2) != 0u) && (is_int(c->param[1]) == 0)) {
        return MT_E_MISSION_PARAM;
    }
    return MT_OK;
}

/* Command-specific param rules. */
/*@ requires \valid_read(c);
    assigns \nothing;
    ensures \result == MT_OK || \result == MT_E_MISSION_PARAM;
*/
static mt_status_t special_ok(const mt_mission_cmd_t *c)
{
    const int32_t *p = c->param;

    switch (c->id) {
    case MT_MAV_CMD_CONDITION_YAW:
        /* angle [0, 360] deg, direction -1/0/1, relative 0/1 */
        if ((p[0] < 0) || (p[0] > (360 * MT_MISSION_MILLI)) ||
            ((p[2] != -MT_MISSION_MILLI) && (p[2] != 0) && (p[2] != MT_MISSION_MILLI)) ||
            ((p[3] != 0) && (p[3] != MT_MISSION_MILLI))) {
            return MT_E_MISSION_PARAM;
        }
        break;
    case MT_MAV_CMD_DO_CHANGE_SPEED:
        /* speed type 0..3; speed >= -2 (AP: -1 no change, -2 default) */
        if ((p[0] < 0) || (p[0] > (3 * MT_MISSION_MILLI)) || (p[1] < (-2 * MT_MISSION_MILLI))) {
            return MT_E_MISSION_PARAM;
        }
        break;
    case MT_MAV_CMD_DO_SET_HOME:
        if ((p[0] != 0) && (p[0] != MT_MISSION_MILLI)) {
            return MT_E_MISSION_PARAM;
        }
        break;
    case MT_MAV_CMD_DO_SET_SERVO:
        /* channel 1..32, pwm 0..65535 */
        if ((p[0] < MT_MISSION_MILLI) || (p[0] > (32 * MT_MISSION_MILLI)) ||
            (p[1] > (65535 * MT_MISSION_MILLI))) {
            return MT_E_MISSION_PARAM;
        }
        break;
    case MT_MAV_CMD_JUMP_TAG:
        if (p[0] > (65535 * MT_MISSION_MILLI)) {
            return MT_E_MISSION_PARAM;
        }
        break;
    default:
        break;
    }
    return MT_OK;
}

mt_status_t mt_mission_check_cmd(const mt_mission_cmd_t *cmds, uint16_t n, uint16_t i)
{
    const mt_mission_cmd_t *c = &cmds[i];
    uint32_t t = find_cmd(c->id);
    uint8_t flags;
    mt_status_t st;

    if (t >= N_CMDS) {
        return MT_E_MISSION_CMD;
    }
    if ((i == 0u) && (c->id != MT_MAV_CMD_WAYPOINT)) {
        return MT_E_MISSION_CMD; /* home must be a waypoint */
    }
    flags = k_cmds[t].flags;
    if (frame_ok(c->frame, flags) == 0) {
        return MT_E_MISSION_FRAME;
    }
    st = params_ok(c, flags);
    if (st != MT_OK) {
        return st;
    }
    st = special_ok(c);
    if (st != MT_OK) {
        return st;
    }
    if (((flags & F_LOC) != 0u) &&
        ((c->x < -MT_MISSION_LAT_MAX) || (c->x > MT_MISSION_LAT_MAX) ||
         (c->y < -MT_MISSION_LON_MAX) || (c->y > MT_MISSION_LON_MAX))) {
        return MT_E_MISSION_LOCATION;
    }
    if ((c->id == MT_MAV_CMD_DO_JUMP) || (c->id == MT_MAV_CMD_DO_JUMP_TAG)) {
        if (repeat_ok(c->param[1]) == 0) {
            return MT_E_MISSION_JUMP;
        }
        if (is_int(c->param[0]) == 0) {
            return MT_E_MISSION_JUMP;
        }
        if (c->id == MT_MAV_CMD_DO_JUMP) {
            if (((c->param[0] / MT_MISSION_MILLI) < 1) ||
                ((c->param[0] / MT_MISSION_MILLI) >= (int32_t)n)) {
                return MT_E_MISSION_JUMP;
            }
        } else if ((c->param[0] < 0) || (c->param[0] > (65535 * MT_MISSION_MILLI))) {
            return MT_E_MISSION_JUMP;
        } else {
            /* a tag in range */
        }
    }
    return MT_OK;
}

/* First JUMP_TAG in [1, n) whose tag is `tag` (fixed point), or n. Bounded by n. */
/*@ requires MtMissionCmdsIn(cmds, n);
    assigns \nothing;
    ensures 1 <= \result <= n;
*/
static uint16_t find_tag(const mt_mission_cmd_t *cmds, uint16_t n, int32_t tag)
{
    uint16_t j;

    /*@ loop invariant 1 <= j <= n;
        loop assigns j;
        loop variant n - j;
    */
    for (j = 1u; j < n; j++) {
        if ((cmds[j].id == MT_MAV_CMD_JUMP_TAG) && (cmds[j].param[0] == tag)) {
            return j;
        }
    }
    return n;
}

/* Whether every walk from index i reaches a nav command or the end, given the
 * marks of the other nodes (one relaxation step of the loop check). */
/*@ requires MtMissionStaged(&mt_mission_scratch_target[0], cmds, n);
    requires 1 <= i < n;
    assigns \nothing;
*/
static uint8_t node_safe(const mt_mission_cmd_t *cmds, uint16_t n, uint16_t i)
{
    uint16_t id = cmds[i].id;
    uint8_t next = ((i + 1u) >= n) ? 1u : mt_mission_scratch_safe[i + 1u];
    int32_t rep;
    uint8_t tgt;

    if ((id != MT_MAV_CMD_DO_JUMP) && (id != MT_MAV_CMD_DO_JUMP_TAG)) {
        return (mt_mission_kind_of(id) == MT_MISSION_KIND_NAV) ? 1u : next;
    }
    rep = cmds[i].param[1];
    tgt = mt_mission_scratch_safe[mt_mission_scratch_target[i]];
    if (rep < 0) {
        return tgt;
    }
    if (rep == 0) {
        return next;
    }
    return ((tgt != 0u) && (next != 0u)) ? 1u : 0u;
}

/* mt_mission_check without the mission object (which it does not need). */
/*@ requires cmds: n < 1 || n > MT_CFG_MISSION_MAX_CMDS || MtMissionCmdsIn(cmds, n);
    requires bad: \valid(bad) && \separated(bad, cmds + (0 .. n - 1));
    requires sep_scratch: \separated(bad, mt_mission_scratch_safe + (0 .. MT_CFG_MISSION_MAX_CMDS - 1),
                                      mt_mission_scratch_target + (0 .. MT_CFG_MISSION_MAX_CMDS - 1)) &&
        \separated(cmds + (0 .. n - 1), mt_mission_scratch_safe + (0 .. MT_CFG_MISSION_MAX_CMDS - 1),
                   mt_mission_scratch_target + (0 .. MT_CFG_MISSION_MAX_CMDS - 1));
    assigns mt_mission_scratch_safe[0 .. MT_CFG_MISSION_MAX_CMDS - 1],
            mt_mission_scratch_target[0 .. MT_CFG_MISSION_MAX_CMDS - 1], *bad;
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
static mt_status_t check_list(const mt_mission_cmd_t *cmds, uint16_t n, uint16_t *bad)
{
    uint16_t i;
    uint32_t round;
    int changed;

    *bad = 0u;
    if ((n < 1u) || (n > MT_CFG_MISSION_MAX_CMDS)) {
        return MT_E_MISSION_SIZE;
    }
    /* 1. every command on its own; jump targets into the scratch */
    /*@ loop invariant 0 <= i <= n;
        loop invariant \forall integer j; 1 <= j < i ==> MtMissionIsJumpId(cmds[j].id) ==>
            1 <= mt_mission_scratch_target[j] < n && MtMissionRepeatOk(cmds[j].param[1]);
        loop assigns i, mt_mission_scratch_target[0 .. n - 1], *bad;
        loop variant n - i;
    */
    for (i = 0u; i < n; i++) {
        mt_status_t st = mt_mission_check_cmd(cmds, n, i);
        if (st != MT_OK) {
            *bad = i;
            return st;
        }
        mt_mission_scratch_target[i] = 0u;
        if ((i >= 1u) && (cmds[i].id == MT_MAV_CMD_DO_JUMP)) {
            int32_t tgt = cmds[i].param[0] / MT_MISSION_MILLI;
            mt_mission_scratch_target[i] = (uint16_t)tgt;
        } else if ((i >= 1u) && (cmds[i].id == MT_MAV_CMD_DO_JUMP_TAG)) {
            uint16_t t = find_tag(cmds, n, cmds[i].param[0]);
            if (t >= n) {
                *bad = i;
                return MT_E_MISSION_JUMP;
            }
            mt_mission_scratch_target[i] = t;
        } else {
            /* not a jump: no target */
        }
    }
    /* 2. loop check: mark the nodes from which every walk reaches a nav command or
     *    the end; a node never marked lies on, or leads into, a loop without a nav
     *    command. n rounds suffice (each round marks at least one new node). */
    /*@ loop invariant 0 <= i <= n;
        loop assigns i, mt_mission_scratch_safe[0 .. n - 1];
        loop variant n - i;
    */
    for (i = 0u; i < n; i++) {
        mt_mission_scratch_safe[i] = 0u;
    }
    changed = 1;
    /*@ loop invariant 0 <= round <= n;
        loop invariant MtMissionStaged(&mt_mission_scratch_target[0], cmds, n);
        loop assigns round, changed, i, mt_mission_scratch_safe[0 .. n - 1];
        loop variant n - round;
    */
    for (round = 0u; (round < n) && (changed != 0); round++) {
        changed = 0;
        /*@ loop invariant 0 <= i < n;
            loop invariant MtMissionStaged(&mt_mission_scratch_target[0], cmds, n);
            loop assigns i, changed, mt_mission_scratch_safe[0 .. n - 1];
            loop variant i;
        */
        for (i = (uint16_t)(n - 1u); i >= 1u; i--) {
            if ((mt_mission_scratch_safe[i] == 0u) && (node_safe(cmds, n, i) != 0u)) {
                mt_mission_scratch_safe[i] = 1u;
                changed = 1;
            }
        }
    }
    /*@ loop invariant 1 <= i <= n;
        loop assigns i, *bad;
        loop variant n - i;
    */
    for (i = 1u; i < n; i++) {
        if (mt_mission_scratch_safe[i] == 0u) {
            *bad = i;
            return MT_E_MISSION_LOOP;
        }
    }
    *bad = MT_MISSION_NONE;
    return MT_OK;
}

mt_status_t mt_mission_check(const mt_mission_t *m, const mt_mission_cmd_t *cmds, uint16_t n, uint16_t *bad)
{
    mt_status_t st = check_list(cmds, n, bad);

    (void)m; /* the active mission is not needed to check a candidate */
    /*@ assert kept: MtMissionActiveUnchanged{Pre, Here}(m); */
    /*@ assert kinds: MtMissionKinds(m); */
    /*@ assert jumps: MtMissionJumps(m); */
    /*@ assert counters: MtMissionCounters(m); */
    /*@ assert cursors: MtMissionCursors(m); */
    return st;
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
 * jump its resolved target and repeat count; the jump counter starts at 0. */
/*@ requires \valid(m) && 1 <= i < n <= MT_CFG_MISSION_MAX_CMDS;
    requires \valid_read(c) && \separated(c, m);
    requires MtMissionIsJumpId(c->id) ==> 1 <= tgt < n && MtMissionRepeatOk(c->param[1]);
    assigns m->cmd[i].id, m->cmd[i].frame, m->cmd[i].options, m->cmd[i].param[0 .. 3],
            m->cmd[i].x, m->cmd[i].y, m->cmd[i].z,
            m->kind[i], m->target[i], m->repeat[i], m->count[i];
    ensures kind: (m->kind[i] == MT_MISSION_KIND_NAV || m->kind[i] == MT_MISSION_KIND_DO ||
             m->kind[i] == MT_MISSION_KIND_JUMP || m->kind[i] == MT_MISSION_KIND_TAG) &&
            (m->kind[i] == MT_MISSION_KIND_JUMP <==> MtMissionIsJumpId(m->cmd[i].id)) &&
            (m->kind[i] == MT_MISSION_KIND_TAG <==> m->cmd[i].id == MT_MAV_CMD_JUMP_TAG);
    ensures jump: (m->kind[i] == MT_MISSION_KIND_JUMP ==>
                1 <= m->target[i] < n && -1 <= m->repeat[i] <= MT_MISSION_REPEAT_MAX);
    ensures counter: (m->kind[i] == MT_MISSION_KIND_JUMP ==>
                (m->repeat[i] >= 0 ==> 0 <= m->count[i] <= m->repeat[i]) &&
                (m->repeat[i] < 0 ==> m->count[i] == 0));
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
    m->count[i] = 0;
    if (k == MT_MISSION_KIND_JUMP) {
        m->target[i] = tgt;
        m->repeat[i] = (int16_t)(c->param[1] / MT_MISSION_MILLI);
    }
}

/* Cursors of a freshly applied list of n commands (entries already stored). */
/*@ requires \valid(m) && 1 <= n <= MT_CFG_MISSION_MAX_CMDS;
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
*/
static void reset_cursors(mt_mission_t *m, uint16_t n)
{
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

/* Entries 1 .. n-1 from the checked list (home is stored by apply). */
/*@ requires \valid(m) && 1 <= n <= MT_CFG_MISSION_MAX_CMDS;
    requires \separated(m, mt_mission_scratch_target + (0 .. MT_CFG_MISSION_MAX_CMDS - 1));
    requires MtMissionStaged(&mt_mission_scratch_target[0], cmds, n);
    requires \separated(cmds + (0 .. n - 1), m);
    assigns m->cmd[1 .. n - 1], m->kind[1 .. n - 1], m->target[1 .. n - 1], m->repeat[1 .. n - 1],
            m->count[1 .. n - 1];
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
        loop assigns i, m->cmd[1 .. n - 1], m->kind[1 .. n - 1], m->target[1 .. n - 1],
                     m->repeat[1 .. n - 1], m->count[1 .. n - 1];
        loop variant n - i;
    */
    for (i = 1u; i < n; i++) {
        put_cmd(m, i, &cmds[i], mt_mission_scratch_target[i], n);
    }
}

/* Make the checked list the active mission. Cannot fail. (Only the parts of
 * the invariant it keeps are required: small contexts keep the goals fast.) */
/*@ requires \valid(m) && \separated(m, mt_mission_scratch_safe + (0 .. MT_CFG_MISSION_MAX_CMDS - 1),
                                     mt_mission_scratch_target + (0 .. MT_CFG_MISSION_MAX_CMDS - 1));
    requires m->start_fn != \null && m->verify_fn != \null && m->complete_fn != \null;
    requires MtMissionStaged(&mt_mission_scratch_target[0], cmds, n);
    requires \separated(cmds + (0 .. n - 1), m);
    assigns m->cmd[0 .. n - 1], m->kind[0 .. n - 1], m->target[0 .. n - 1], m->repeat[0 .. n - 1],
            m->count[0 .. n - 1], m->total, m->generation, m->state, m->do_done, m->nav,
            m->do_cmd, m->nav_idx, m->do_idx, m->prev_nav;
    ensures MtMissionInv(m);
    ensures m->total == n && m->state == MT_MISSION_STOPPED && m->nav_idx == MT_MISSION_NONE;
    ensures m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE;
    ensures m->generation == \old(m->generation) + 1 || \old(m->generation) == 0xFFFFFFFF;
*/
static void apply(mt_mission_t *m, const mt_mission_cmd_t *cmds, uint16_t n)
{
    copy_cmd(&m->cmd[0], &cmds[0]);
    m->kind[0] = MT_MISSION_KIND_HOME;
    m->target[0] = 0u;
    m->repeat[0] = 0;
    m->count[0] = 0;
    put_all(m, cmds, n);
    reset_cursors(m, n);
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
    apply(m, cmds, n);
    return MT_OK;
}

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

/* The nav command the walk from p reaches first, jumps followed without
 * counting (fresh: with every counter 0); total at the end; MT_MISSION_NONE
 * when the bound is hit. Visits at most total commands. */
/*@ requires MtMissionInv(m) && 1 <= p < m->total;
    assigns \nothing;
    ensures \result == m->total || \result == MT_MISSION_NONE ||
            (MtMissionIdx(m, \result) && m->kind[\result] == MT_MISSION_KIND_NAV);
*/
static uint16_t look_nav(const mt_mission_t *m, uint16_t p, int fresh)
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
    n = look_nav(m, from, 0);
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
    assigns m->state, m->nav, m->do_cmd, m->do_done, m->completions, MtPortNow;
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

/* No active nav or do command; the do search starts over. */
/*@ requires MtMissionInv(m);
    assigns m->nav, m->do_cmd, m->do_idx, m->do_done;
    ensures MtMissionInv(m);
    ensures m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE && m->do_idx == MT_MISSION_NONE;
    ensures m->do_done == 0;
*/
static void drop_both(mt_mission_t *m)
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
    assigns MtPortNow;
*/
static void start_do(mt_mission_t *m)
{
    if (m->kind[m->do_cmd] == MT_MISSION_KIND_DO) {
        (void)mt_mission_invoke_cmd(m->start_fn, m->ctx, m->do_cmd, &m->cmd[m->do_cmd]);
    }
}

/* Verify the active do command: a JUMP_TAG verifies at once [verify_command]. */
/*@ requires MtMissionInv(m) && m->do_cmd != MT_MISSION_NONE;
    assigns MtPortNow;
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
            m->count[0 .. m->total - 1], MtPortNow;
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

    drop_both(m);
    /*@ loop invariant 0 <= k <= m->total + ADVANCE_EXTRA;
        loop invariant 1 <= q <= m->total;
        loop invariant MtMissionInv(m) && m->state == MT_MISSION_RUNNING;
        loop invariant m->nav == MT_MISSION_NONE && m->do_cmd == MT_MISSION_NONE && m->do_done == 0;
        loop invariant d == MT_MISSION_NONE || (d == m->do_idx && MtMissionIdx(m, d));
        loop assigns k, q, d, m->nav, m->nav_idx, m->prev_nav, m->do_cmd, m->do_idx, m->do_done,
                     m->count[0 .. m->total - 1], MtPortNow;
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

/* Drop both commands and run the nav advance from p; the end completes the
 * mission [set_current_cmd while running]. */
/*@ requires MtMissionInv(m) && m->total >= 2 && m->state == MT_MISSION_RUNNING;
    requires 1 <= p <= m->total;
    assigns m->state, m->nav, m->nav_idx, m->prev_nav, m->do_cmd, m->do_idx, m->do_done,
            m->completions, m->count[0 .. m->total - 1], MtPortNow;
    ensures MtMissionInv(m);
    ensures m->state == MT_MISSION_RUNNING || m->state == MT_MISSION_COMPLETE;
    ensures complete_once: m->completions == \old(m->completions) + (m->state == MT_MISSION_COMPLETE ? 1 : 0) ||
        \old(m->completions) == 0xFFFFFFFF;
*/
static void advance_or_finish(mt_mission_t *m, uint16_t p)
{
    if (advance(m, p) == 0) {
        finish(m);
    }
}

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
    drop_both(m);
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
    advance_or_finish(m, 1u);
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

/* Not running: walk from p, counting jumps, to the first nav command; it and
 * the first do command passed become active without a start [the stopped
 * branch of set_current_cmd]. The caller has seen a nav command ahead; if the
 * walk still ends, nothing is active and no nav command is set. */
/*@ requires MtMissionInv(m) && m->total >= 2 && m->state != MT_MISSION_RUNNING;
    requires 1 <= p < m->total;
    assigns m->nav, m->nav_idx, m->do_cmd, m->do_idx, m->do_done, m->count[0 .. m->total - 1];
    ensures MtMissionInv(m);
*/
static void preload(mt_mission_t *m, uint16_t p)
{
    uint16_t q = p;
    uint16_t d = MT_MISSION_NONE;
    uint32_t k;

    drop_both(m);
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
        advance_or_finish(m, m->do_cmd);
    } else if (m->nav != MT_MISSION_NONE) {
        advance_or_finish(m, m->nav);
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
    if ((m->state != MT_MISSION_RUNNING) && (look_nav(m, p, fresh) >= m->total)) {
        return MT_E_EMPTY;
    }
    if (fresh != 0) {
        zero_counts(m);
        m->prev_nav = MT_MISSION_NONE;
    }
    if (m->state == MT_MISSION_RUNNING) {
        advance_or_finish(m, p);
    } else {
        preload(m, p);
        set_state(m, MT_MISSION_STOPPED);
    }
    return MT_OK;
}

mt_status_t mt_mission_restart_current(mt_mission_t *m)
{
    if ((m->state != MT_MISSION_RUNNING) || (m->nav_idx == MT_MISSION_NONE)) {
        return MT_E_STATE;
    }
    advance_or_finish(m, m->nav_idx);
    return MT_OK;
}

/* The do search [advance_current_do_cmd]: the next command after do_idx,
 * jumps followed without counting, starts if it is a do command (or is a
 * JUMP_TAG); a nav command or the end sets do_done. */
/*@ requires MtMissionInv(m) && m->total >= 2 && m->nav != MT_MISSION_NONE;
    requires m->do_cmd == MT_MISSION_NONE;
    assigns m->do_cmd, m->do_idx, m->do_done, MtPortNow;
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
            m->completions, m->count[0 .. m->total - 1], MtPortNow;
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
    assigns m->do_cmd, m->do_idx, m->do_done, MtPortNow;
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
