/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file posctl.c
 * @brief nav_update (50 Hz): flight modes, navigation targets and the
 *        position controller.
 *
 * Targets: a "carrot" moves along the current leg (origin to destination) at
 * the cruise speed, accelerating and braking at LEG_ACCEL and waiting when
 * the vehicle falls more than LEASH behind. The position controller turns the
 * target position and the carrot's velocity into a velocity command, then an
 * acceleration, then lean angles and a total thrust for attitude_run.
 * The nav command of AUTO mode (auto.c fills s->nav) decides the legs:
 * takeoff, waypoint (reach, then hold), loiter (time, unlimited), circle
 * (loiter turns), land and RTL (climb, return, land). GUIDED and HOLD fly to one
 * target and hold it: where the mode was entered, or a ground station's takeoff.
 *
 * Topics: takes the newest `estimate` at each entry point (the estimate does not
 * change while this file runs) and publishes the attitude and thrust setpoint on
 * `att_sp` after every change of it: at the end of each nav_update, on arming and on
 * disarming. The flight state (veh_flight_t) is this file's; auto.c fills the nav
 * command and the guidance parameters.
 */
#include <string.h>

#include "veh_int.h"

#define POS_P 1.0f
#define VEL_P 2.0f
#define VEL_I 0.4f
#define ACC_MAX 5.0f
#define LEAN_MAX (30.0f * VM_DEG2RAD)
#define ALT_P 1.5f
#define CLIMB_P 4.0f
#define CLIMB_I 1.5f
#define CLIMB_MAX 2.5f
#define DESCENT_MAX 1.5f
#define LAND_SPEED 0.7f
#define LAND_SPEED_HIGH 1.5f
#define LAND_SLOW_ALT 6.0f
#define LEG_ACCEL 2.0f
#define LEASH 6.0f
#define YAW_RATE_DEFAULT (60.0f * VM_DEG2RAD)
#define CIRCLE_RATE_MAX 1.0f
#define LAND_DETECT_RUNS 25u /* 0.5 s */

const char *veh_mode_name(veh_mode_t m)
{
    switch (m) {
    case VEH_MODE_STANDBY: return "STANDBY";
    case VEH_MODE_AUTO: return "AUTO";
    case VEH_MODE_HOLD: return "HOLD";
    case VEH_MODE_LAND: return "LAND";
    case VEH_MODE_RTL: return "RTL";
    case VEH_MODE_GUIDED: return "GUIDED";
    default: return "?";
    }
}

float veh_dist_xy(const float a[3], const float b[3])
{
    return vm_norm2(a[0] - b[0], a[1] - b[1]);
}

float veh_dist3(const float a[3], const float b[3])
{
    float d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return vm_norm3(d);
}

/* The newest estimate into the flight state's copy. */
static void est_refresh(veh_t *v)
{
    veh_latest(&v->fl.est_sub, &v->fl.est, (uint32_t)sizeof(v->fl.est));
}

/* The setpoint (targets, thrust, arming) on `att_sp`. */
static void sp_publish(veh_t *v)
{
    const veh_flight_t *s = &v->fl;
    veh_att_sp_msg_t sp;
    int i;

    for (i = 0; i < 3; i++) {
        sp.att[i] = s->att_target[i];
        sp.pos[i] = s->pc_target[i];
    }
    sp.thrust = s->thrust;
    sp.armed = s->armed;
    sp.flying = s->flying;
    (void)mt_topic_publish(&v->att_sp, &sp, (uint32_t)sizeof(sp));
}

static void pc_reset(veh_t *v)
{
    veh_flight_t *s = &v->fl;
    int i;

    for (i = 0; i < 3; i++) {
        s->pc_target[i] = s->est.pos[i];
        s->pc_vel_ff[i] = 0.0f;
        s->pc_vel_i[i] = 0.0f;
        s->leg_origin[i] = s->est.pos[i];
        s->leg_dest[i] = s->est.pos[i];
    }
    s->pc_alt_i = 0.0f;
    s->leg_len = 0.0f;
    s->leg_s = 0.0f;
    s->leg_v = 0.0f;
    s->leg_done = true;
    s->yaw_cmd = s->est.att[2];
    s->yaw_goal = s->est.att[2];
}

