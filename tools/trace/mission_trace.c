/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file tools/trace/mission_trace.c
 * @brief Trace generator for trace validation of tla/Mission.tla.
 *
 * Loads one fixed mission into the real kernel/src/mission*.c and runs a
 * seeded random sequence of mt_mission_start / stop / resume / set_current /
 * restart_current / update; the start and verify callbacks return seeded
 * random outcomes (a do command's start result is ignored by mission_seq.c).
 * Every call is logged with the callbacks it made (in order, with their
 * index and outcome) and the cursor state it left.
 *
 * The log is a TLA+ module (MissionTraceData.tla):
 *   TN, TKind, TTgt, TRep   the mission as loaded (kind, resolved jump
 *                           target, repeat count per index 1..TN-1)
 *   Trace                   one record per event:
 *     op    "start", "stop", "resume", "set_current", "restart_current",
 *           "update" (a refused update, rc E_STATE), or the two halves of an
 *           accepted update: "update_nav" (the verify of the nav command and
 *           the advance: nav and do starts, the complete callback) then
 *           "update_do" (the verify of the do command or the do search's
 *           start: at most one callback, the call's last, on a do command;
 *           the nav half never ends with one)
 *     arg   set_current's index (0 otherwise)
 *     rc    the status ("OK", "E_STATE", "E_INVALID", "E_EMPTY")
 *     cbs   <<[k |-> "start" | "verify" | "done", i |-> index, r |-> outcome]>>
 *     snap  TRUE when the state fields below are the state after the event
 *           (FALSE for "update_nav": the call has not returned yet)
 *     st, nav, navidx, dcmd, doidx, ddone, prev, cnt
 *           state, nav, nav_idx, do_cmd, do_idx, do_done, prev_nav
 *           (MT_MISSION_NONE logged as 0) and the jump counters of indices
 *           1..TN-1
 * tla/MissionTrace.tla checks that the model takes exactly these steps.
 *
 * usage: mission_trace MISSION OPS SEED OUT_DIR
 *        MISSION: nested | forever | tags_do | do_runs
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mt/mission.h"
#include "trace_rng.h"

#define MAX_CMDS 24u
#define MAX_CBS 600u /* an advance visits at most total + MT_CFG_MISSION_ADVANCE_EXTRA commands */

typedef struct {
    const char *k;
    uint16_t i;
    int r;
} cb_t;

static mt_mission_t g_m;
static uint64_t g_rng;
static cb_t g_cbs[MAX_CBS];
static uint32_t g_ncb;
static FILE *g_out;
static int g_first = 1;

static uint32_t rnd(uint32_t n)
{
    return trace_rnd(&g_rng, n);
}

static void record(const char *k, uint16_t i, int r)
{
    if (g_ncb >= MAX_CBS) {
        fprintf(stderr, "mission_trace: more than %u callbacks in one call\n", MAX_CBS);
        exit(2);
    }
    g_cbs[g_ncb].k = k;
    g_cbs[g_ncb].i = i;
    g_cbs[g_ncb].r = r;
    g_ncb++;
}

/* starts succeed 3 times in 4, verifies 1 time in 3 */
static bool start_cb(void *ctx, uint16_t i, const mt_mission_cmd_t *c)
{
    bool ok = rnd(4u) != 0u;

    (void)ctx;
    (void)c;
    record("start", i, ok);
    return ok;
}

static bool verify_cb(void *ctx, uint16_t i, const mt_mission_cmd_t *c)
{
    bool ok = rnd(3u) == 0u;

    (void)ctx;
    (void)c;
    record("verify", i, ok);
    return ok;
}

static void done_cb(void *ctx)
{
    (void)ctx;
    record("done", 0u, 1);
}

static uint32_t idx(uint16_t v)
{
    return v == MT_MISSION_NONE ? 0u : v;
}

static const char *state_name(uint8_t s)
{
    return s == MT_MISSION_RUNNING ? "running" : s == MT_MISSION_COMPLETE ? "complete" : "stopped";
}

static const char *rc_name(mt_status_t st)
{
    switch (st) {
    case MT_OK: return "OK";
    case MT_E_STATE: return "E_STATE";
    case MT_E_INVALID: return "E_INVALID";
    case MT_E_EMPTY: return "E_EMPTY";
    default: return "other";
    }
}

/* Log the callbacks g_cbs[from .. to-1] as one event. */
static void emit(const char *op, uint32_t arg, mt_status_t rc, uint32_t from, uint32_t to, int snap)
{
    uint32_t j;

    fputs(g_first ? "    " : ",\n    ", g_out);
    g_first = 0;
    fprintf(g_out, "[op |-> \"%s\", arg |-> %u, rc |-> \"%s\", cbs |-> <<", op, arg, rc_name(rc));
    for (j = from; j < to; j++) {
        fprintf(g_out, "%s[k |-> \"%s\", i |-> %u, r |-> %s]", j > from ? ", " : "", g_cbs[j].k,
                g_cbs[j].i, g_cbs[j].r ? "TRUE" : "FALSE");
    }
    fprintf(g_out,
            ">>, snap |-> %s, st |-> \"%s\", nav |-> %u, navidx |-> %u, dcmd |-> %u, doidx |-> %u, "
            "ddone |-> %s, prev |-> %u, cnt |-> <<",
            snap ? "TRUE" : "FALSE", state_name(g_m.state), idx(g_m.nav), idx(g_m.nav_idx),
            idx(g_m.do_cmd), idx(g_m.do_idx), g_m.do_done ? "TRUE" : "FALSE", idx(g_m.prev_nav));
    for (j = 1u; j < g_m.total; j++) {
        fprintf(g_out, "%s%d", j > 1u ? ", " : "", g_m.count[j]);
    }
    fputs(">>]", g_out);
}

/* ------------------------------------------------------------ missions */

typedef struct {
    uint16_t id;
    int16_t p1; /* param 1 (jump target, tag), whole units */
    int16_t p2; /* param 2 (repeat count), whole units */
} item_t;

/* clang-format off */
#define NAV {MT_MAV_CMD_WAYPOINT, 0, 0}
#define DO {MT_MAV_CMD_CONDITION_DELAY, 1, 0}
#define JUMP(to, rep) {MT_MAV_CMD_DO_JUMP, (to), (rep)}
#define TAG(t) {MT_MAV_CMD_JUMP_TAG, (t), 0}
#define JUMP_TAG(t, rep) {MT_MAV_CMD_DO_JUMP_TAG, (t), (rep)}
/* clang-format on */

/* index 0 is home; comments give index: kind */
static const item_t k_nested[] = {
    NAV, /* 1 nav, 2 do, 3 nav, 4 jump->1 x2, 5 tag, 6 do, 7 nav, 8 jump->3 x1, 9 nav */
    NAV, DO, NAV, JUMP(1, 2), TAG(5), DO, NAV, JUMP(3, 1), NAV};
static const item_t k_forever[] = {
    NAV, /* 1 nav, 2 do, 3 jump->5 forever (goto), 4 nav, 5 nav, 6 do, 7 jump->1 forever */
    NAV, DO, JUMP(5, -1), NAV, NAV, DO, JUMP(1, -1)};
static const item_t k_tags_do[] = {
    NAV, /* do-only stretches and jump tags: 1 do, 2 do, 3 nav, 4 tag 7, 5 do, 6 do, 7 nav,
          * 8 jump_tag 7 x2, 9 do, 10 do, 11 do, 12 nav, 13 jump->12 x1, 14 do, 15 do */
    DO,  DO, NAV, TAG(7), DO, DO, NAV, JUMP_TAG(7, 2), DO, DO, DO, NAV, JUMP(12, 1), DO, DO};
static const item_t k_do_runs[] = {
    NAV, /* runs of do commands: 1 do, 2 do, 3 nav, 4 do, 5 do, 6 do, 7 nav, 8 jump->5 x2,
          * 9 tag 9, 10 do, 11 do, 12 nav, 13 jump_tag 9 x1, 14 do, 15 do, 16 do (trailing) */
    DO,  DO, NAV, DO, DO, DO, NAV, JUMP(5, 2), TAG(9), DO, DO, NAV, JUMP_TAG(9, 1), DO, DO, DO};

static mt_mission_cmd_t g_cmds[MAX_CMDS];
static uint16_t g_n;

static int build(const char *name)
{
    const item_t *items;
    uint16_t n;
    uint16_t i;

    if (strcmp(name, "nested") == 0) {
        items = k_nested;
        n = (uint16_t)(sizeof k_nested / sizeof k_nested[0]);
    } else if (strcmp(name, "forever") == 0) {
        items = k_forever;
        n = (uint16_t)(sizeof k_forever / sizeof k_forever[0]);
    } else if (strcmp(name, "tags_do") == 0) {
        items = k_tags_do;
        n = (uint16_t)(sizeof k_tags_do / sizeof k_tags_do[0]);
    } else if (strcmp(name, "do_runs") == 0) {
        items = k_do_runs;
        n = (uint16_t)(sizeof k_do_runs / sizeof k_do_runs[0]);
    } else {
        return -1;
    }
    memset(g_cmds, 0, sizeof g_cmds);
    for (i = 0u; i < n; i++) {
        g_cmds[i].id = items[i].id;
        g_cmds[i].frame = 3u; /* GLOBAL_RELATIVE_ALT */
        g_cmds[i].param[0] = items[i].p1 * MT_MISSION_MILLI;
        g_cmds[i].param[1] = items[i].p2 * MT_MISSION_MILLI;
    }
    g_n = n;
    return 0;
}

static const char *kind_name(uint8_t k)
{
    return k == MT_MISSION_KIND_NAV    ? "nav"
           : k == MT_MISSION_KIND_DO   ? "do"
           : k == MT_MISSION_KIND_JUMP ? "jump"
           : k == MT_MISSION_KIND_TAG  ? "tag"
                                       : "home";
}

static void write_mission(void)
{
    uint16_t i;

    fprintf(g_out, "TN == %u\nTKind == <<", g_m.total);
    for (i = 1u; i < g_m.total; i++) {
        fprintf(g_out, "%s\"%s\"", i > 1u ? ", " : "", kind_name(g_m.kind[i]));
    }
    fputs(">>\nTTgt == <<", g_out);
    for (i = 1u; i < g_m.total; i++) {
        fprintf(g_out, "%s%u", i > 1u ? ", " : "",
                g_m.kind[i] == MT_MISSION_KIND_JUMP ? g_m.target[i] : 0u);
    }
    fputs(">>\nTRep == <<", g_out);
    for (i = 1u; i < g_m.total; i++) {
        fprintf(g_out, "%s%d", i > 1u ? ", " : "",
                g_m.kind[i] == MT_MISSION_KIND_JUMP ? g_m.repeat[i] : 0);
    }
    fputs(">>\n", g_out);
}

/* ------------------------------------------------------------ one operation */

static void step(void)
{
    uint32_t c = rnd(100u);
    mt_status_t rc;
    uint32_t j;

    g_ncb = 0u;
    if (c < 55u) {
        rc = mt_mission_update(&g_m);
        if (rc != MT_OK) {
            emit("update", 0u, rc, 0u, g_ncb, 1);
            return;
        }
        /* the do half's callback, if any, is the last one and is on a do command: the nav
         * half ends with the nav command's verify, a nav start or the complete callback */
        j = g_ncb;
        if ((j > 0u) && (strcmp(g_cbs[j - 1u].k, "done") != 0) &&
            (g_m.kind[g_cbs[j - 1u].i] == MT_MISSION_KIND_DO)) {
            j--;
        }
        emit("update_nav", 0u, rc, 0u, j, 0);
        emit("update_do", 0u, rc, j, g_ncb, 1);
    } else if (c < 63u) {
        rc = mt_mission_stop(&g_m);
        emit("stop", 0u, rc, 0u, g_ncb, 1);
    } else if (c < 75u) {
        rc = mt_mission_resume(&g_m);
        emit("resume", 0u, rc, 0u, g_ncb, 1);
    } else if (c < 85u) {
        uint16_t to = (uint16_t)rnd(g_m.total + 1u); /* total itself: E_INVALID */
        rc = mt_mission_set_current(&g_m, to);
        emit("set_current", to, rc, 0u, g_ncb, 1);
    } else if (c < 96u) {
        rc = mt_mission_restart_current(&g_m);
        emit("restart_current", 0u, rc, 0u, g_ncb, 1);
    } else {
        rc = mt_mission_start(&g_m);
        emit("start", 0u, rc, 0u, g_ncb, 1);
    }
}

int main(int argc, char **argv)
{
    char path[4096];
    uint16_t bad = 0u;
    uint32_t ops;
    uint32_t k;
    mt_status_t st;

    if (argc != 5) {
        fprintf(stderr, "usage: %s nested|forever|tags_do|do_runs OPS SEED OUT_DIR\n", argv[0]);
        return 2;
    }
    if (build(argv[1]) != 0) {
        fprintf(stderr, "mission_trace: unknown mission %s\n", argv[1]);
        return 2;
    }
    ops = (uint32_t)strtoul(argv[2], NULL, 0);
    g_rng = strtoull(argv[3], NULL, 0) * 0x9E3779B97F4A7C15ull + 1u;
    mt_mission_init(&g_m, start_cb, verify_cb, done_cb, NULL);
    st = mt_mission_load(&g_m, g_cmds, g_n, &bad);
    if (st != MT_OK) {
        fprintf(stderr, "mission_trace: mission %s rejected (%d at %u)\n", argv[1], (int)st, bad);
        return 2;
    }
    snprintf(path, sizeof path, "%s/MissionTraceData.tla", argv[4]);
    g_out = fopen(path, "w");
    if (g_out == NULL) {
        perror(path);
        return 2;
    }
    fprintf(g_out,
            "---- MODULE MissionTraceData ----\n"
            "\\* generated by tools/trace/mission_trace %s %s %s\nEXTENDS Integers\n",
            argv[1], argv[2], argv[3]);
    write_mission();
    fputs("Trace == <<\n", g_out);
    /* the first call starts the mission; then random operations */
    g_ncb = 0u;
    st = mt_mission_start(&g_m);
    emit("start", 0u, st, 0u, g_ncb, 1);
    for (k = 1u; k < ops; k++) {
        step();
    }
    fprintf(g_out, "\n    >>\nCompletions == %u\n====\n", g_m.completions);
    fclose(g_out);
    return 0;
}
