/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file report.c
 * @brief Whole-file check and execution plan (see report.h).
 */
#include "report.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    mt_mission_t *m;
    mt_report_t *rep;
    mt_plan_step_t *plan;
    size_t max_plan;
    size_t steps; /**< commands started, recorded or not */
} sim_t;

/* The part of a running mission that decides what it does next. */
typedef struct {
    uint8_t state;
    uint8_t do_done;
    uint16_t nav;
    uint16_t do_cmd;
    uint16_t nav_idx;
    uint16_t do_idx;
    uint16_t prev_nav;
    int16_t count[MT_CFG_MISSION_MAX_CMDS];
} snap_t;

static void snap_take(snap_t *s, const mt_mission_t *m)
{
    s->state = m->state;
    s->do_done = m->do_done;
    s->nav = m->nav;
    s->do_cmd = m->do_cmd;
    s->nav_idx = m->nav_idx;
    s->do_idx = m->do_idx;
    s->prev_nav = m->prev_nav;
    memcpy(s->count, m->count, (size_t)m->total * sizeof m->count[0]);
}

static int snap_same(const snap_t *s, const mt_mission_t *m)
{
    return s->state == m->state && s->do_done == m->do_done && s->nav == m->nav &&
           s->do_cmd == m->do_cmd && s->nav_idx == m->nav_idx && s->do_idx == m->do_idx &&
           s->prev_nav == m->prev_nav &&
           memcmp(s->count, m->count, (size_t)m->total * sizeof m->count[0]) == 0;
}

static bool sim_start(void *ctx, uint16_t i, const mt_mission_cmd_t *c)
{
    sim_t *s = (sim_t *)ctx;

    if (s->rep->nplan < s->max_plan) {
        mt_plan_step_t *st = &s->plan[s->rep->nplan];
        st->index = i;
        st->command = c->id;
        st->kind = mt_mission_kind_of(c->id);
        /* during the nav advance no nav command is active (mt/mission.h) */
        st->during = st->kind == MT_MISSION_KIND_NAV ? MT_MISSION_NONE : s->m->nav;
        s->rep->nplan++;
    }
    s->steps++;
    return true;
}

static bool sim_verify(void *ctx, uint16_t i, const mt_mission_cmd_t *c)
{
    sim_t *s = (sim_t *)ctx;

    (void)i;
    if (mt_mission_kind_of(c->id) != MT_MISSION_KIND_NAV) {
        return true;
    }
    /* a nav command completes once the do commands before it have run */
    return s->m->do_cmd == MT_MISSION_NONE && s->m->do_done != 0u;
}

static void sim_done(void *ctx)
{
    (void)ctx;
}

static const char *cmd_problem(mt_status_t st, size_t i, uint8_t frame)
{
    static char buf[64];

    switch (st) {
    case MT_E_MISSION_CMD:
        return i == 0u ? "index 0 (home) must be a WAYPOINT (16)" : "unknown or unsupported command id";
    case MT_E_MISSION_PARAM:
        return "a parameter is out of range, not an integer, or NaN where NaN is not allowed";
    case MT_E_MISSION_LOCATION:
        return "latitude outside [-90, 90] or longitude outside [-180, 180]";
    case MT_E_MISSION_FRAME:
        snprintf(buf, sizeof buf, "frame %u is not supported for this command", (unsigned)frame);
        return buf;
    case MT_E_MISSION_JUMP:
        return "jump target outside [1, count), tag outside [0, 65535], or repeat not -1 or "
               "0..32767";
    default: return "rejected";
    }
}

static void add_err(mt_report_t *rep, const mt_wpl_error_t *e)
{
    if (rep->nerr < MT_REPORT_MAX_ERRORS) {
        rep->errors[rep->nerr++] = *e;
    }
}

/* Run the sequencer under the report's verify policy (report.h); record the plan, decide why
 * it is cut. */
