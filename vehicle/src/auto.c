/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file auto.c
 * @brief AUTO mode: mission_update (50 Hz) and the mission callbacks
 *        (mt/mission.h: start, verify, complete).
 *
 * Nav commands: TAKEOFF, WAYPOINT and SPLINE_WAYPOINT (flown as a waypoint:
 * reach within param2 metres, default 2, then hold param1 seconds),
 * LOITER_UNLIM (reach, hold forever), LOITER_TURNS (param1 turns of radius
 * |param3| m, default 10, counter-clockwise when param3 < 0), LOITER_TIME
 * (reach, hold param1 s), LAND (at x/y, or here when both are 0), RTL (climb
 * to 15 m or more, return home, land).
 * Do and condition commands: DO_CHANGE_SPEED (param2 m/s), DO_SET_SERVO
 * (param1 channel, param2 PWM), DO_SET_HOME (param1 = 1: here, else x/y/z),
 * DO_LAND_START (a marker), CONDITION_DELAY (param1 s), CONDITION_DISTANCE
 * (until param1 m from the active nav destination), CONDITION_YAW (param1
 * degrees at param2 deg/s, param3 direction -1/0/1, param4 = 1 relative).
 * Any other command is refused by its start callback, which AP_Mission's
 * rules turn into "skipped" (printed, never silent).
 * The callbacks only read the mission object (assumption A1 of the kernel's
 * proofs): they change the vehicle, never the sequencer. They take the newest
 * `estimate` when they start, and fly the vehicle through posctl.c (arming,
 * modes, legs) and the nav command of the flight state.
 */
#include "veh_int.h"

#define MILLI 0.001f
#define WP_RADIUS_DEFAULT 2.0f
#define CIRCLE_RADIUS_DEFAULT 10.0f

static float par(const mt_mission_cmd_t *c, unsigned i)
{
    int32_t p = c->param[i];
    return (p == MT_MISSION_PARAM_NAN) ? 0.0f : ((float)p * MILLI);
}

const char *veh_cmd_name(uint16_t id)
{
    switch (id) {
    case MT_MAV_CMD_WAYPOINT: return "WAYPOINT";
    case MT_MAV_CMD_LOITER_UNLIM: return "LOITER_UNLIM";
    case MT_MAV_CMD_LOITER_TURNS: return "LOITER_TURNS";
    case MT_MAV_CMD_LOITER_TIME: return "LOITER_TIME";
    case MT_MAV_CMD_RETURN_TO_LAUNCH: return "RTL";
    case MT_MAV_CMD_LAND: return "LAND";
    case MT_MAV_CMD_TAKEOFF: return "TAKEOFF";
    case MT_MAV_CMD_SPLINE_WAYPOINT: return "SPLINE_WAYPOINT";
    case MT_MAV_CMD_CONDITION_DELAY: return "CONDITION_DELAY";
    case MT_MAV_CMD_CONDITION_DISTANCE: return "CONDITION_DISTANCE";
    case MT_MAV_CMD_CONDITION_YAW: return "CONDITION_YAW";
    case MT_MAV_CMD_DO_JUMP: return "DO_JUMP";
    case MT_MAV_CMD_DO_CHANGE_SPEED: return "DO_CHANGE_SPEED";
    case MT_MAV_CMD_DO_SET_HOME: return "DO_SET_HOME";
    case MT_MAV_CMD_DO_SET_SERVO: return "DO_SET_SERVO";
    case MT_MAV_CMD_DO_LAND_START: return "DO_LAND_START";
    case MT_MAV_CMD_JUMP_TAG: return "JUMP_TAG";
    case MT_MAV_CMD_DO_JUMP_TAG: return "DO_JUMP_TAG";
    default: return "CMD";
    }
}

/* Location of a mission command in the NED frame (z: relative altitude down). */
static void cmd_location(const veh_t *v, const mt_mission_cmd_t *c, float out[3], bool *has_xy)
{
    const veh_estimate_msg_t *est = &v->au.est;
    float alt = (float)c->z * 0.01f;

    *has_xy = (c->x != 0) || (c->y != 0);
    if (*has_xy) {
        vm_ne_from_ll(v->home.lat, v->home.lon, c->x, c->y, &out[0], &out[1]);
    } else {
        out[0] = est->pos[0];
        out[1] = est->pos[1];
    }
    if ((c->frame == 0u) || (c->frame == 2u) || (c->frame == 5u)) {
        alt -= (float)v->home.alt_cm * 0.01f; /* AMSL (frame 2 too, as ArduPilot reads it) */
    }
    out[2] = -alt;
}

