/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mission_check.c
 * @brief Mission validation: the command table, the per-command checks and the
 *        whole-list check (see mt/mission.h for the operating rules).
 *
 * The first half of the seL4-style validate-then-apply: nothing here writes a
 * mission object; the module's validation scratch (defined here) holds the
 * resolved jump targets that mt_mission_load (mission.c) then applies.
 */
#include "mt/mission.h"

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
    ensures known: \result < N_CMDS <==> MtMissionIsKnownId(id);
    ensures flags: \result < N_CMDS ==> k_cmds[\result].flags == MtMissionCmdFlags(id);
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

/* ------------------------------------------------------------ validation */

/* Frames ArduPilot's loader accepts for a command it stores as a location (F_LOC): 0 GLOBAL,
 * 2 MISSION (read as GLOBAL: altitude above mean sea level), 5 GLOBAL_INT, 3 and 6 relative to
 * home, 10 and 11 above terrain. The frame of any other command is not looked at (AP ignores
 * it; the file layer warns). */
/*@ assigns \nothing;
    ensures exact: \result != 0 <==> ((flags & F_LOC) == 0 || frame == 0 || frame == 2 ||
        frame == 3 || frame == 5 || frame == 6 || frame == 10 || frame == 11);
*/
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
    requires nan3: (flags & F_NAN3) != 0 <==> MtMissionFlagNan3(c->id);
    requires nan4: (flags & F_NAN4) != 0 <==> MtMissionFlagNan4(c->id);
    requires nn1: (flags & F_NN1) != 0 <==> MtMissionFlagNn1(c->id);
    requires nn2: (flags & F_NN2) != 0 <==> MtMissionFlagNn2(c->id);
    requires int1: (flags & F_INT1) != 0 <==> MtMissionFlagInt1(c->id);
    requires int2: (flags & F_INT2) != 0 <==> MtMissionFlagInt2(c->id);
    assigns \nothing;
    ensures status: \result == MT_OK || \result == MT_E_MISSION_PARAM;
    ensures exact: \result == MT_OK <==> MtMissionParamsOk(c);
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
    ensures status: \result == MT_OK || \result == MT_E_MISSION_PARAM;
    ensures exact: \result == MT_OK <==> MtMissionSpecialOk(c);
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
    ensures range: 1 <= \result <= n;
    ensures found: \result < n ==> cmds[\result].id == MT_MAV_CMD_JUMP_TAG &&
        cmds[\result].param[0] == tag;
    ensures absent: \result == n ==> \forall integer k; 1 <= k < n ==>
        !(cmds[k].id == MT_MAV_CMD_JUMP_TAG && cmds[k].param[0] == tag);