static void leg_start_from(veh_t *v, const float origin[3], const float dest[3])
{
    veh_flight_t *s = &v->fl;
    int i;

    for (i = 0; i < 3; i++) {
        s->leg_origin[i] = origin[i];
        s->leg_dest[i] = dest[i];
    }
    s->leg_len = veh_dist3(origin, dest);
    s->leg_s = 0.0f;
    s->leg_v = 0.0f;
    s->leg_done = s->leg_len < 0.01f;
}

void veh_leg_start(veh_t *v, const float dest[3])
{
    float origin[3];
    int i;

    /* from where the target is now, so the target never jumps */
    for (i = 0; i < 3; i++) {
        origin[i] = v->fl.pc_target[i];
    }
    leg_start_from(v, origin, dest);
}

static void leg_update(veh_t *v, float dt)
{
    veh_flight_t *s = &v->fl;
    float u[3];
    float hx;
    float hz;
    float vlim = 1.0e6f;
    float vstop;
    int i;

    if (s->leg_done) {
        for (i = 0; i < 3; i++) {
            s->pc_target[i] = s->leg_dest[i];
            s->pc_vel_ff[i] = 0.0f;
        }
        return;
    }
    for (i = 0; i < 3; i++) {
        u[i] = (s->leg_dest[i] - s->leg_origin[i]) / s->leg_len;
    }
    hx = vm_norm2(u[0], u[1]);
    hz = fabsf(u[2]);
    if (hx > 0.01f) {
        vlim = s->speed_xy / hx;
    }
    if (hz > 0.01f) {
        float vz = (u[2] < 0.0f) ? CLIMB_MAX : DESCENT_MAX;
        if ((vz / hz) < vlim) {
            vlim = vz / hz;
        }
    }
    vstop = sqrtf(2.0f * LEG_ACCEL * (s->leg_len - s->leg_s));
    if (vstop < vlim) {
        vlim = vstop;
    }
    if (veh_dist3(s->pc_target, s->est.pos) > LEASH) {
        /* the vehicle is far behind: let it catch up */
        s->leg_v = fmaxf(0.0f, s->leg_v - (2.0f * LEG_ACCEL * dt));
    } else {
        s->leg_v = fminf(s->leg_v + (LEG_ACCEL * dt), vlim);
    }
    s->leg_s += s->leg_v * dt;
    if (s->leg_s >= (s->leg_len - 0.01f)) {
        s->leg_s = s->leg_len;
        s->leg_v = 0.0f;
        s->leg_done = true;
    }
    for (i = 0; i < 3; i++) {
        s->pc_target[i] = s->leg_origin[i] + (u[i] * s->leg_s);
        s->pc_vel_ff[i] = s->leg_done ? 0.0f : (u[i] * s->leg_v);
    }
}

static void yaw_update(veh_t *v, float dt)
{
    veh_flight_t *s = &v->fl;
    float err = vm_wrap_pi(s->yaw_goal - s->yaw_cmd);
    float step = s->yaw_rate * dt;

    s->yaw_cmd = vm_wrap_2pi(s->yaw_cmd + vm_clamp(err, -step, step));
}

/* Face the leg's destination while it is more than a few metres away. */
static void yaw_face_leg(veh_t *v)
{
    veh_flight_t *s = &v->fl;
    float dn = s->leg_dest[0] - s->est.pos[0];
    float de = s->leg_dest[1] - s->est.pos[1];

    if (!s->yaw_fixed && !s->leg_done && (vm_norm2(dn, de) > 3.0f)) {
        s->yaw_goal = vm_wrap_2pi(atan2f(de, dn));
    }
}

