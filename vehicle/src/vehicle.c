/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file vehicle.c
 * @brief The vehicle's topology: the task table (expanded from tasks.def),
 *        the procs, the topics and who subscribes to them, the components'
 *        state and the mission, and the summary. Knows nothing of threads or
 *        ports (see veh.h). It calls the components; no component calls it.
 */
#include <string.h>

#include "veh_int.h"

/* The task table's source; a test build may give another one (tests/vehicle/). */
#ifndef VEHICLE_TASKS_DEF
#define VEHICLE_TASKS_DEF "tasks.def"
#endif

static veh_t g_veh;

/* ---- the table, expanded from its single source ------------------------------------------ */

/* Task indices, in table order. */
#define SCHED_LOOP(hz)
#define SCHED_LATENCY(us)
#define SCHED_TIMER(period, cmin, cmax)
#define SCHED_FAST(name, prio, budget, cmin, cmax) VT_##name,
#define SCHED_TASK(name, rate, budget, prio, cmin, cmax) VT_##name,
enum {
#include VEHICLE_TASKS_DEF
    VT_COUNT
};
#undef SCHED_LOOP
#undef SCHED_LATENCY
#undef SCHED_TIMER
#undef SCHED_FAST
#undef SCHED_TASK

/* Loop rate and timer load. */
#define SCHED_LOOP(hz) VEH_LOOP_HZ = (hz),
#define SCHED_LATENCY(us) VEH_LATENCY_US = (us),
#define SCHED_TIMER(period, cmin, cmax) \
    VEH_TIMER_PERIOD_US = (period), VEH_TIMER_COST_MIN = (cmin), VEH_TIMER_COST_MAX = (cmax),
#define SCHED_FAST(name, prio, budget, cmin, cmax)
#define SCHED_TASK(name, rate, budget, prio, cmin, cmax)
enum {
#include VEHICLE_TASKS_DEF
    VEH_SPEC_END
};
#undef SCHED_LOOP
#undef SCHED_LATENCY
#undef SCHED_TIMER
#undef SCHED_FAST
#undef SCHED_TASK

/* Honest budgets: the worst-case cost plus the timer rounds that can pre-empt one run fit the
 * budget. n rounds stretch a run of cost c to at most c + n * t_max, and need (n - 1) timer
 * periods inside it, so n <= 1 + (c + t_max) / (period - t_max) (tools/sched_check.py). */
#define VEH_ROUNDS_IN_RUN(c) \
    (1 + (((c) + VEH_TIMER_COST_MAX) / (VEH_TIMER_PERIOD_US - VEH_TIMER_COST_MAX)))
#define VEH_HONEST(cmin, cmax, budget) \
    (((cmin) <= (cmax)) && (((cmax) + (VEH_TIMER_COST_MAX * VEH_ROUNDS_IN_RUN(cmax))) <= (budget)))
