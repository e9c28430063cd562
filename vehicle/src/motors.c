/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file motors.c
 * @brief motors_output (fast task): the quad-X mixer (total thrust and three
 *        torques to four motor thrusts; yaw gives way first when a motor
 *        saturates) and the outputs, from the `actuator` topic.
 *
 * Motors (ArduPilot numbering): 1 front-right and 2 rear-left turn
 * counter-clockwise, 3 front-left and 4 rear-right clockwise.
 */
#include "veh_int.h"

static void mix(const veh_actuator_msg_t *s, float yaw_share, float t[4])
{
    float f = s->thrust * 0.25f;
    float r = s->torque[0] / (4.0f * VEH_ARM);
    float p = s->torque[1] / (4.0f * VEH_ARM);
    float y = (s->torque[2] * yaw_share) / (4.0f * VEH_YAW_K);

    t[0] = f - r + p + y;
    t[1] = f + r - p + y;
    t[2] = f + r + p - y;
    t[3] = f - r - p - y;
}

void veh_motors_output(veh_t *v)
{
    veh_motors_t *s = &v->mot;
    veh_actuator_msg_t a;
    float t[4];
    int i;

    veh_latest(&s->act, &a, (uint32_t)sizeof(a));
    if (!a.armed) {
        for (i = 0; i < 4; i++) {
            s->motor[i] = 0.0f;
        }
    } else if (!a.flying) {
        for (i = 0; i < 4; i++) {
            s->motor[i] = VEH_MOTOR_IDLE;
        }
    } else {
        bool sat = false;
        mix(&a, 1.0f, t);
        for (i = 0; i < 4; i++) {
            if ((t[i] < 0.0f) || (t[i] > VEH_THRUST_MAX)) {
                sat = true;
            }
        }
        if (sat) {
            mix(&a, 0.2f, t); /* yaw gives way to attitude and thrust */
        }
        for (i = 0; i < 4; i++) {
            s->motor[i] = vm_clamp(t[i] / VEH_THRUST_MAX, VEH_MOTOR_IDLE, 1.0f);
        }
    }
    v->plat->motors_write(v->plat->ctx, s->motor, a.armed);
}
