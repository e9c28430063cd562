/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file timeline.c
 * @brief SITL --timeline: the Chrome trace-event JSON writer (see timeline.h).
 */
#include "timeline.h"

#include <stdio.h>

typedef struct {
    uint64_t overruns;
    uint64_t slips;
    uint64_t skips;
} tl_counts_t;

typedef struct {
    FILE *f;
    bool error;
    uint64_t events;
    /* the task run in progress */
    int32_t task;
    uint64_t task_start;
    /* the tick in progress */
    uint64_t tick_start;
    bool in_tick;
    /* each task's last run, and its counters at the start of the tick */
    uint64_t run_start[MT_CFG_SCHED_MAX_TASKS];
    uint64_t run_end[MT_CFG_SCHED_MAX_TASKS];
    tl_counts_t before[MT_CFG_SCHED_MAX_TASKS];
    /* the work queue's items' run counters before a round */
    uint64_t work_before[MT_CFG_WQ_MAX_ITEMS];
} tl_t;

static tl_t g_tl = {NULL, false, 0u, -1, 0u, 0u, false, {0u}, {0u}, {{0u, 0u, 0u}}, {0u}};

/* A JSON string (names come from tables and are plain, but nothing is taken on trust). */
static void put_str(FILE *f, const char *s)
{
    (void)fputc('"', f);
    for (; *s != '\0'; s++) {
        unsigned char c = (unsigned char)*s;
        if ((c == '"') || (c == '\\')) {
            (void)fprintf(f, "\\%c", c);
        } else if (c < 0x20u) {
            (void)fprintf(f, "\\u%04x", (unsigned)c);
        } else {
            (void)fputc(c, f);
        }
    }
    (void)fputc('"', f);
}

/* The separator and the fields every event has. */
static void event_head(const char *ph, tl_track_t track, const char *name, uint64_t ts)
{
    FILE *f = g_tl.f;
    (void)fputs((g_tl.events == 0u) ? "\n" : ",\n", f);
    (void)fprintf(f, "{\"ph\":\"%s\",\"pid\":1,\"tid\":%d,\"ts\":%llu,\"name\":", ph, (int)track,
                  (unsigned long long)ts);
    put_str(f, name);
    g_tl.events++;
}

static void thread_name(tl_track_t track, const char *name, int sort)
{
    event_head("M", track, "thread_name", 0u);
    (void)fputs(",\"args\":{\"name\":", g_tl.f);
    put_str(g_tl.f, name);
    (void)fputs("}}", g_tl.f);
    event_head("M", track, "thread_sort_index", 0u);
    (void)fprintf(g_tl.f, ",\"args\":{\"sort_index\":%d}}", sort);
}

bool tl_open(const char *path, const mt_wq_t *wq)
{
    char wq_name[64];

    g_tl.f = fopen(path, "w");
    if (g_tl.f == NULL) {
        return false;
    }
    (void)fputs(
        "{\"displayTimeUnit\":\"ms\",\"otherData\":{\"source\":\"metronome-sitl --timeline\","
        "\"clock\":\"port time, us\"},\"traceEvents\":[",
        g_tl.f);
    event_head("M", TL_MAIN, "process_name", 0u);
    (void)fputs(",\"args\":{\"name\":\"metronome SITL\"}}", g_tl.f);
    (void)snprintf(wq_name, sizeof(wq_name), "work queue %s", wq->name);
    thread_name(TL_MAIN, "main loop (scheduler)", 1);
    thread_name(TL_TIMER, "timer thread (timer procs)", 2);
    thread_name(TL_IO, "IO thread (io procs)", 3);
    thread_name(TL_WORK, wq_name, 4);
    return true;
}

void tl_work_begin(const mt_wq_t *q)
{
    uint32_t k;

    if (g_tl.f == NULL) {
        return;
    }
    for (k = 0u; k < q->nitems; k++) {
        g_tl.work_before[k] = q->slot[k].stats.runs;
    }
}

void tl_work_end(const mt_wq_t *q, uint64_t t0, uint64_t t1, const char *(*name_of)(uint32_t slot))
{
    uint32_t k;

    if (g_tl.f == NULL) {
        return;
    }
    for (k = 0u; k < q->nitems; k++) {
        uint64_t r;
        for (r = g_tl.work_before[k]; r < q->slot[k].stats.runs; r++) {
            tl_slice(TL_WORK, name_of(k), t0, t1 - t0, "slot", k);
        }
    }
}

