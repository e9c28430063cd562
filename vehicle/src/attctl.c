/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file attctl.c
 * @brief attitude_run (fast task): angle controller (P on the attitude error,
 *        giving body-rate targets) and rate controller (PID on the rate error,
 *        giving body torques). Takes `estimate` and `att_sp`, publishes
 *        `actuator` (the torques with the setpoint's thrust and arming state).
 */
#include "veh_int.h"

#define ANGLE_P 6.0f /* 1/s, roll and pitch */
#define YAW_ANGLE_P 3.0f
#define RATE_MAX 3.0f /* rad/s, roll and pitch */
#define YAW_RATE_MAX 1.2f
#define RATE_P 25.0f /* 1/s */
#define RATE_I 8.0f  /* 1/s^2 */
#define RATE_D 0.25f
#define YAW_RATE_P 10.0f
#define YAW_RATE_I 2.0f
#define TORQUE_MAX 1.6f /* N m, roll and pitch */
#define YAW_TORQUE_MAX 0.3f

void veh_attitude_run(veh_t *v)
{
    veh_attctl_t *s = &v->att;
    const float inertia[3] = {VEH_IXX, VEH_IYY, VEH_IZZ};
    veh_estimate_msg_t e;
    veh_att_sp_msg_t sp;
    veh_actuator_msg_t out;
    float err[3];
    int i;

    veh_latest(&s->est, &e, (uint32_t)sizeof(e));
    veh_latest(&s->sp, &sp, (uint32_t)sizeof(sp));
    out.thrust = sp.thrust;
    out.armed = sp.armed;
    out.flying = sp.flying;
    if (!sp.armed || !sp.flying) {
        for (i = 0; i < 3; i++) {
            s->rate_target[i] = 0.0f;
            s->rate_i[i] = 0.0f;
            s->rate_prev_err[i] = 0.0f;
            out.torque[i] = 0.0f;
        }
        (void)mt_topic_publish(&v->actuator, &out, (uint32_t)sizeof(out));
        return;
    }
    /* angle loop */
    err[0] = vm_wrap_pi(sp.att[0] - e.att[0]);
    err[1] = vm_wrap_pi(sp.att[1] - e.att[1]);
    err[2] = vm_wrap_pi(sp.att[2] - e.att[2]);
    s->rate_target[0] = vm_clamp(ANGLE_P * err[0], -RATE_MAX, RATE_MAX);
    s->rate_target[1] = vm_clamp(ANGLE_P * err[1], -RATE_MAX, RATE_MAX);
    s->rate_target[2] = vm_clamp(YAW_ANGLE_P * err[2], -YAW_RATE_MAX, YAW_RATE_MAX);

    /* rate loop */
    for (i = 0; i < 3; i++) {
        float er = s->rate_target[i] - e.rates[i];
        float kp = (i < 2) ? RATE_P : YAW_RATE_P;
        float ki = (i < 2) ? RATE_I : YAW_RATE_I;
        float kd = (i < 2) ? RATE_D : 0.0f;
        float lim = (i < 2) ? TORQUE_MAX : YAW_TORQUE_MAX;
        float de = (er - s->rate_prev_err[i]) / e.dt;
        float acc;
        s->rate_prev_err[i] = er;
        s->rate_i[i] = vm_clamp(s->rate_i[i] + (ki * er * e.dt), -5.0f, 5.0f);
        acc = (kp * er) + s->rate_i[i] + (kd * de);
        out.torque[i] = vm_clamp(inertia[i] * acc, -lim, lim);
    }
    (void)mt_topic_publish(&v->actuator, &out, (uint32_t)sizeof(out));
}