#define SCHED_LOOP(hz)
#define SCHED_LATENCY(us)
#define SCHED_TIMER(period, cmin, cmax)
#define SCHED_FAST(name, prio, budget, cmin, cmax) \
    _Static_assert(VEH_HONEST(cmin, cmax, budget), \
                   "task " #name ": budget below its worst-case cost plus timer pre-emption");
#define SCHED_TASK(name, rate, budget, prio, cmin, cmax) \
    _Static_assert(VEH_HONEST(cmin, cmax, budget),       \
                   "task " #name ": budget below its worst-case cost plus timer pre-emption");
#include VEHICLE_TASKS_DEF
#undef SCHED_LOOP
#undef SCHED_LATENCY
#undef SCHED_TIMER
#undef SCHED_FAST
#undef SCHED_TASK

/* Task bodies: the component's work, then the simulated execution time (SITL). */
static void task_work(uint32_t i);
#define SCHED_LOOP(hz)
#define SCHED_LATENCY(us)
#define SCHED_TIMER(period, cmin, cmax)
#define SCHED_FAST(name, prio, budget, cmin, cmax) \
    static void vt_##name(void *arg)               \
    {                                              \
        veh_##name((veh_t *)arg);                  \
        task_work(VT_##name);                      \
    }
#define SCHED_TASK(name, rate, budget, prio, cmin, cmax) SCHED_FAST(name, prio, budget, cmin, cmax)
#include VEHICLE_TASKS_DEF
#undef SCHED_LOOP
#undef SCHED_LATENCY
#undef SCHED_TIMER
#undef SCHED_FAST
#undef SCHED_TASK

#define SCHED_LOOP(hz)
#define SCHED_LATENCY(us)
#define SCHED_TIMER(period, cmin, cmax)
#define SCHED_FAST(name, prio, budget, cmin, cmax) {#name, vt_##name, &g_veh, 0u, (budget), (prio)},
#define SCHED_TASK(name, rate, budget, prio, cmin, cmax) \
    {#name, vt_##name, &g_veh, MT_HZ(rate), (budget), (prio)},
static const mt_task_t g_tasks[VT_COUNT] = {
#include VEHICLE_TASKS_DEF
};
#undef SCHED_FAST
#undef SCHED_TASK

typedef struct {
    uint32_t min_us;
    uint32_t max_us;
} veh_cost_t;

#define SCHED_FAST(name, prio, budget, cmin, cmax) {(cmin), (cmax)},
#define SCHED_TASK(name, rate, budget, prio, cmin, cmax) {(cmin), (cmax)},
static const veh_cost_t g_cost[VT_COUNT] = {
#include VEHICLE_TASKS_DEF
};
#undef SCHED_LOOP
#undef SCHED_LATENCY
#undef SCHED_TIMER
#undef SCHED_FAST
#undef SCHED_TASK

static void task_work(uint32_t i)
{
    const veh_platform_t *p = g_veh.plat;
    if (p->task_work != NULL) {
        p->task_work(p->ctx, i, g_cost[i].min_us, g_cost[i].max_us);
    }
}

/* ---- set-up and loop ----------------------------------------------------------------------- */

/* The work queue and the battery topic (the summary's last lines). */
static void veh_summary_battery(veh_t *v)
{
    mt_wq_report_t q;
    mt_work_report_t w;
    char a[24];
    char b[24];
    char c[24];

    mt_wq_report(&v->wq, &q);
    mt_work_report(&v->battery_work, &w);
    veh_printf("work queue %s: %llu runs, %u merged, %u periods missed, deepest %u, max "
               "latency %u us\n",
               q.name, (unsigned long long)q.runs, (unsigned)q.merged, (unsigned)q.missed,
               (unsigned)q.max_depth, (unsigned)q.max_latency_us);
    veh_printf("battery item: %llu runs, run mean %u us max %u us, interval %s ms (min %s, max "
               "%s), %u failed reads\n",
               (unsigned long long)w.runs, (unsigned)w.mean_run_us, (unsigned)w.max_run_us,
               vp_fix(a, sizeof(a), (int64_t)w.mean_interval_us, 1000, 1u),
               vp_fix(b, sizeof(b), (int64_t)w.min_interval_us, 1000, 1u),
               vp_fix(c, sizeof(c), (int64_t)w.max_interval_us, 1000, 1u),
               (unsigned)v->battery_read_fail);
    veh_printf("topic battery: %u published, %u refused; housekeeping: %u received, %u missed, "
               "%u torn\n",
               (unsigned)v->battery_topic.publishes, (unsigned)v->battery_topic.rejected,
               (unsigned)v->house.battery_sub.received, (unsigned)v->house.battery_sub.missed,
               (unsigned)v->house.battery_sub.torn);
}

/* ---- topics: the data flow between the components --------------------------------------- */

static const mt_topic_desc_t g_estimate_desc =
    MT_TOPIC_DESC("estimate", veh_estimate_msg_t, 1u, 0u);
static const mt_topic_desc_t g_att_sp_desc = MT_TOPIC_DESC("att_sp", veh_att_sp_msg_t, 1u, 0u);
static const mt_topic_desc_t g_actuator_desc =
    MT_TOPIC_DESC("actuator", veh_actuator_msg_t, 1u, 0u);

/* One topic with a first, all-zero message (the state before the first sample), so a
 * subscriber's newest message always exists (veh_latest). */
static mt_status_t topic_start(mt_topic_t *t, const mt_topic_desc_t *d, void *store, uint32_t bytes)
{
    static const uint8_t zero[MT_CFG_BUS_MAX_MSG];
    mt_status_t st = mt_topic_init(t, d, store, bytes);

    if (st == MT_OK) {
        st = mt_topic_publish(t, zero, d->msg_size);
    }
    return st;
}

/* Publishers:  estimate  ins.c, gps.c, baro.c (the estimator's stages, main loop)
 *              att_sp    posctl.c
 *              actuator  attctl.c
 *              battery   battery.c (work queue; created by veh_battery_init)
 * Subscribers, all in the main loop, one subscription each: */
static mt_status_t topics_init(veh_t *v)
{
    mt_status_t st = topic_start(&v->estimate, &g_estimate_desc, v->estimate_store,
                                 (uint32_t)sizeof(v->estimate_store));
    if (st == MT_OK) {
        st = topic_start(&v->att_sp, &g_att_sp_desc, v->att_sp_store,
                         (uint32_t)sizeof(v->att_sp_store));
    }
    if (st == MT_OK) {
        st = topic_start(&v->actuator, &g_actuator_desc, v->actuator_store,
                         (uint32_t)sizeof(v->actuator_store));
    }
    if (st != MT_OK) {
        return st;
    }
    mt_sub_init(&v->ins.est, &v->estimate, 0u);
    mt_sub_init(&v->gps.est, &v->estimate, 0u);
    mt_sub_init(&v->baro.est, &v->estimate, 0u);
    mt_sub_init(&v->att.est, &v->estimate, 0u);
    mt_sub_init(&v->att.sp, &v->att_sp, 0u);
    mt_sub_init(&v->mot.act, &v->actuator, 0u);
    mt_sub_init(&v->fl.est_sub, &v->estimate, 0u);
    mt_sub_init(&v->au.est_sub, &v->estimate, 0u);
    mt_sub_init(&v->gcs.est_sub, &v->estimate, 0u);
    mt_sub_init(&v->house.est_sub, &v->estimate, 0u);
    mt_sub_init(&v->lg.est_sub, &v->estimate, 0u);
    mt_sub_init(&v->lg.sp_sub, &v->att_sp, 0u);
    return MT_OK;
}

mt_status_t veh_init(const veh_platform_t *plat, const veh_home_t *home,
                     const mt_mission_cmd_t *cmds, uint16_t n, uint32_t *bad)
{
    veh_t *v = &g_veh;
    mt_status_t st;

    memset(v, 0, sizeof(*v));
    v->plat = plat;
    v->home = *home;
    veh_params_default(&v->par);
    v->fl.speed_xy = v->par.wpnav_speed_cms * 0.01f;
    v->fl.yaw_rate = 60.0f * VM_DEG2RAD;
    veh_console_init(plat);
    veh_link_init();
    mt_sem_init(&v->bus.sem, true);
    (void)veh_baro_link_init(&v->baro_link);
    veh_log_init(v);
    veh_auto_init(v);
    mt_proc_set_init(&v->timer_procs);
    mt_proc_set_init(&v->io_procs);
    st = topics_init(v);
    if (st != MT_OK) {
        return st;
    }

    st = mt_sched_init(&v->sched, g_tasks, VT_COUNT, VEH_LOOP_HZ, bad);
    if (st != MT_OK) {
        return st;
    }
    /* the work queue exists before its timer proc is registered */
    st = veh_battery_init(v);
    if (st != MT_OK) {
        return st;
    }
    mt_sub_init(&v->house.battery_sub, &v->battery_topic, 0u);
    if ((mt_proc_register(&v->timer_procs, veh_baro_timer_proc, v) != MT_OK) ||
        (mt_proc_register(&v->timer_procs, mt_wq_timer_proc, &v->wq) != MT_OK) ||
        (mt_proc_register(&v->io_procs, veh_log_io_proc, v) != MT_OK)) {
        return MT_E_FULL;
    }
    v->mission_st = MT_E_EMPTY;
    if ((cmds != NULL) && (n > 0u)) {
        uint16_t b = MT_MISSION_NONE;
        v->mission_st = mt_mission_load(&v->mission, cmds, n, &b);
        v->mission_bad = b;
        if (v->mission_st != MT_OK) {
            *bad = b;
            return v->mission_st;
        }
        v->mission_ok = n >= 2u;
        if (!v->mission_ok) {
            v->mission_st = MT_E_EMPTY;
        }
    }
    return MT_OK;
}

void veh_loop_once(mt_sample_wait_fn_t wait, void *ctx)
{
    mt_sched_loop_once(&g_veh.sched, wait, ctx);
}

mt_proc_set_t *veh_timer_procs(void)
{
    return &g_veh.timer_procs;
}

mt_proc_set_t *veh_io_procs(void)
{
    return &g_veh.io_procs;
}

mt_wq_t *veh_work_queue(void)
{
    return &g_veh.wq;
}

const char *veh_work_item_name(uint32_t slot)
{
    const mt_work_t *w = &g_veh.battery_work;
    return ((w->wq == &g_veh.wq) && (w->slot == slot)) ? "battery" : "unknown";
}

void veh_timer_spec(uint32_t *period_us, uint32_t *cost_min_us, uint32_t *cost_max_us)
{
    *period_us = VEH_TIMER_PERIOD_US;
    *cost_min_us = VEH_TIMER_COST_MIN;
    *cost_max_us = VEH_TIMER_COST_MAX;
}

const mt_sched_t *veh_sched(void)
{
    return &g_veh.sched;
}

void veh_task_cost(uint32_t i, uint32_t *cost_min_us, uint32_t *cost_max_us)
{
    *cost_min_us = (i < VT_COUNT) ? g_cost[i].min_us : 0u;
    *cost_max_us = (i < VT_COUNT) ? g_cost[i].max_us : 0u;
}

const veh_counters_t *veh_counters(void)
{
    veh_t *v = &g_veh;
    v->c.baro_sent = v->baro_link.published;
    v->c.baro_dropped = veh_baro_link_lost(&v->baro_link) + v->baro_link.refused;
    v->c.baro_bus_fail = v->baro_bus_fail;
    v->c.bus_transfers = v->bus.transfers;
    v->c.bus_waits = v->bus.waits;
    v->c.bus_timeouts = v->bus.timeouts;
    return &v->c;
}

void veh_note_crash(float speed_mps)
{
    veh_t *v = &g_veh;
    char b[16];

    if (!v->crashed) {
        v->crashed = true;
        veh_say("vehicle: CRASH: touchdown at %s m/s", vp_float(b, sizeof(b), speed_mps, 1u));
        veh_disarm(v, "crash");
    }
}

veh_phase_t veh_phase(void)
{
    const veh_t *v = &g_veh;

    if (v->crashed) {
        return VEH_PHASE_CRASHED;
    }
    if (v->fl.armed) {
        return VEH_PHASE_FLYING;
    }
    if (v->c.armed_us == 0u) {
        return VEH_PHASE_BOOT;
    }
    if (v->c.completions > 0u) {
        return VEH_PHASE_DONE;
    }
    if ((v->fl.mode == VEH_MODE_AUTO) && (v->mission.state == MT_MISSION_RUNNING)) {
        return VEH_PHASE_FLYING; /* landed by a LAND command; the mission goes on */
    }
    return VEH_PHASE_ABORTED;
}

const char *veh_incomplete_reason(void)
{
    static char why[96];
    const veh_t *v = &g_veh;

    if (v->c.completions > 0u) {
        return "";
    }
    if (!v->mission_ok) {
        (void)vp_snprintf(why, sizeof(why), "no mission (%s)", mt_status_str(v->mission_st));
    } else if (v->c.armed_us == 0u) {
        (void)vp_snprintf(why, sizeof(why), "never armed%s%s",
                          (v->gcs.refuse_reason[0] != '\0') ? ": " : "", v->gcs.refuse_reason);
    } else if (v->crashed) {
        (void)vp_snprintf(why, sizeof(why), "crashed");
    } else if (v->mission.state == MT_MISSION_STOPPED) {
        (void)vp_snprintf(why, sizeof(why), "mission stopped at #%u", v->mission.nav);
    } else {
        (void)vp_snprintf(why, sizeof(why), "mission still running at #%u %s", v->mission.nav,
                          (v->mission.nav < v->mission.total)
                              ? veh_cmd_name(v->mission.cmd[v->mission.nav].id)
                              : "");
    }
    return why;
}

/* ---- summary -------------------------------------------------------------------------------- */

void veh_summary(const char *stop_reason)
{
    veh_t *v = &g_veh;
    const veh_counters_t *c = veh_counters();
    mt_loop_report_t lr;
    uint64_t busy = 0u;
    uint64_t overruns = 0u;
    uint64_t slips = 0u;
    uint64_t skips = 0u;
    uint64_t nach = 0u;
    uint32_t i;
    char a[24];
    char b[24];
    char d[24];

    mt_sched_loop_report(&v->sched, &lr);
    veh_printf("== flight summary ==\n");
    veh_printf("run ended: %s\n", stop_reason);
    if (c->completions > 0u) {
        veh_printf("mission: COMPLETE (%u commands started, %u nav commands completed)\n",
                   (unsigned)c->cmds_started, (unsigned)c->wps_reached);
    } else {
        veh_printf("mission: NOT COMPLETE: %s (%u commands started, %u nav commands "
                   "completed)\n",
                   veh_incomplete_reason(), (unsigned)c->cmds_started, (unsigned)c->wps_reached);
    }
    if (c->armed_us != 0u) {
        uint64_t end = (c->disarmed_us != 0u) ? c->disarmed_us : mt_port_now_us();
        veh_printf("flight time: %s s (armed at %s s, %s at %s s)\n",
                   vp_fix(a, sizeof(a), (int64_t)(end - c->armed_us), 1000000, 1u),
                   vp_fix(b, sizeof(b), (int64_t)(c->armed_us - veh_boot_us()), 1000000, 1u),
                   (c->disarmed_us != 0u) ? "disarmed" : "still armed",
                   vp_fix(d, sizeof(d), (int64_t)(end - veh_boot_us()), 1000000, 1u));
    } else {
        veh_printf("flight time: 0.0 s (never armed)\n");
    }
    veh_printf("scheduler: loop %u Hz, %u tasks, %llu ticks\n", (unsigned)v->sched.loop_rate_hz,
               (unsigned)v->sched.ntasks, (unsigned long long)lr.ticks);
    veh_printf("%-15s %7s %6s %8s %8s %6s %6s %7s %7s %6s %6s %7s\n", "task", "rate_hz", "budget",
               "runs", "expect", "min_us", "max_us", "mean_us", "overrun", "slips", "skips",
               "pending");
    for (i = 0u; i < v->sched.ntasks; i++) {
        mt_task_report_t r;
        const mt_task_t *t = &v->sched.tasks[i];
        char rate[16];
        mt_sched_task_report(&v->sched, i, &r);
        if (t->rate_mhz == 0u) {
            (void)vp_snprintf(rate, sizeof(rate), "fast");
        } else {
            (void)vp_fix(rate, sizeof(rate), (int64_t)t->rate_mhz, 1000, 0u);
        }
        veh_printf("%-15s %7s %6u %8llu %8llu %6u %6u %7u %7u %6llu %6llu %7llu\n", r.name, rate,
                   (unsigned)t->budget_us, (unsigned long long)r.runs,
                   (unsigned long long)(lr.ticks / r.interval), (unsigned)r.min_us,
                   (unsigned)r.max_us, (unsigned)r.mean_us, (unsigned)r.overruns,
                   (unsigned long long)r.slips, (unsigned long long)r.budget_skips,
                   (unsigned long long)r.pending);
        busy += r.runs * (uint64_t)r.mean_us;
        overruns += r.overruns;
        slips += r.slips;
        skips += r.budget_skips;
        nach += r.not_achieved;
    }
    veh_printf("loop: %llu ticks, mean %u us (min %u, max %u), long loops %u, extra %u us\n",
               (unsigned long long)lr.ticks, (unsigned)lr.mean_us, (unsigned)lr.min_us,
               (unsigned)lr.max_us, (unsigned)lr.long_loops, (unsigned)lr.extra_us);
    veh_printf("load average: %s%% (last 32 loops), %s%% over the run\n",
               vp_fix(a, sizeof(a), (int64_t)lr.load_permille, 10, 1u),
               vp_fix(b, sizeof(b),
                      (lr.ticks == 0u)
                          ? 0
                          : (int64_t)((busy * 1000u) / (lr.ticks * (uint64_t)v->sched.period_us)),
                      10, 1u));
    veh_printf("overruns: %llu, slips: %llu, budget skips: %llu, not achieved: %llu\n",
               (unsigned long long)overruns, (unsigned long long)slips, (unsigned long long)skips,
               (unsigned long long)nach);
    veh_printf("timer procs: %llu dispatches, %u periods missed; barometer: %llu samples "
               "published, %llu taken, %u dropped, %u queued, %u failed reads\n",
               (unsigned long long)v->timer_procs.dispatches,
               (unsigned)v->timer_procs.periods_missed, (unsigned long long)c->baro_sent,
               (unsigned long long)c->baro_received, (unsigned)c->baro_dropped,
               (unsigned)mt_oring_available(&v->baro_link.ring), (unsigned)c->baro_bus_fail);
    veh_printf("bus: %llu transactions, %u waited for the bus, %u timeouts\n",
               (unsigned long long)c->bus_transfers, (unsigned)c->bus_waits,
               (unsigned)c->bus_timeouts);
    veh_printf("log: %llu records, %llu bytes to the sink, %u dropped, ring peak %u of %u "
               "bytes; io procs: %llu dispatches\n",
               (unsigned long long)c->log_records, (unsigned long long)c->log_bytes,
               (unsigned)c->log_dropped, (unsigned)c->log_max_fill, (unsigned)sizeof(v->log_store),
               (unsigned long long)v->io_procs.dispatches);
    veh_printf("link (MAVLink 2): %llu messages, %llu bytes sent, %u not sent (ring full), %u "
               "console lines lost; %u messages received, %u ignored, %u frames dropped, %u "
               "unsigned, %llu "
               "bytes not in a valid frame, %u parameter requests unknown, %u sets refused, %u "
               "commands unsupported\n",
               (unsigned long long)c->telem_packets, (unsigned long long)c->telem_bytes,
               (unsigned)c->telem_full, (unsigned)c->said_lost, (unsigned)c->link_rx_msgs,
               (unsigned)c->link_rx_ignored, (unsigned)c->link_rx_errors,
               (unsigned)c->link_rx_unsigned,
               (unsigned long long)(c->link_rx_bytes - c->link_rx_frame_bytes),
               (unsigned)c->link_param_unknown, (unsigned)c->link_param_refused,
               (unsigned)c->link_cmd_unsupported);
    veh_summary_battery(v);
}