static void run_plan(mt_mission_t *m, sim_t *sim, mt_report_t *rep)
{
    const size_t limit = 8u * (sim->max_plan + 8u) + MT_REPORT_EXTRA_UPDATES;
    snap_t *snap = malloc(sizeof *snap);
    size_t guard = 0u;
    size_t since = 0u;
    size_t power = 1u;
    int have_snap = 0;
    int forever = 0;

    if (snap == NULL || mt_mission_start(m) != MT_OK) {
        free(snap);
        return;
    }
    while (m->state == MT_MISSION_RUNNING && guard < limit) {
        (void)mt_mission_update(m);
        guard++;
        if (sim->steps <= sim->max_plan) {
            continue;
        }
        /* past the plan limit: does the (deterministic) run come back to a state? */
        if (have_snap && snap_same(snap, m)) {
            forever = 1;
            break;
        }
        if (++since == power) {
            snap_take(snap, m);
            have_snap = 1;
            power *= 2u;
            since = 0u;
        }
    }
    free(snap);
    if (m->state != MT_MISSION_RUNNING) {
        rep->plan_total = sim->steps;
    }
    if (forever) {
        rep->truncated = MT_REPORT_FOREVER;
    } else if (sim->steps > sim->max_plan || m->state == MT_MISSION_RUNNING) {
        rep->truncated = MT_REPORT_OVER_LIMIT;
    }
}

mt_status_t mt_report_check(const char *text, size_t len, mt_plan_step_t *plan, size_t max_plan,
                            mt_report_t *rep)
{
    return mt_report_check_as(MT_MFILE_AUTO, text, len, plan, max_plan, rep);
}

mt_status_t mt_report_check_as(mt_mfile_format_t fmt, const char *text, size_t len, mt_plan_step_t *plan,
                               size_t max_plan, mt_report_t *rep)
{
    mt_wpl_item_t *items = calloc(MT_CFG_MISSION_MAX_CMDS, sizeof *items);
    mt_mission_cmd_t *cmds = calloc(MT_CFG_MISSION_MAX_CMDS, sizeof *cmds);
    mt_mission_t *m = calloc(1u, sizeof *m);
    mt_status_t first = MT_OK;
    mt_wpl_error_t e;
    size_t n = 0u;
    size_t i;
    sim_t sim;

    memset(rep, 0, sizeof *rep);
    rep->plan = plan;
    rep->max_plan = max_plan;
    if (items == NULL || cmds == NULL || m == NULL) {
        free(items);
        free(cmds);
        free(m);
        return MT_E_FULL;
    }
    first = mt_mfile_parse(fmt, text, len, items, MT_CFG_MISSION_MAX_CMDS, &n, &e, &rep->warnings);
    rep->nitems = n;
    if (first != MT_OK) {
        add_err(rep, &e);
        goto out;
    }
    if (n == 0u) {
        memset(&e, 0, sizeof e);
        e.st = MT_E_MISSION_SIZE;
        e.line = 1u;
        e.index = 0u;
        strcpy(e.reason, "no items: a mission needs at least the home entry (index 0)");
        add_err(rep, &e);
        first = MT_E_MISSION_SIZE;
        goto out;
    }
    /* every item: conversion, then the kernel's per-command check */
    for (i = 0u; i < n; i++) {
        mt_status_t st = mt_wpl_to_cmd(&items[i], &cmds[i], &e);
        if (st != MT_OK) {
            add_err(rep, &e);
            if (first == MT_OK) {
                first = st;
            }
            cmds[i].id = 0xFFFFu; /* unknown: the per-command check would repeat the error */
        } else if (cmds[i].frame != items[i].frame) {
            mt_wpl_warn(&rep->warnings, items[i].line, 3u, (uint32_t)i,
                        "frame %u ignored: command %u (%s) has no location; checked as frame 2 (MISSION)",
                        (unsigned)items[i].frame, (unsigned)items[i].command,
                        mt_wpl_cmd_name(items[i].command) != NULL ? mt_wpl_cmd_name(items[i].command) : "?");
        }
    }
    for (i = 0u; i < n; i++) {
        mt_status_t st;
        if (cmds[i].id == 0xFFFFu) {
            continue;
        }
        st = mt_mission_check_cmd(cmds, (uint16_t)n, (uint16_t)i);
        if (st != MT_OK) {
            memset(&e, 0, sizeof e);
            e.st = st;
            e.line = items[i].line;
            e.index = (uint32_t)i;
            snprintf(e.reason, sizeof e.reason, "%s %u (%s): %s", "command", (unsigned)cmds[i].id,
                     mt_wpl_cmd_name(cmds[i].id) != NULL ? mt_wpl_cmd_name(cmds[i].id) : "unknown",
                     cmd_problem(st, i, cmds[i].frame));
            add_err(rep, &e);
            if (first == MT_OK) {
                first = st;
            }
        }
    }
    if (first != MT_OK) {
        goto out;
    }
    /* the whole mission: tags, loops */
    memset(&sim, 0, sizeof sim);
    sim.m = m;
    sim.rep = rep;
    sim.plan = plan;
    sim.max_plan = max_plan;
    mt_mission_init(m, sim_start, sim_verify, sim_done, &sim);
    {
        uint16_t bad = 0u;
        mt_status_t st = mt_mission_load(m, cmds, (uint16_t)n, &bad);
        if (st != MT_OK) {
            memset(&e, 0, sizeof e);
            e.st = st;
            e.index = bad;
            e.line = bad < n ? items[bad].line : 0u;
            snprintf(e.reason, sizeof e.reason, "%s",
                     st == MT_E_MISSION_LOOP ? "a loop without a nav command starts here (it would never end)"
                     : st == MT_E_MISSION_JUMP ? "DO_JUMP_TAG: no JUMP_TAG with this tag"
                                               : "rejected");
            add_err(rep, &e);
            first = st;
            goto out;
        }
    }
    rep->valid = 1;
    /* the plan: run the sequencer */
    if (n >= 2u) {
        run_plan(m, &sim, rep);
    }
out:
    free(items);
    free(cmds);
    free(m);
    return first;
}