static void pos_control(veh_t *v, float dt, float descent_max)
{
    veh_flight_t *s = &v->fl;
    float vcmd[2];
    float acc[2];
    float n;
    float c = cosf(s->est.att[2]);
    float sn = sinf(s->est.att[2]);
    float a_fwd;
    float a_right;
    float roll;
    float pitch;
    float alt = -s->est.pos[2];
    float climb = -s->est.vel[2];
    float climb_cmd;
    float e;
    float a_up;
    float tilt;
    int i;

    for (i = 0; i < 2; i++) {
        vcmd[i] = s->pc_vel_ff[i] + (POS_P * (s->pc_target[i] - s->est.pos[i]));
    }
    n = vm_norm2(vcmd[0], vcmd[1]);
    if (n > (s->speed_xy + 2.0f)) {
        vcmd[0] *= (s->speed_xy + 2.0f) / n;
        vcmd[1] *= (s->speed_xy + 2.0f) / n;
    }
    for (i = 0; i < 2; i++) {
        float err = vcmd[i] - s->est.vel[i];
        s->pc_vel_i[i] = vm_clamp(s->pc_vel_i[i] + (VEL_I * err * dt), -2.0f, 2.0f);
        acc[i] = (VEL_P * err) + s->pc_vel_i[i];
    }
    n = vm_norm2(acc[0], acc[1]);
    if (n > ACC_MAX) {
        acc[0] *= ACC_MAX / n;
        acc[1] *= ACC_MAX / n;
    }
    a_fwd = (c * acc[0]) + (sn * acc[1]);
    a_right = (-sn * acc[0]) + (c * acc[1]);
    pitch = vm_clamp(-atanf(a_fwd / VM_GRAVITY), -LEAN_MAX, LEAN_MAX);
    roll = vm_clamp(atanf((a_right * cosf(pitch)) / VM_GRAVITY), -LEAN_MAX, LEAN_MAX);

    climb_cmd = (-s->pc_vel_ff[2]) + (ALT_P * ((-s->pc_target[2]) - alt));
    climb_cmd = vm_clamp(climb_cmd, -descent_max, CLIMB_MAX);
    e = climb_cmd - climb;
    s->pc_alt_i = vm_clamp(s->pc_alt_i + (CLIMB_I * e * dt), -4.0f, 4.0f);
    a_up = vm_clamp((CLIMB_P * e) + s->pc_alt_i, -6.0f, 8.0f);
    tilt = fmaxf(cosf(roll) * cosf(pitch), 0.5f);
    s->thrust =
        vm_clamp((VEH_MASS * (VM_GRAVITY + a_up)) / tilt, 0.0f, 0.95f * 4.0f * VEH_THRUST_MAX);
    s->att_target[0] = roll;
    s->att_target[1] = pitch;
    s->att_target[2] = s->yaw_cmd;
}

/* Landing: hold (x, y), bring the target down, detect the touchdown. Returns true once
 * landed (the vehicle is then disarmed). */
static bool land_run(veh_t *v, const float xy[3], float dt)
{
    veh_flight_t *s = &v->fl;
    float alt = -s->est.pos[2];
    float speed = (alt > LAND_SLOW_ALT) ? LAND_SPEED_HIGH : LAND_SPEED;
    float weight = VEH_MASS * VM_GRAVITY;

    s->pc_target[0] = xy[0];
    s->pc_target[1] = xy[1];
    s->pc_vel_ff[0] = 0.0f;
    s->pc_vel_ff[1] = 0.0f;
    /* keep the target just below the vehicle: the climb command is the land speed */
    s->pc_target[2] = s->est.pos[2] + (speed / ALT_P);
    s->pc_vel_ff[2] = 0.0f;
    pos_control(v, dt, speed);
    if ((alt < 2.0f) && (fabsf(s->est.vel[2]) < 0.3f) && (s->thrust < (0.7f * weight))) {
        s->landed_ticks++;
    } else {
        s->landed_ticks = 0u;
    }
    if (s->landed_ticks >= LAND_DETECT_RUNS) {
        veh_say("vehicle: landed at %s m from home",
                vp_float((char[16]){0}, 16u, vm_norm2(s->est.pos[0], s->est.pos[1]), 1u));
        veh_disarm(v, "landed");
        return true;
    }
    return false;
}

