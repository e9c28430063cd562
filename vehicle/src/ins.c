/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file ins.c
 * @brief imu_read (fast task): the IMU sample of the tick, the attitude
 *        estimate (gyro integration with a slow accelerometer correction of
 *        roll and pitch) and the inertial prediction of velocity and position
 *        (corrected by gps.c and baro.c). The first stage of the estimator: it
 *        takes the newest estimate (with the corrections since its last run),
 *        predicts and publishes it on `estimate`.
 */
#include "veh_int.h"

#define ACC_GAIN 0.5f /* 1/s: accelerometer correction of roll and pitch */

void veh_imu_read(veh_t *v)
{
    veh_ins_t *ins = &v->ins;
    veh_estimate_msg_t est;
    veh_estimate_msg_t *s = &est;
    float d[3];
    float r[3][3];
    float a[3];
    int i;

    veh_latest(&ins->est, &est, (uint32_t)sizeof(est));
    v->plat->imu_read(v->plat->ctx, &ins->imu);
    if (ins->last_imu_us == 0u) {
        s->dt = 0.0025f;
    } else {
        s->dt = vm_clamp((float)(ins->imu.t_us - ins->last_imu_us) * 1.0e-6f, 0.0005f, 0.02f);
    }
    ins->last_imu_us = ins->imu.t_us;
    s->t_us = ins->imu.t_us;

    /* attitude: integrate the body rates */
    for (i = 0; i < 3; i++) {
        s->rates[i] = ins->imu.gyro[i];
    }
    vm_euler_rates(s->att, s->rates, d);
    for (i = 0; i < 3; i++) {
        s->att[i] += d[i] * s->dt;
    }
    /* roll and pitch from gravity when the specific force is close to 1 g */
    {
        const float *f = ins->imu.accel;
        float g = vm_norm3(f);
        if ((g > (0.9f * VM_GRAVITY)) && (g < (1.1f * VM_GRAVITY))) {
            float roll_a = atan2f(-f[1], -f[2]);
            float pitch_a = atan2f(f[0], vm_norm2(f[1], f[2]));
            float k = ACC_GAIN * s->dt;
            s->att[0] += vm_wrap_pi(roll_a - s->att[0]) * k;
            s->att[1] += vm_wrap_pi(pitch_a - s->att[1]) * k;
        }
    }
    s->att[0] = vm_wrap_pi(s->att[0]);
    s->att[1] = vm_clamp(s->att[1], -1.4f, 1.4f);
    s->att[2] = vm_wrap_2pi(s->att[2]);

    /* inertial prediction: earth-frame acceleration = R f + g */
    vm_dcm(s->att, r);
    for (i = 0; i < 3; i++) {
        a[i] = (r[i][0] * ins->imu.accel[0]) + (r[i][1] * ins->imu.accel[1]) +
               (r[i][2] * ins->imu.accel[2]);
    }
    a[2] += VM_GRAVITY;
    for (i = 0; i < 3; i++) {
        s->pos[i] += (s->vel[i] * s->dt) + (0.5f * a[i] * s->dt * s->dt);
        s->vel[i] += a[i] * s->dt;
    }
    (void)mt_topic_publish(&v->estimate, &est, (uint32_t)sizeof(est));
}