static char *fmt_m(char *buf, float x)
{
    return (char *)vp_float(buf, 16u, x, 1u);
}

/* ---- nav commands ----------------------------------------------------------------------- */

static bool start_nav(veh_t *v, uint16_t index, const mt_mission_cmd_t *c)
{
    veh_flight_t *s = &v->fl;
    const veh_estimate_msg_t *est = &v->au.est;
    veh_navcmd_t *n = &s->nav;
    bool has_xy;
    float loc[3];
    char a[16];
    char b[16];

    n->kind = VEH_NAV_NONE;
    n->index = index;
    n->id = c->id;
    n->phase = 0u;
    n->reached = false;
    n->done = false;
    n->radius = WP_RADIUS_DEFAULT;
    n->hold_s = 0.0f;
    s->yaw_fixed = false; /* CONDITION_YAW holds until the next nav command */
    cmd_location(v, c, loc, &has_xy);

    if (!s->armed && (c->id != MT_MAV_CMD_TAKEOFF)) {
        veh_say("mission: #%u %s skipped: the vehicle has landed (only TAKEOFF re-arms it)", index,
                veh_cmd_name(c->id));
        return false;
    }
    switch (c->id) {
    case MT_MAV_CMD_TAKEOFF:
        if (!s->armed && !veh_arm(v)) {
            return false;
        }
        n->kind = VEH_NAV_TAKEOFF;
        n->dest[0] = est->pos[0];
        n->dest[1] = est->pos[1];
        n->dest[2] = fminf(loc[2], -1.0f);
        veh_leg_start(v, n->dest);
        veh_say("mission: #%u TAKEOFF started, climb to %s m", index, fmt_m(a, -n->dest[2]));
        return true;
    case MT_MAV_CMD_WAYPOINT:
    case MT_MAV_CMD_SPLINE_WAYPOINT:
        n->kind = VEH_NAV_WAYPOINT;
        n->hold_s = par(c, 0);
        if (par(c, 1) > 0.1f) {
            n->radius = par(c, 1);
        }
        break;
    case MT_MAV_CMD_LOITER_TIME:
        n->kind = VEH_NAV_LOITER;
        n->hold_s = par(c, 0);
        break;
    case MT_MAV_CMD_LOITER_UNLIM:
        n->kind = VEH_NAV_LOITER;
        n->hold_s = -1.0f;
        break;
    case MT_MAV_CMD_LOITER_TURNS:
        n->kind = VEH_NAV_CIRCLE;
        n->turns = fmaxf(par(c, 0), 0.0f);
        n->circle_r = fabsf(par(c, 2));
        if (n->circle_r < 1.0f) {
            n->circle_r = CIRCLE_RADIUS_DEFAULT;
        }
        n->circle_dir = (par(c, 2) < 0.0f) ? -1.0f : 1.0f;
        {
            /* approach the circle at its nearest point */
            float dn = est->pos[0] - loc[0];
            float de = est->pos[1] - loc[1];
            float d = vm_norm2(dn, de);
            float edge[3];
            if (d < 0.1f) {
                dn = 1.0f;
                de = 0.0f;
                d = 1.0f;
            }
            edge[0] = loc[0] + ((dn / d) * n->circle_r);
            edge[1] = loc[1] + ((de / d) * n->circle_r);
            edge[2] = loc[2];
            n->dest[0] = loc[0];
            n->dest[1] = loc[1];
            n->dest[2] = loc[2];
            veh_leg_start(v, edge);
        }
        veh_say("mission: #%u LOITER_TURNS started, %s turns of %s m", index, fmt_m(a, n->turns),
                fmt_m(b, n->circle_r));
        return true;
    case MT_MAV_CMD_LAND:
        n->kind = VEH_NAV_LAND;
        n->dest[0] = loc[0];
        n->dest[1] = loc[1];
        n->dest[2] = est->pos[2]; /* reach x/y at the current altitude, then descend */
        s->landed_ticks = 0u;
        veh_leg_start(v, n->dest);
        veh_say("mission: #%u LAND started, %s m away", index,
                fmt_m(a, veh_dist_xy(est->pos, n->dest)));
        return true;
    case MT_MAV_CMD_RETURN_TO_LAUNCH: {
        float up[3];
        n->kind = VEH_NAV_RTL;
        s->rtl_alt = fmaxf(VEH_RTL_ALT_MIN, -est->pos[2]);
        up[0] = est->pos[0];
        up[1] = est->pos[1];
        up[2] = -s->rtl_alt;
        n->dest[0] = 0.0f;
        n->dest[1] = 0.0f;
        n->dest[2] = 0.0f;
        s->landed_ticks = 0u;
        veh_leg_start(v, up);
        veh_say("mission: #%u RTL started, return at %s m, %s m from home", index,
                fmt_m(a, s->rtl_alt), fmt_m(b, vm_norm2(est->pos[0], est->pos[1])));
        return true;
    }
    default:
        veh_say("mission: #%u %s (%u) not supported by this vehicle: skipped", index,
                veh_cmd_name(c->id), c->id);
        return false;
    }
    /* waypoint and loiter: fly to the location */
    n->dest[0] = loc[0];
    n->dest[1] = loc[1];
    n->dest[2] = loc[2];
    veh_leg_start(v, n->dest);
    veh_say("mission: #%u %s started, %s m away at %s m", index, veh_cmd_name(c->id),
            fmt_m(a, veh_dist3(est->pos, n->dest)), fmt_m(b, -n->dest[2]));
    return true;
}