*/
static uint16_t find_tag(const mt_mission_cmd_t *cmds, uint16_t n, int32_t tag)
{
    uint16_t j;

    /*@ loop invariant 1 <= j <= n;
        loop invariant \forall integer k; 1 <= k < j ==>
            !(cmds[k].id == MT_MAV_CMD_JUMP_TAG && cmds[k].param[0] == tag);
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

/* mt_mission_check without the mission object; ok.entries is WP's alone for now (issue 23). */
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
      ensures entries: MtMissionListReported(cmds, n, \result, *bad);
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
        loop invariant entries: MtMissionEntriesOk(cmds, n, i);
        loop invariant kept: MtMissionCmdsKept{Pre, Here}(cmds, n);
        loop assigns i, mt_mission_scratch_target[0 .. n - 1], *bad;
        loop variant n - i;
    */
    for (i = 0u; i < n; i++) {
        mt_status_t st = mt_mission_check_cmd(cmds, n, i);
        uint16_t tgt = 0u;

        if (st != MT_OK) {
            /*@ assert faulty: MtMissionEntryStatus(cmds, n, i, st); */
            /*@ assert not_ok: !MtMissionEntryStatus(cmds, n, i, MT_OK); */
            *bad = i;
            /*@ assert kept: MtMissionCmdsKept{LoopCurrent, Here}(cmds, n); */
            /*@ assert reported: MtMissionListReported(cmds, n, st, i); */
            return st;
        }
        if ((i >= 1u) && (cmds[i].id == MT_MAV_CMD_DO_JUMP)) {
            int32_t q = cmds[i].param[0] / MT_MISSION_MILLI;
            tgt = (uint16_t)q;
        } else if ((i >= 1u) && (cmds[i].id == MT_MAV_CMD_DO_JUMP_TAG)) {
            tgt = find_tag(cmds, n, cmds[i].param[0]);
            if (tgt >= n) {
                /*@ assert untagged: MtMissionEntryStatus(cmds, n, i, MT_E_MISSION_JUMP); */
                /*@ assert not_ok: !MtMissionEntryStatus(cmds, n, i, MT_OK); */
                *bad = i;
                /*@ assert kept: MtMissionCmdsKept{LoopCurrent, Here}(cmds, n); */
                /*@ assert reported: MtMissionListReported(cmds, n, MT_E_MISSION_JUMP, i); */
                return MT_E_MISSION_JUMP;
            }
            /*@ assert tagged: MtMissionTagFound(cmds, n, i); */
        } else {
            /* not a jump: no target */
        }
        mt_mission_scratch_target[i] = tgt;
        /*@ assert entry_ok: MtMissionEntryStatus(cmds, n, i, MT_OK); */
        /*@ assert kept_here: MtMissionCmdsKept{LoopCurrent, Here}(cmds, n); */
        /*@ assert before_ok: MtMissionEntriesOk(cmds, n, i); */
    }
    /*@ assert back: MtMissionCmdsKept{Here, Pre}(cmds, n); */
    /*@ assert entries_pre: MtMissionEntriesOk{Pre}(cmds, n, n); */
    /* 2. loop check: mark the nodes from which every walk reaches a nav command or
     *    the end; a node never marked lies on, or leads into, a loop without a nav
     *    command. n rounds suffice (each round marks at least one new node). */
    /*@ loop invariant 0 <= i <= n;
        loop invariant kept: MtMissionCmdsKept{Pre, Here}(cmds, n);
        loop assigns i, mt_mission_scratch_safe[0 .. n - 1];
        loop variant n - i;
    */
    for (i = 0u; i < n; i++) {
        mt_mission_scratch_safe[i] = 0u;
    }
    changed = 1;
    /*@ loop invariant 0 <= round <= n;
        loop invariant MtMissionStaged(&mt_mission_scratch_target[0], cmds, n);
        loop invariant kept: MtMissionCmdsKept{Pre, Here}(cmds, n);
        loop assigns round, changed, i, mt_mission_scratch_safe[0 .. n - 1];
        loop variant n - round;
    */
    for (round = 0u; (round < n) && (changed != 0); round++) {
        changed = 0;
        /*@ loop invariant 0 <= i < n;
            loop invariant MtMissionStaged(&mt_mission_scratch_target[0], cmds, n);
            loop invariant kept: MtMissionCmdsKept{Pre, Here}(cmds, n);
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
        loop invariant kept: MtMissionCmdsKept{Pre, Here}(cmds, n);
        loop assigns i, *bad;
        loop variant n - i;
    */
    for (i = 1u; i < n; i++) {
        if (mt_mission_scratch_safe[i] == 0u) {
            *bad = i;
            /*@ assert kept: MtMissionCmdsKept{Pre, Here}(cmds, n); */
            /*@ assert reported: MtMissionListReported(cmds, n, MT_E_MISSION_LOOP, i); */
            return MT_E_MISSION_LOOP;
        }
    }
    *bad = MT_MISSION_NONE;
    /*@ assert kept: MtMissionCmdsKept{Pre, Here}(cmds, n); */
    /*@ assert reported: MtMissionListReported(cmds, n, MT_OK, MT_MISSION_NONE); */
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
