/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file gcs.c
 * @brief gcs_update (400 Hz): ground-station commands (arm and fly AUTO, stop,
 *        resume, land) with the pre-arm checks, then the MAVLink link's receive
 *        side; telemetry_send (10 Hz): the link's telemetry streams (link.c).
 *        The estimate (and the sensors' health in it) comes from the
 *        `estimate` topic; arming and modes go through posctl.c.
 */
#include <string.h>

#include "veh_int.h"

#define GPS_FIXES_TO_ARM 5u

/* Why the vehicle may not arm, or NULL. */
static const char *prearm_failure(veh_t *v)
{
    veh_estimate_msg_t est;
    const veh_estimate_msg_t *s = &est;

    veh_latest(&v->gcs.est_sub, &est, (uint32_t)sizeof(est));
    if (!v->mission_ok) {
        return "no valid mission loaded";
    }
    if (!s->baro_ok) {
        return "barometer not calibrated";
    }
    if (!s->pos_ok || (s->gps_fixes < GPS_FIXES_TO_ARM)) {
        return "waiting for GPS";
    }
    if (!veh_battery_ok(v)) {
        return "battery monitor not read";
    }
    return NULL;
}

static void arm_auto(veh_t *v)
{
    veh_gcs_t *s = &v->gcs;
    const char *why;

    if (v->fl.armed) {
        return;
    }
    why = prearm_failure(v);
    if (why != NULL) {
        if (!s->arm_refused_said || (strcmp(why, s->refuse_reason) != 0)) {
            veh_say("vehicle: arming refused: %s", why);
            (void)vp_snprintf(s->refuse_reason, sizeof(s->refuse_reason), "%s", why);
            s->arm_refused_said = true;
        }
        return;
    }
    s->refuse_reason[0] = '\0';
    (void)veh_arm(v);
    veh_set_mode(v, VEH_MODE_AUTO);
    if (!veh_auto_start(v)) {
        veh_disarm(v, "mission start refused");
        veh_set_mode(v, VEH_MODE_STANDBY);
    }
}

void veh_gcs_update(veh_t *v)
{
    const veh_flight_t *s = &v->fl;
    veh_gcs_cmd_t cmd = v->plat->gcs_poll(v->plat->ctx);

    switch (cmd) {
    case VEH_GCS_ARM_AUTO: arm_auto(v); break;
    case VEH_GCS_STOP:
        if ((s->mode == VEH_MODE_AUTO) && (mt_mission_stop(&v->mission) == MT_OK)) {
            veh_say("gcs: mission stopped at #%u, holding position", v->mission.nav);
            veh_set_mode(v, VEH_MODE_HOLD);
        } else {
            veh_say("gcs: stop refused (mode %s)", veh_mode_name(s->mode));
        }
        break;
    case VEH_GCS_RESUME:
        if ((s->mode == VEH_MODE_HOLD) && s->armed) {
            veh_set_mode(v, VEH_MODE_AUTO);
            if (mt_mission_resume(&v->mission) == MT_OK) {
                veh_say("gcs: mission resumed");
            } else {
                veh_say("gcs: resume refused by the mission");
                veh_set_mode(v, VEH_MODE_HOLD);
            }
        } else {
            veh_say("gcs: resume refused (mode %s)", veh_mode_name(s->mode));
        }
        break;
    case VEH_GCS_LAND:
        if (s->armed) {
            (void)mt_mission_stop(&v->mission);
            veh_say("gcs: land");
            veh_set_mode(v, VEH_MODE_LAND);
        }
        break;
    case VEH_GCS_NONE:
    default: break;
    }
    veh_link_receive(v);
}

void veh_telemetry_send(veh_t *v)
{
    veh_link_stream(v);
}