static void nav_reached(veh_t *v)
{
    veh_flight_t *s = &v->fl;
    if (!s->nav.reached) {
        s->nav.reached = true;
        s->nav.reached_us = veh_now();
    }
}

static bool held(const veh_t *v)
{
    const veh_navcmd_t *n = &v->fl.nav;
    if (!n->reached || (n->hold_s < 0.0f)) {
        return false;
    }
    return (float)(veh_now() - n->reached_us) >= (n->hold_s * 1.0e6f);
}

static void auto_circle(veh_t *v, float dt)
{
    veh_flight_t *s = &v->fl;
    veh_navcmd_t *n = &s->nav;

    if (n->phase == 0u) {
        leg_update(v, dt);
        yaw_face_leg(v);
        if (s->leg_done && (veh_dist3(s->est.pos, s->leg_dest) < n->radius)) {
            n->phase = 1u;
            n->angle = atan2f(s->est.pos[1] - n->dest[1], s->est.pos[0] - n->dest[0]);
            n->swept = 0.0f;
            nav_reached(v);
        }
    } else {
        float w = fminf(s->speed_xy / n->circle_r, CIRCLE_RATE_MAX);
        n->angle = vm_wrap_pi(n->angle + (n->circle_dir * w * dt));
        n->swept += w * dt;
        s->pc_target[0] = n->dest[0] + (n->circle_r * cosf(n->angle));
        s->pc_target[1] = n->dest[1] + (n->circle_r * sinf(n->angle));
        s->pc_target[2] = n->dest[2];
        /* tangential velocity */
        s->pc_vel_ff[0] = -n->circle_dir * w * n->circle_r * sinf(n->angle);
        s->pc_vel_ff[1] = n->circle_dir * w * n->circle_r * cosf(n->angle);
        s->pc_vel_ff[2] = 0.0f;
        if (!s->yaw_fixed) {
            s->yaw_goal = vm_wrap_2pi(atan2f(s->pc_vel_ff[1], s->pc_vel_ff[0]));
        }
        if (n->swept >= (n->turns * 2.0f * VM_PI)) {
            n->done = true;
            /* stay where the circle ended */
            s->leg_done = true;
            s->leg_dest[0] = s->pc_target[0];
            s->leg_dest[1] = s->pc_target[1];
            s->leg_dest[2] = s->pc_target[2];
        }
    }
}

static void auto_rtl(veh_t *v, float dt)
{
    veh_flight_t *s = &v->fl;
    veh_navcmd_t *n = &s->nav;

    if (n->phase == 0u) {
        /* climb to the return altitude here */
        leg_update(v, dt);
        if (s->leg_done && (fabsf(s->est.pos[2] - s->leg_dest[2]) < 1.0f)) {
            float home[3] = {0.0f, 0.0f, -s->rtl_alt};
            n->phase = 1u;
            veh_leg_start(v, home);
        }
    } else if (n->phase == 1u) {
        leg_update(v, dt);
        yaw_face_leg(v);
        if (s->leg_done && (veh_dist_xy(s->est.pos, s->leg_dest) < 2.0f)) {
            n->phase = 2u;
            nav_reached(v);
            veh_say("%s: RTL home reached, landing",
                    (s->mode == VEH_MODE_RTL) ? "vehicle" : "mission");
        }
    } else {
        float home[3] = {0.0f, 0.0f, 0.0f};
        if (land_run(v, home, dt)) {
            n->done = true;
        }
        return;
    }
    pos_control(v, dt, DESCENT_MAX);
}