/* snprintf-style appender */
typedef struct {
    char *out;
    size_t cap;
    size_t used;
} buf_t;

static void put(buf_t *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void put(buf_t *b, const char *fmt, ...)
{
    va_list ap;
    int k;

    va_start(ap, fmt);
    k = vsnprintf(b->used < b->cap ? b->out + b->used : NULL, b->used < b->cap ? b->cap - b->used : 0u, fmt,
                  ap);
    va_end(ap);
    if (k > 0) {
        b->used += (size_t)k;
    }
}

static void put_json_str(buf_t *b, const char *s)
{
    put(b, "\"");
    for (; *s != '\0'; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') {
            put(b, "\\%c", c);
        } else if (c < 0x20u || c >= 0x7Fu) {
            put(b, "\\u%04x", c);
        } else {
            put(b, "%c", c);
        }
    }
    put(b, "\"");
}

/* {"line", "field", "index", ["status",] "reason"} */
static void put_json_diag(buf_t *b, const mt_wpl_error_t *e, int with_status)
{
    put(b, "{\"line\": %u, \"field\": %u, \"index\": ", (unsigned)e->line, (unsigned)e->field);
    if (e->index == MT_MISSION_NONE) {
        put(b, "null");
    } else {
        put(b, "%u", (unsigned)e->index);
    }
    if (with_status) {
        put(b, ", \"status\": ");
        put_json_str(b, mt_status_str(e->st));
    }
    put(b, ", \"reason\": ");
    put_json_str(b, e->reason);
    put(b, "}");
}

static const char *cmd_label(uint16_t id)
{
    const char *n = mt_wpl_cmd_name(id);
    return n != NULL ? n : "?";
}

/* "file:line: field F: index I:" (mt_wpl_where) */
static void put_where(buf_t *b, const char *file, const mt_wpl_error_t *e)
{
    char where[MT_WPL_WHERE_MAX];

    put(b, "%s", mt_wpl_where(where, sizeof where, file, e));
}

static const char *trunc_reason(int t)
{
    return t == (int)MT_REPORT_FOREVER ? "repeats forever" : "longer than the plan limit";
}

