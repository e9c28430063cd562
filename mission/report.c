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
} sim_t;

static bool sim_start(void *ctx, uint16_t i, const mt_mission_cmd_t *c)
{
    sim_t *s = (sim_t *)ctx;

    if (s->rep->nplan < s->max_plan) {
        mt_plan_step_t *st = &s->plan[s->rep->nplan];
        st->index = i;
        st->command = c->id;
        st->kind = mt_mission_kind_of(c->id);
        s->rep->nplan++;
    } else {
        s->rep->truncated = 1;
    }
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
        return "jump target outside [1, count), tag outside [0, 65535], or repeat not -1 or 0..32767";
    default:
        return "rejected";
    }
}

static void add_err(mt_report_t *rep, const mt_wpl_error_t *e)
{
    if (rep->nerr < MT_REPORT_MAX_ERRORS) {
        rep->errors[rep->nerr++] = *e;
    }
}

mt_status_t mt_report_check(const char *text, size_t len, mt_plan_step_t *plan, size_t max_plan,
                            mt_report_t *rep)
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
    if (items == NULL || cmds == NULL || m == NULL) {
        free(items);
        free(cmds);
        free(m);
        return MT_E_FULL;
    }
    first = mt_wpl_parse(text, len, items, MT_CFG_MISSION_MAX_CMDS, &n, &e);
    rep->nitems = n;
    if (first != MT_OK) {
        add_err(rep, &e);
        goto out;
    }
    if (n == 0u) {
        memset(&e, 0, sizeof e);
        e.st = MT_E_MISSION_SIZE;
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
    if (n >= 2u && mt_mission_start(m) == MT_OK) {
        size_t guard = 0u;
        while (m->state == MT_MISSION_RUNNING && !rep->truncated && guard < 8u * (max_plan + 8u)) {
            (void)mt_mission_update(m);
            guard++;
        }
        if (m->state == MT_MISSION_RUNNING) {
            rep->truncated = 1;
        }
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

static const char *cmd_label(uint16_t id)
{
    const char *n = mt_wpl_cmd_name(id);
    return n != NULL ? n : "?";
}

size_t mt_report_text(const mt_report_t *rep, const char *file, char *out, size_t cap)
{
    buf_t b = {out, cap, 0u};
    size_t i;

    if (cap > 0u) {
        out[0] = '\0';
    }
    for (i = 0u; i < rep->nerr; i++) {
        const mt_wpl_error_t *e = &rep->errors[i];
        put(&b, "%s:%u:", file, (unsigned)e->line);
        if (e->field != 0u) {
            put(&b, " field %u:", (unsigned)e->field);
        }
        if (e->index != MT_MISSION_NONE) {
            put(&b, " index %u:", (unsigned)e->index);
        }
        put(&b, " %s [%s]\n", e->reason, mt_status_str(e->st));
    }
    if (!rep->valid) {
        put(&b, "%s: INVALID (%u error%s)\n", file, (unsigned)rep->nerr, rep->nerr == 1u ? "" : "s");
        return b.used;
    }
    put(&b, "%s: valid, %u items\nplan (every verify succeeds, jumps unrolled):\n", file,
        (unsigned)rep->nitems);
    for (i = 0u; i < rep->nplan; i++) {
        const mt_plan_step_t *s = &rep->plan[i];
        put(&b, "  %4u  %-3s  #%-4u %s (%u)\n", (unsigned)i + 1u, s->kind == MT_MISSION_KIND_NAV ? "nav" : "do",
            (unsigned)s->index, cmd_label(s->command), (unsigned)s->command);
    }
    if (rep->truncated) {
        put(&b, "  ... truncated after %u steps (the mission repeats forever)\n", (unsigned)rep->nplan);
    } else {
        put(&b, "  mission complete\n");
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
        const mt_wpl_error_t *e = &rep->errors[i];
        put(&b, "%s{\"line\": %u, \"field\": %u, \"index\": ", i ? ", " : "", (unsigned)e->line,
            (unsigned)e->field);
        if (e->index == MT_MISSION_NONE) {
            put(&b, "null");
        } else {
            put(&b, "%u", (unsigned)e->index);
        }
        put(&b, ", \"status\": ");
        put_json_str(&b, mt_status_str(e->st));
        put(&b, ", \"reason\": ");
        put_json_str(&b, e->reason);
        put(&b, "}");
    }
    put(&b, "], \"plan\": [");
    for (i = 0u; i < rep->nplan; i++) {
        const mt_plan_step_t *s = &rep->plan[i];
        put(&b, "%s{\"index\": %u, \"command\": %u, \"name\": \"%s\", \"kind\": \"%s\"}", i ? ", " : "",
            (unsigned)s->index, (unsigned)s->command, cmd_label(s->command),
            s->kind == MT_MISSION_KIND_NAV ? "nav" : "do");
    }
    put(&b, "], \"truncated\": %s}\n", rep->truncated ? "true" : "false");
    return b.used;
}