static void auto_run(veh_t *v, float dt)
{
    veh_flight_t *s = &v->fl;
    veh_navcmd_t *n = &s->nav;

    switch (n->kind) {
    case VEH_NAV_TAKEOFF:
        leg_update(v, dt);
        if (s->leg_done && (fabsf(s->est.pos[2] - n->dest[2]) < 0.5f)) {
            nav_reached(v);
            n->done = true;
        }
        break;
    case VEH_NAV_WAYPOINT:
    case VEH_NAV_LOITER:
        leg_update(v, dt);
        yaw_face_leg(v);
        if (s->leg_done && (veh_dist3(s->est.pos, n->dest) < n->radius)) {
            nav_reached(v);
        }
        if (held(v)) {
            n->done = true;
        }
        break;
    case VEH_NAV_CIRCLE: auto_circle(v, dt); break;
    case VEH_NAV_LAND:
        if (n->phase == 0u) {
            leg_update(v, dt);
            yaw_face_leg(v);
            if (s->leg_done && (veh_dist_xy(s->est.pos, s->leg_dest) < 1.5f)) {
                n->phase = 1u;
                nav_reached(v);
            }
        } else {
            if (land_run(v, n->dest, dt)) {
                n->done = true;
            }
            return;
        }
        break;
    case VEH_NAV_RTL: auto_rtl(v, dt); return;
    case VEH_NAV_NONE:
    default: leg_update(v, dt); break;
    }
    pos_control(v, dt, DESCENT_MAX);
}

void veh_set_mode(veh_t *v, veh_mode_t m)
{
    veh_flight_t *s = &v->fl;
    int i;

    if (m == s->mode) {
        return;
    }
    est_refresh(v);
    veh_say("vehicle: mode %s -> %s", veh_mode_name(s->mode), veh_mode_name(m));
    s->mode = m;
    veh_log_event(v, 3u, (uint8_t)m);
    if ((m == VEH_MODE_HOLD) || (m == VEH_MODE_GUIDED)) {
        for (i = 0; i < 3; i++) {
            s->hold_pos[i] = s->est.pos[i];
        }
        (void)memset(&s->nav, 0, sizeof(s->nav));
        s->nav.index = MT_MISSION_NONE;
        veh_leg_start(v, s->hold_pos);
    } else if (m == VEH_MODE_LAND) {
        for (i = 0; i < 3; i++) {
            s->land_pos[i] = s->est.pos[i];
        }
        s->landed_ticks = 0u;
    } else if (m == VEH_MODE_RTL) {
        /* the mission's RTL, flown as a mode: climb here, return, land at home */
        float up[3] = {s->est.pos[0], s->est.pos[1], 0.0f};
        (void)memset(&s->nav, 0, sizeof(s->nav));
        s->nav.kind = VEH_NAV_RTL;
        s->nav.index = MT_MISSION_NONE;
        s->rtl_alt = fmaxf(VEH_RTL_ALT_MIN, -s->est.pos[2]);
        up[2] = -s->rtl_alt;
        s->landed_ticks = 0u;
        veh_leg_start(v, up);
        veh_say("vehicle: RTL, return at %s m, %s m from home",
                vp_float((char[16]){0}, 16u, s->rtl_alt, 1u),
                vp_float((char[16]){0}, 16u, vm_norm2(s->est.pos[0], s->est.pos[1]), 1u));
    } else {
        /* AUTO and STANDBY: the mission or nothing sets the targets */
    }
}

void veh_user_takeoff(veh_t *v, float alt)
{
    veh_flight_t *s = &v->fl;

    est_refresh(v);
    (void)memset(&s->nav, 0, sizeof(s->nav));
    s->nav.kind = VEH_NAV_TAKEOFF;
    s->nav.index = MT_MISSION_NONE;
    s->hold_pos[0] = s->est.pos[0];
    s->hold_pos[1] = s->est.pos[1];
    s->hold_pos[2] = -alt;
    (void)memcpy(s->nav.dest, s->hold_pos, sizeof(s->nav.dest));
    veh_leg_start(v, s->hold_pos);
}