size_t mt_report_text(const mt_report_t *rep, const char *file, char *out, size_t cap)
{
    buf_t b = {out, cap, 0u};
    size_t i;
    int timed = 0;

    if (cap > 0u) {
        out[0] = '\0';
    }
    for (i = 0u; i < rep->warnings.n; i++) {
        put_where(&b, file, &rep->warnings.w[i]);
        put(&b, " warning: %s\n", rep->warnings.w[i].reason);
    }
    if (rep->warnings.dropped != 0u) {
        put(&b, "%s: warning: %u more warnings not shown\n", file, (unsigned)rep->warnings.dropped);
    }
    for (i = 0u; i < rep->nerr; i++) {
        const mt_wpl_error_t *e = &rep->errors[i];
        put_where(&b, file, e);
        put(&b, " %s [%s]\n", e->reason, mt_status_str(e->st));
    }
    if (!rep->valid) {
        put(&b, "%s: INVALID (%u error%s)\n", file, (unsigned)rep->nerr, rep->nerr == 1u ? "" : "s");
        return b.used;
    }
    put(&b,
        "%s: valid, %u items\nplan (start order, jumps unrolled; a do command verifies at once, a "
        "nav command "
        "once the do commands before it have started):\n",
        file, (unsigned)rep->nitems);
    for (i = 0u; i < rep->nplan; i++) {
        const mt_plan_step_t *s = &rep->plan[i];
        put(&b, "  %4u  %-3s  #%-4u %s (%u)", (unsigned)i + 1u,
            s->kind == MT_MISSION_KIND_NAV ? "nav" : "do", (unsigned)s->index,
            cmd_label(s->command), (unsigned)s->command);
        if (s->kind != MT_MISSION_KIND_NAV && s->during != MT_MISSION_NONE) {
            put(&b, "  while #%u runs*", (unsigned)s->during);
            timed = 1;
        }
        put(&b, "\n");
    }
    if (rep->truncated == (int)MT_REPORT_FOREVER) {
        put(&b, "  ... truncated after %u steps: the mission repeats forever\n", (unsigned)rep->nplan);
    } else if (rep->truncated != 0 && rep->plan_total != 0u) {
        put(&b,
            "  ... truncated after %u steps: longer than the plan limit (%u steps in all; "
            "--max-plan)\n",
            (unsigned)rep->nplan, (unsigned)rep->plan_total);
    } else if (rep->truncated != 0) {
        put(&b,
            "  ... truncated after %u steps: longer than the plan limit (no end and no repetition "
            "found "
            "in %u more sequencer updates)\n",
            (unsigned)rep->nplan, (unsigned)MT_REPORT_EXTRA_UPDATES);
    } else {
        put(&b, "  mission complete\n");
    }
    if (rep->kernel_max != 0u) {
        put(&b, "%s a kernel built with MT_CFG_MISSION_MAX_CMDS=%u: %u commands, home included%s\n",
            rep->nitems <= rep->kernel_max ? "fits" : "does NOT fit", (unsigned)rep->kernel_max,
            (unsigned)rep->nitems, rep->nitems <= rep->kernel_max ? "" : " (build it with a larger setting)");
    }
    if (timed) {
        put(&b, "* starts while that nav command runs, at the update after the previous do command "
                "verified: "
                "with slower do or condition commands it starts later, and it is dropped if the "
                "nav command "
                "completes first (ArduPilot's AP_Mission order; the other do commands start with "
                "the nav "
                "advance, whatever the timing)\n");
    }
    return b.used;
}

size_t mt_report_json(const mt_report_t *rep, char *out, size_t cap)
{
    buf_t b = {out, cap, 0u};
    size_t i;

    if (cap > 0u) {
        out[0] = '\0';
    }
    put(&b, "{\"valid\": %s, \"errors\": [", rep->valid ? "true" : "false");
    for (i = 0u; i < rep->nerr; i++) {
        put(&b, "%s", i ? ", " : "");
        put_json_diag(&b, &rep->errors[i], 1);
    }
    put(&b, "], \"warnings\": [");
    for (i = 0u; i < rep->warnings.n; i++) {
        put(&b, "%s", i ? ", " : "");
        put_json_diag(&b, &rep->warnings.w[i], 0);
    }
    put(&b, "], \"warnings_not_shown\": %u", (unsigned)rep->warnings.dropped);
    put(&b, ", \"plan\": [");
    for (i = 0u; i < rep->nplan; i++) {
        const mt_plan_step_t *s = &rep->plan[i];
        put(&b,
            "%s{\"index\": %u, \"command\": %u, \"name\": \"%s\", \"kind\": \"%s\", \"during\": ",
            i ? ", " : "", (unsigned)s->index, (unsigned)s->command, cmd_label(s->command),
            s->kind == MT_MISSION_KIND_NAV ? "nav" : "do");
        if (s->during != MT_MISSION_NONE) {
            put(&b, "%u}", (unsigned)s->during);
        } else {
            put(&b, "null}");
        }
    }
    put(&b, "], \"truncated\": %s, \"truncated_reason\": ", rep->truncated ? "true" : "false");
    if (rep->truncated) {
        put_json_str(&b, trunc_reason(rep->truncated));
    } else {
        put(&b, "null");
    }
    if (rep->valid && rep->plan_total != 0u) {
        put(&b, ", \"plan_total\": %u", (unsigned)rep->plan_total);
    } else {
        put(&b, ", \"plan_total\": null");
    }
    if (rep->kernel_max != 0u) {
        put(&b, ", \"items\": %u, \"kernel_max_cmds\": %u, \"fits_kernel\": %s", (unsigned)rep->nitems,
            (unsigned)rep->kernel_max, rep->nitems <= rep->kernel_max ? "true" : "false");
    }
    put(&b, "}\n");
    return b.used;
}
