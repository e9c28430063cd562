/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file house.c
 * @brief housekeeping (3 Hz): the battery monitor, read over the shared bus
 *        (the barometer driver uses the same bus from the timer thread), and
 *        the health warnings; status_line (1 Hz): one console line.
 */
#include "veh_int.h"

#define BUS_TIMEOUT_US 2000u
#define BAT_LOW_V 13.6f

void veh_housekeeping(veh_t *v)
{
    veh_state_t *s = &v->s;
    uint8_t rx[4];

    if (veh_bus_read(&v->bus, v->plat, VEH_DEV_BATT, 0u, rx, 4u, BUS_TIMEOUT_US)) {
        uint32_t w = ((uint32_t)rx[0] << 24) | ((uint32_t)rx[1] << 16) | ((uint32_t)rx[2] << 8) |
                     (uint32_t)rx[3];
        s->bat_volt = (float)(w >> 16) * 0.001f;
        s->bat_amp = (float)(w & 0xFFFFu) * 0.01f;
        s->bat_ok = s->bat_volt > BAT_LOW_V;
        if (!s->bat_ok && s->armed && !s->bat_low_said) {
            s->bat_low_said = true;
            veh_say(v, "vehicle: battery low (%s V)",
                    vp_float((char[16]){0}, 16u, s->bat_volt, 2u));
        }
        if (s->armed) {
            uint8_t rec[12];
            uint64_t t = veh_now(v);
            uint32_t mv = (uint32_t)lroundf(s->bat_volt * 1000.0f);
            uint32_t ca = (uint32_t)lroundf(s->bat_amp * 100.0f);
            uint32_t i;
            for (i = 0u; i < 8u; i++) {
                rec[i] = (uint8_t)(t >> (8u * i));
            }
            rec[8] = (uint8_t)mv;
            rec[9] = (uint8_t)(mv >> 8);
            rec[10] = (uint8_t)ca;
            rec[11] = (uint8_t)(ca >> 8);
            veh_log_record(v, VEH_LOG_BATT, rec, 12u);
        }
    }
    /* GPS health: fixes arrive at 5 Hz */
    if (s->armed && s->pos_ok && ((veh_now(v) - s->gps_last_us) > 1000000u)) {
        veh_say(v, "vehicle: GPS fixes stopped");
    }
}

void veh_status_line(veh_t *v)
{
    veh_state_t *s = &v->s;
    char alt[16];
    char dist[16];
    char gs[16];
    char bat[16];
    char load[16];
    char nav[8];

    s->status_runs++;
    if (!v->plat->status_lines) {
        return;
    }
    (void)vp_float(alt, sizeof(alt), -s->pos[2], 1u);
    (void)vp_float(dist, sizeof(dist),
                   (s->nav.kind != VEH_NAV_NONE) ? veh_dist_xy(s->pos, s->nav.dest) : 0.0f, 1u);
    (void)vp_float(gs, sizeof(gs), vm_norm2(s->vel[0], s->vel[1]), 1u);
    (void)vp_float(bat, sizeof(bat), s->bat_volt, 2u);
    (void)vp_fix(load, sizeof(load), (int64_t)mt_sched_load_permille(&v->sched), 10, 1u);
    if (v->mission.nav == MT_MISSION_NONE) {
        (void)vp_snprintf(nav, sizeof(nav), "-");
    } else {
        (void)vp_snprintf(nav, sizeof(nav), "#%u", (unsigned)v->mission.nav);
    }
    veh_say(v, "status: %s %s nav %s alt %s m dist %s m gs %s m/s bat %s V load %s%%",
            veh_mode_name(s->mode), s->armed ? "armed" : "disarmed", nav, alt, dist, gs, bat, load);
}