/* ---- do and condition commands ---------------------------------------------------------- */

static bool start_do(veh_t *v, uint16_t index, const mt_mission_cmd_t *c)
{
    veh_flight_t *s = &v->fl;
    veh_docmd_t *d = &v->au.doc;
    char a[16];

    d->index = index;
    d->id = c->id;
    d->start_us = veh_now();
    d->active = true;
    d->value = 0.0f;
    switch (c->id) {
    case MT_MAV_CMD_DO_CHANGE_SPEED:
        if (par(c, 1) > 0.0f) {
            s->speed_xy = vm_clamp(par(c, 1), 0.5f, 15.0f);
        }
        veh_say("mission: #%u DO_CHANGE_SPEED started, speed %s m/s", index, fmt_m(a, s->speed_xy));
        break;
    case MT_MAV_CMD_DO_SET_SERVO: {
        int32_t ch = c->param[0] / MT_MISSION_MILLI;
        int32_t pwm = c->param[1] / MT_MISSION_MILLI;
        if ((ch < 1) || (ch > 16) || (pwm < 0) || (pwm > 3000)) {
            veh_say("mission: #%u DO_SET_SERVO refused: channel %d pwm %d", index, (int)ch,
                    (int)pwm);
            return false;
        }
        v->plat->servo_write(v->plat->ctx, (uint8_t)ch, (uint16_t)pwm);
        veh_say("mission: #%u DO_SET_SERVO started, servo %d -> %d", index, (int)ch, (int)pwm);
        break;
    }
    case MT_MAV_CMD_DO_SET_HOME:
        if (c->param[0] == MT_MISSION_MILLI) {
            veh_say("mission: #%u DO_SET_HOME started, home stays at the launch point "
                    "(local frame)",
                    index);
        } else {
            veh_say("mission: #%u DO_SET_HOME started, home kept (moving home in flight is "
                    "not supported)",
                    index);
        }
        break;
    case MT_MAV_CMD_DO_LAND_START:
        veh_say("mission: #%u DO_LAND_START (landing sequence marker)", index);
        break;
    case MT_MAV_CMD_CONDITION_DELAY:
        d->value = par(c, 0);
        veh_say("mission: #%u CONDITION_DELAY started, %s s", index, fmt_m(a, d->value));
        break;
    case MT_MAV_CMD_CONDITION_DISTANCE:
        d->value = par(c, 0);
        veh_say("mission: #%u CONDITION_DISTANCE started, until %s m from the destination", index,
                fmt_m(a, d->value));
        break;
    case MT_MAV_CMD_CONDITION_YAW: {
        float target = par(c, 0) * VM_DEG2RAD;
        float rate = par(c, 1);
        float dir = par(c, 2);
        if (par(c, 3) > 0.5f) {
            /* relative: the direction gives the sign */
            target = s->yaw_cmd + ((dir < 0.0f) ? -target : target);
        }
        s->yaw_goal = vm_wrap_2pi(target);
        s->yaw_rate = (rate > 1.0f) ? (rate * VM_DEG2RAD) : (60.0f * VM_DEG2RAD);
        s->yaw_fixed = true;
        d->value = s->yaw_goal;
        veh_say("mission: #%u CONDITION_YAW started, heading %s deg", index,
                fmt_m(a, s->yaw_goal * VM_RAD2DEG));
        break;
    }
    default:
        d->active = false;
        veh_say("mission: #%u %s (%u) not supported by this vehicle: skipped", index,
                veh_cmd_name(c->id), c->id);
        return false;
    }
    return true;
}

