/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file house.c
 * @brief housekeeping (3 Hz): the battery readings the battery monitor (a
 *        work item, battery.c) publishes on the `battery` topic, and the
 *        health warnings (the GPS's from the `estimate` topic); status_line
 *        (1 Hz): one console line.
 */
#include "veh_int.h"

#define BAT_LOW_V 13.6f

/* One battery reading into the state and the log. */
static void battery_take(veh_t *v, const veh_battery_msg_t *m)
{
    veh_house_t *s = &v->house;

    s->bat_volt = (float)m->mv * 0.001f;
    s->bat_amp = (float)m->ca * 0.01f;
    s->bat_ok = s->bat_volt > BAT_LOW_V;
    if (!s->bat_ok && v->fl.armed && !s->bat_low_said) {
        s->bat_low_said = true;
        veh_say("vehicle: battery low (%s V)", vp_float((char[16]){0}, 16u, s->bat_volt, 2u));
    }
    s->bat_last_us = m->t_us;
    if (v->fl.armed) {
        uint8_t rec[12];
        uint64_t t = veh_now(); /* log records carry the time they are written */
        uint32_t i;
        for (i = 0u; i < 8u; i++) {
            rec[i] = (uint8_t)(t >> (8u * i));
        }
        rec[8] = (uint8_t)m->mv;
        rec[9] = (uint8_t)(m->mv >> 8);
        rec[10] = (uint8_t)m->ca;
        rec[11] = (uint8_t)(m->ca >> 8);
        veh_log_record(v, VEH_LOG_BATT, rec, 12u);
    }
}

bool veh_battery_ok(const veh_t *v)
{
    return v->house.bat_ok;
}

float veh_battery_volts(const veh_t *v)
{
    return v->house.bat_volt;
}

float veh_battery_amps(const veh_t *v)
{
    return v->house.bat_amp;
}

void veh_housekeeping(veh_t *v)
{
    veh_house_t *s = &v->house;
    bool armed = v->fl.armed;
    veh_estimate_msg_t est;
    veh_battery_msg_t m;
    mt_status_t st;

    /* every reading published since the last run, oldest first (a reading that
     * left the queue first is counted in the subscription's `missed`) */
    for (;;) {
        st = mt_sub_copy_next(&s->battery_sub, &m, (uint32_t)sizeof(m), veh_now());
        if ((st != MT_OK) && (st != MT_W_BUS_MISSED)) {
            break; /* MT_E_EMPTY: nothing new; MT_E_BUS_TORN: counted, next run */
        }
        battery_take(v, &m);
    }
    /* battery health: readings arrive at 3 Hz */
    if (armed && s->bat_ok && ((veh_now() - s->bat_last_us) > 1000000u) && !s->bat_stale_said) {
        s->bat_stale_said = true;
        veh_say("vehicle: battery readings stopped");
    }
    /* GPS health: fixes arrive at 5 Hz */
    veh_latest(&s->est_sub, &est, (uint32_t)sizeof(est));
    if (armed && est.pos_ok && ((veh_now() - est.gps_last_us) > 1000000u)) {
        veh_say("vehicle: GPS fixes stopped");
    }
}

void veh_status_line(veh_t *v)
{
    const veh_flight_t *s = &v->fl;
    veh_estimate_msg_t est;
    char alt[16];
    char dist[16];
    char gs[16];
    char bat[16];
    char load[16];
    char nav[8];

    v->house.status_runs++;
    if (!v->plat->status_lines) {
        return;
    }
    veh_latest(&v->house.est_sub, &est, (uint32_t)sizeof(est));
    (void)vp_float(alt, sizeof(alt), -est.pos[2], 1u);
    (void)vp_float(dist, sizeof(dist),
                   (s->nav.kind != VEH_NAV_NONE) ? veh_dist_xy(est.pos, s->nav.dest) : 0.0f, 1u);
    (void)vp_float(gs, sizeof(gs), vm_norm2(est.vel[0], est.vel[1]), 1u);
    (void)vp_float(bat, sizeof(bat), v->house.bat_volt, 2u);
    (void)vp_fix(load, sizeof(load), (int64_t)mt_sched_load_permille(&v->sched), 10, 1u);
    if (v->mission.nav == MT_MISSION_NONE) {
        (void)vp_snprintf(nav, sizeof(nav), "-");
    } else {
        (void)vp_snprintf(nav, sizeof(nav), "#%u", (unsigned)v->mission.nav);
    }
    veh_say("status: %s %s nav %s alt %s m dist %s m gs %s m/s bat %s V load %s%%",
            veh_mode_name(s->mode), s->armed ? "armed" : "disarmed", nav, alt, dist, gs, bat, load);
}
