/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file attctl.c
 * @brief attitude_run (fast task): angle controller (P on the attitude error,
 *        giving body-rate targets) and rate controller (PID on the rate error,
 *        giving body torques).
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
    veh_state_t *s = &v->s;
    const float inertia[3] = {VEH_IXX, VEH_IYY, VEH_IZZ};
    float err[3];
    int i;

    if (!s->armed || !s->flying) {
        for (i = 0; i < 3; i++) {
            s->rate_target[i] = 0.0f;
            s->rate_i[i] = 0.0f;
            s->rate_prev_err[i] = 0.0f;
            s->torque[i] = 0.0f;
        }
        return;
    }
    /* angle loop */
    err[0] = vm_wrap_pi(s->att_target[0] - s->att[0]);
    err[1] = vm_wrap_pi(s->att_target[1] - s->att[1]);
    err[2] = vm_wrap_pi(s->att_target[2] - s->att[2]);
    s->rate_target[0] = vm_clamp(ANGLE_P * err[0], -RATE_MAX, RATE_MAX);
    s->rate_target[1] = vm_clamp(ANGLE_P * err[1], -RATE_MAX, RATE_MAX);
    s->rate_target[2] = vm_clamp(YAW_ANGLE_P * err[2], -YAW_RATE_MAX, YAW_RATE_MAX);

    /* rate loop */
    for (i = 0; i < 3; i++) {
        float e = s->rate_target[i] - s->rates[i];
        float kp = (i < 2) ? RATE_P : YAW_RATE_P;
        float ki = (i < 2) ? RATE_I : YAW_RATE_I;
        float kd = (i < 2) ? RATE_D : 0.0f;
        float lim = (i < 2) ? TORQUE_MAX : YAW_TORQUE_MAX;
        float de = (e - s->rate_prev_err[i]) / s->dt;
        float acc;
        s->rate_prev_err[i] = e;
        s->rate_i[i] = vm_clamp(s->rate_i[i] + (ki * e * s->dt), -5.0f, 5.0f);
        acc = (kp * e) + s->rate_i[i] + (kd * de);
        s->torque[i] = vm_clamp(inertia[i] * acc, -lim, lim);
    }
}