/* GUIDED and HOLD: to the target, then hold it; on the ground, idle until a takeoff. */
static void hold_run(veh_t *v, float dt)
{
    veh_flight_t *s = &v->fl;
    veh_navcmd_t *n = &s->nav;

    if (!s->flying && (n->kind != VEH_NAV_TAKEOFF)) {
        pc_reset(v);
        s->thrust = 0.0f;
        return;
    }
    leg_update(v, dt);
    pos_control(v, dt, DESCENT_MAX);
    if ((n->kind == VEH_NAV_TAKEOFF) && !n->reached && s->leg_done &&
        (fabsf(s->est.pos[2] - s->hold_pos[2]) < 0.5f)) {
        nav_reached(v);
        veh_say("vehicle: takeoff complete at %s m, holding",
                vp_float((char[16]){0}, 16u, -s->est.pos[2], 1u));
    }
}

bool veh_arm(veh_t *v)
{
    veh_flight_t *s = &v->fl;

    if (s->armed) {
        return true;
    }
    s->armed = true;
    s->flying = false;
    s->landed_ticks = 0u;
    s->yaw_fixed = false;
    est_refresh(v);
    pc_reset(v);
    sp_publish(v);
    if (v->c.armed_us == 0u) {
        v->c.armed_us = veh_now();
    }
    v->c.disarmed_us = 0u;
    veh_log_event(v, 1u, 0u);
    veh_say("vehicle: armed");
    return true;
}

void veh_disarm(veh_t *v, const char *why)
{
    veh_flight_t *s = &v->fl;

    if (!s->armed) {
        return;
    }
    s->armed = false;
    s->flying = false;
    s->thrust = 0.0f;
    sp_publish(v);
    v->c.disarmed_us = veh_now();
    veh_log_event(v, 2u, 0u);
    veh_say("vehicle: disarmed (%s)", why);
    if (s->mode != VEH_MODE_AUTO) {
        veh_set_mode(v, VEH_MODE_STANDBY);
    }
}

static void nav_run(veh_t *v)
{
    veh_flight_t *s = &v->fl;
    uint64_t now = veh_now();
    float dt = (s->last_nav_us == 0u)
                   ? 0.02f
                   : vm_clamp((float)(now - s->last_nav_us) * 1.0e-6f, 0.005f, 0.1f);

    s->last_nav_us = now;
    if (!s->armed) {
        pc_reset(v);
        s->thrust = 0.0f;
        return;
    }
    yaw_update(v, dt);
    switch (s->mode) {
    case VEH_MODE_AUTO: auto_run(v, dt); break;
    case VEH_MODE_HOLD:
    case VEH_MODE_GUIDED: hold_run(v, dt); break;
    case VEH_MODE_LAND: (void)land_run(v, s->land_pos, dt); break;
    case VEH_MODE_RTL: auto_rtl(v, dt); break;
    case VEH_MODE_STANDBY:
    default: s->thrust = 0.0f; break;
    }
    /* spool up once the controller asks for more than the idle thrust */
    if (s->armed && !s->flying && (s->thrust > (0.3f * VEH_MASS * VM_GRAVITY)) &&
        ((-s->pc_target[2]) > 0.3f)) {
        s->flying = true;
        veh_say("vehicle: taking off");
    }
}

void veh_nav_update(veh_t *v)
{
    veh_flight_t *s = &v->fl;

    /* a WPNAV_SPEED set by the ground station is the cruise speed from now on */
    if (s->speed_gen != v->par.gen[VEH_PARAM_WPNAV_SPEED]) {
        s->speed_gen = v->par.gen[VEH_PARAM_WPNAV_SPEED];
        s->speed_xy = v->par.wpnav_speed_cms * 0.01f;
    }
    est_refresh(v);
    nav_run(v);
    sp_publish(v);
}