void tl_slice(tl_track_t track, const char *name, uint64_t ts, uint64_t dur, const char *arg_name,
              uint64_t arg)
{
    if (g_tl.f == NULL) {
        return;
    }
    event_head("X", track, name, ts);
    (void)fprintf(g_tl.f, ",\"dur\":%llu", (unsigned long long)dur);
    if (arg_name != NULL) {
        (void)fputs(",\"args\":{", g_tl.f);
        put_str(g_tl.f, arg_name);
        (void)fprintf(g_tl.f, ":%llu}", (unsigned long long)arg);
    }
    (void)fputc('}', g_tl.f);
}

void tl_instant(tl_track_t track, const char *name, uint64_t ts, const char *task, uint64_t missed)
{
    if (g_tl.f == NULL) {
        return;
    }
    event_head("i", track, name, ts);
    (void)fputs(",\"s\":\"t\",\"args\":{\"task\":", g_tl.f);
    put_str(g_tl.f, task);
    if (missed != 0u) {
        (void)fprintf(g_tl.f, ",\"missed\":%llu", (unsigned long long)missed);
    }
    (void)fputs("}}", g_tl.f);
}

void tl_task_begin(const mt_sched_t *sched)
{
    g_tl.task = sched->current;
    g_tl.task_start = sched->task_start_us;
}

void tl_task_end(const mt_sched_t *sched, uint64_t now)
{
    uint32_t i;

    if (g_tl.f == NULL) {
        return;
    }
    if ((g_tl.task < 0) || ((uint32_t)g_tl.task >= sched->ntasks)) {
        g_tl.error = true; /* simulated work outside a task run: not expected */
        return;
    }
    i = (uint32_t)g_tl.task;
    tl_slice(TL_MAIN, sched->tasks[i].name, g_tl.task_start, now - g_tl.task_start, "allowed_us",
             sched->task_allowed_us);
    g_tl.run_start[i] = g_tl.task_start;
    g_tl.run_end[i] = now;
    g_tl.task = -1;
}

static void snapshot(const mt_sched_t *sched)
{
    uint32_t i;
    for (i = 0u; i < sched->ntasks; i++) {
        mt_task_report_t r;
        mt_sched_task_report(sched, i, &r);
        g_tl.before[i].overruns = r.overruns;
        g_tl.before[i].slips = r.slips;
        g_tl.before[i].skips = r.budget_skips;
    }
}

void tl_tick_begin(const mt_sched_t *sched, uint64_t sample)
{
    if (g_tl.f == NULL) {
        return;
    }
    snapshot(sched);
    g_tl.tick_start = sample;
    g_tl.in_tick = true;
}

void tl_tick_end(const mt_sched_t *sched, uint64_t now)
{
    char name[40];
    uint32_t i;

    if ((g_tl.f == NULL) || !g_tl.in_tick) {
        return;
    }
    (void)snprintf(name, sizeof(name), "tick %llu", (unsigned long long)sched->tick);
    tl_slice(TL_MAIN, name, g_tl.tick_start, now - g_tl.tick_start, NULL, 0u);
    for (i = 0u; i < sched->ntasks; i++) {
        mt_task_report_t r;
        const tl_counts_t *b = &g_tl.before[i];
        mt_sched_task_report(sched, i, &r);
        if (r.slips != b->slips) {
            tl_instant(TL_MAIN, "slip", g_tl.run_start[i], r.name, r.slips - b->slips);
        }
        if (r.overruns != b->overruns) {
            tl_instant(TL_MAIN, "overrun", g_tl.run_end[i], r.name, 0u);
        }
        if (r.budget_skips != b->skips) {
            tl_instant(TL_MAIN, "budget skip", now, r.name, 0u);
        }
    }
    g_tl.in_tick = false;
}

bool tl_close(void)
{
    bool ok;

    if (g_tl.f == NULL) {
        return true;
    }
    (void)fputs("\n]}\n", g_tl.f);
    ok = (ferror(g_tl.f) == 0) && !g_tl.error;
    ok = (fclose(g_tl.f) == 0) && ok;
    g_tl.f = NULL;
    return ok;
}
