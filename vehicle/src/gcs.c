/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file gcs.c
 * @brief gcs_update (400 Hz): the deployment's ground-station events (arm and
 *        fly AUTO, stop, resume, land) with the pre-arm checks, then the MAVLink
 *        link's receive side and the command it decoded (arm/disarm, modes,
 *        mission start, RTL, land, set current, takeoff), and the link-loss watch;
 *        telemetry_send (10 Hz): the link's telemetry streams (link.c).
 *        The estimate (and the sensors' health in it) comes from the
 *        `estimate` topic; arming and modes go through posctl.c.
 */
#include <math.h>
#include <string.h>

#include "veh_int.h"

#define GPS_FIXES_TO_ARM 5u

/* Why the vehicle may not arm, or NULL (need_mission: arming to fly AUTO at once). */
static const char *prearm_failure(veh_t *v, bool need_mission)
{
    veh_estimate_msg_t est;
    const veh_estimate_msg_t *s = &est;

    veh_latest(&v->gcs.est_sub, &est, (uint32_t)sizeof(est));
    if (need_mission && !v->mission_ok) {
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
    why = prearm_failure(v, true);
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

/* ---- MAVLink commands (link.c decodes and acknowledges them) ---------------------------- */

/* A running mission stops before another mode takes over (it can be resumed). */
static void leave_auto(veh_t *v)
{
    if ((v->fl.mode == VEH_MODE_AUTO) && (v->mission.state == MT_MISSION_RUNNING)) {
        (void)mt_mission_stop(&v->mission);
    }
}

static veh_cmd_result_t refuse(const char *what, const char *why)
{
    veh_say("gcs: %s refused: %s", what, why);
    return VEH_CMD_FAILED;
}

static veh_cmd_result_t cmd_arm(veh_t *v, const veh_command_t *c)
{
    veh_flight_t *s = &v->fl;

    if (c->p[0] == 1.0f) {
        const char *why = prearm_failure(v, false);
        if (s->armed) {
            return VEH_CMD_DONE;
        }
        if (why != NULL) {
            veh_say("vehicle: arming refused: %s", why);
            return VEH_CMD_FAILED;
        }
        (void)veh_arm(v);
        return VEH_CMD_DONE;
    }
    if (c->p[0] != 0.0f) {
        return refuse("arm", "param1 is neither 0 nor 1");
    }
    if (!s->armed) {
        return VEH_CMD_DONE;
    }
    if (s->flying && (c->p[1] != 21196.0f)) {
        return refuse("disarm", "flying (param2 21196 forces it)");
    }
    leave_auto(v);
    veh_disarm(v, "ground station");
    veh_set_mode(v, VEH_MODE_STANDBY);
    return VEH_CMD_DONE;
}

/* AUTO: resume a stopped mission, else start it from its first command. */
static veh_cmd_result_t cmd_auto(veh_t *v, bool restart)
{
    if (!v->fl.armed) {
        return refuse("AUTO", "arm first");
    }
    if (!v->mission_ok) {
        return refuse("AUTO", "no valid mission loaded");
    }
    if (!restart && (v->mission.state == MT_MISSION_STOPPED) &&
        (v->mission.nav != MT_MISSION_NONE)) {
        veh_set_mode(v, VEH_MODE_AUTO);
        if (mt_mission_resume(&v->mission) == MT_OK) {
            veh_say("gcs: mission resumed");
            return VEH_CMD_DONE;
        }
    }
    veh_set_mode(v, VEH_MODE_AUTO);
    if (!veh_auto_start(v)) {
        veh_set_mode(v, VEH_MODE_HOLD);
        return refuse("AUTO", "the mission did not start");
    }
    return VEH_CMD_DONE;
}

static veh_cmd_result_t cmd_mode(veh_t *v, veh_mode_t m)
{
    veh_flight_t *s = &v->fl;

    if (m == s->mode) {
        return VEH_CMD_DONE;
    }
    if (m == VEH_MODE_STANDBY) {
        if (s->armed) {
            return refuse("STABILIZE", "armed (disarm first)");
        }
        veh_set_mode(v, m);
        return VEH_CMD_DONE;
    }
    if (m == VEH_MODE_AUTO) {
        return cmd_auto(v, false);
    }
    if (m == VEH_MODE_GUIDED) {
        /* as ArduCopter: also on the ground, disarmed (a ground station's takeoff sets GUIDED,
         * then arms, then sends NAV_TAKEOFF); it needs a position */
        veh_estimate_msg_t est;
        veh_latest(&v->gcs.est_sub, &est, (uint32_t)sizeof(est));
        if (!est.pos_ok) {
            return refuse("GUIDED", "no position estimate");
        }
        leave_auto(v);
        veh_set_mode(v, m);
        return VEH_CMD_DONE;
    }
    if (!s->armed) {
        return refuse(veh_mode_name(m), "arm first");
    }
    if ((m == VEH_MODE_RTL) && !s->flying) {
        return refuse("RTL", "not flying");
    }
    leave_auto(v);
    veh_set_mode(v, m);
    return VEH_CMD_DONE;
}

/* NAV_TAKEOFF, as ArduCopter's user takeoff: armed, on the ground, in a mode that holds a
 * position (GUIDED, LOITER), to an altitude above the vehicle's (param7, m above home). */
static veh_cmd_result_t cmd_takeoff(veh_t *v, const veh_command_t *c)
{
    const veh_flight_t *s = &v->fl;
    veh_estimate_msg_t est;

    if (!s->armed) {
        return refuse("takeoff", "arm first");
    }
    if (s->flying) {
        return refuse("takeoff", "already flying");
    }
    if ((s->mode != VEH_MODE_GUIDED) && (s->mode != VEH_MODE_HOLD)) {
        return refuse("takeoff", "only in GUIDED or LOITER");
    }
    veh_latest(&v->gcs.est_sub, &est, (uint32_t)sizeof(est));
    if (!isfinite(c->alt) || (c->alt <= -est.pos[2])) {
        return refuse("takeoff", "the altitude is not above the vehicle");
    }
    veh_user_takeoff(v, c->alt);
    veh_say("gcs: takeoff to %s m", vp_float((char[16]){0}, 16u, c->alt, 1u));
    return VEH_CMD_DONE;
}

static veh_cmd_result_t command_run(veh_t *v, const veh_command_t *c)
{
    mt_status_t st;

    switch (c->kind) {
    case VEH_CMD_ARM: return cmd_arm(v, c);
    case VEH_CMD_MODE: return cmd_mode(v, (veh_mode_t)c->custom_mode);
    case VEH_CMD_MISSION_START: return cmd_auto(v, true);
    case VEH_CMD_RTL: return cmd_mode(v, VEH_MODE_RTL);
    case VEH_CMD_LAND: return cmd_mode(v, VEH_MODE_LAND);
    case VEH_CMD_TAKEOFF: return cmd_takeoff(v, c);
    case VEH_CMD_SET_CURRENT:
    default:
        if (!isfinite(c->p[0]) || (c->p[0] < 0.0f) || (c->p[0] > 65535.0f)) {
            return refuse("set current", "not a mission index");
        }
        st = mt_mission_set_current(&v->mission, (uint16_t)c->p[0]);
        if (st != MT_OK) {
            return refuse("set current", mt_status_str(st));
        }
        veh_say("gcs: mission current item set to #%u", (unsigned)c->p[0]);
        return VEH_CMD_DONE;
    }
}

/* Link loss: no ground-station heartbeat for FS_GCS_TIMEOUT while flying takes the
 * FS_GCS_ENABLE action once; the link's return is said. */
static void link_watch(veh_t *v)
{
    veh_gcs_t *g = &v->gcs;
    uint64_t last = 0u;
    uint64_t limit = (uint64_t)(v->par.fs_gcs_timeout_s * 1.0e6f);

    if (!veh_link_gcs_seen(&last)) {
        return;
    }
    if ((veh_now() - last) <= limit) {
        if (g->link_lost) {
            g->link_lost = false;
            veh_say("failsafe: ground station link back (mode %s)", veh_mode_name(v->fl.mode));
        }
        return;
    }
    if (g->link_lost || !v->fl.armed || !v->fl.flying) {
        return;
    }
    g->link_lost = true;
    if (v->par.fs_gcs_enable == VEH_FS_GCS_RTL) {
        veh_say("failsafe: ground station link lost: RTL");
        leave_auto(v);
        veh_set_mode(v, VEH_MODE_RTL);
    } else if (v->par.fs_gcs_enable == VEH_FS_GCS_LAND) {
        veh_say("failsafe: ground station link lost: LAND");
        leave_auto(v);
        veh_set_mode(v, VEH_MODE_LAND);
    } else {
        veh_say("failsafe: ground station link lost: continuing (FS_GCS_ENABLE 0)");
    }
}

void veh_gcs_update(veh_t *v)
{
    const veh_flight_t *s = &v->fl;
    veh_gcs_cmd_t cmd = v->plat->gcs_poll(v->plat->ctx);
    veh_command_t c;

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
    if (veh_link_take_command(&c)) {
        veh_link_command_ack(v, &c, command_run(v, &c));
    }
    link_watch(v);
}

void veh_telemetry_send(veh_t *v)
{
    veh_link_stream(v);
}