static bool verify_do(veh_t *v, const mt_mission_cmd_t *c)
{
    const veh_estimate_msg_t *est = &v->au.est;
    veh_docmd_t *d = &v->au.doc;

    switch (c->id) {
    case MT_MAV_CMD_CONDITION_DELAY: return (float)(veh_now() - d->start_us) >= (d->value * 1.0e6f);
    case MT_MAV_CMD_CONDITION_DISTANCE: return veh_dist_xy(est->pos, v->fl.nav.dest) <= d->value;
    case MT_MAV_CMD_CONDITION_YAW:
        return fabsf(vm_wrap_pi(est->att[2] - d->value)) < (3.0f * VM_DEG2RAD);
    default: return true;
    }
}

/* ---- callbacks -------------------------------------------------------------------------- */

/* The newest estimate into AUTO's copy. */
static void est_refresh(veh_t *v)
{
    veh_latest(&v->au.est_sub, &v->au.est, (uint32_t)sizeof(v->au.est));
}

static bool cb_start(void *ctx, uint16_t index, const mt_mission_cmd_t *cmd)
{
    veh_t *v = (veh_t *)ctx;
    bool ok;

    est_refresh(v);
    if (mt_mission_kind_of(cmd->id) == MT_MISSION_KIND_NAV) {
        ok = start_nav(v, index, cmd);
    } else {
        ok = start_do(v, index, cmd);
    }
    if (ok) {
        v->c.cmds_started++;
    }
    veh_log_cmd(v, index, cmd->id, ok ? 1u : 0u);
    return ok;
}

static bool cb_verify(void *ctx, uint16_t index, const mt_mission_cmd_t *cmd)
{
    veh_t *v = (veh_t *)ctx;
    veh_flight_t *s = &v->fl;
    const veh_estimate_msg_t *est = &v->au.est;
    char a[16];

    est_refresh(v);
    if (mt_mission_kind_of(cmd->id) != MT_MISSION_KIND_NAV) {
        bool done = verify_do(v, cmd);
        if (done && (cmd->id >= MT_MAV_CMD_CONDITION_DELAY) &&
            (cmd->id <= MT_MAV_CMD_CONDITION_YAW)) {
            veh_say("mission: #%u %s done", index, veh_cmd_name(cmd->id));
        }
        if (done) {
            v->au.doc.active = false;
            veh_log_cmd(v, index, cmd->id, 2u);
        }
        return done;
    }
    if ((s->nav.index != index) || !s->nav.done) {
        return false;
    }
    v->au.reached_index = index;
    v->c.wps_reached++;
    veh_log_cmd(v, index, cmd->id, 2u);
    if ((cmd->id == MT_MAV_CMD_WAYPOINT) || (cmd->id == MT_MAV_CMD_SPLINE_WAYPOINT)) {
        veh_say("mission: waypoint #%u reached (%s m off)", index,
                fmt_m(a, veh_dist3(est->pos, s->nav.dest)));
    } else {
        veh_say("mission: #%u %s complete", index, veh_cmd_name(cmd->id));
    }
    return true;
}

static void cb_complete(void *ctx)
{
    veh_t *v = (veh_t *)ctx;
    const veh_flight_t *s = &v->fl;

    v->c.completions++;
    veh_log_cmd(v, 0u, 0u, 3u);
    veh_say("mission: complete");
    if (s->armed) {
        veh_say("mission: vehicle still airborne, landing here");
        veh_set_mode(v, VEH_MODE_LAND);
    } else {
        veh_set_mode(v, VEH_MODE_STANDBY);
    }
}

void veh_auto_init(veh_t *v)
{
    mt_mission_init(&v->mission, cb_start, cb_verify, cb_complete, v);
}

bool veh_auto_start(veh_t *v)
{
    mt_status_t st = mt_mission_start(&v->mission);
    if (st != MT_OK) {
        veh_say("mission: start refused (%s)", mt_status_str(st));
        return false;
    }
    return true;
}

void veh_mission_update(veh_t *v)
{
    if ((v->fl.mode == VEH_MODE_AUTO) && v->mission_ok) {
        mt_mission_update(&v->mission);
    }
}
