/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file physics.c
 * @brief The simulated multirotor and its sensors (see physics.h).
 */
#include "physics.h"

#include <math.h>
#include <string.h>

#include "vmath.h"

void sim_params_default(sim_params_t *p)
{
    p->mass = 1.5f;
    p->thrust_max = 7.5f;
    p->arm = 0.25f * 0.70710678f;
    p->yaw_k = 0.016f;
    p->inertia[0] = 0.015f;
    p->inertia[1] = 0.015f;
    p->inertia[2] = 0.026f;
    p->motor_tau = 0.025f;
    p->drag = 0.06f;
    p->rot_damp = 0.01f;
    p->crash_speed = 3.0f;
}

void sim_init(sim_t *s, const sim_params_t *p, uint64_t seed)
{
    memset(s, 0, sizeof(*s));
    s->p = *p;
    s->on_ground = true;
    s->bat_volt = 16.8f;
    s->rng = (seed != 0u) ? seed : 0x9E3779B97F4A7C15ull;
}

/* xorshift64* */
static uint64_t rng_next(sim_t *s)
{
    uint64_t x = s->rng;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    s->rng = x;
    return x * 0x2545F4914F6CDD1Dull;
}

float sim_noise(sim_t *s, float sigma)
{
    /* sum of four uniforms on [-0.5, 0.5): variance 1/3 */
    float sum = 0.0f;
    int i;

    for (i = 0; i < 4; i++) {
        sum += ((float)(rng_next(s) >> 40) / 16777216.0f) - 0.5f;
    }
    return sum * 1.7320508f * sigma;
}

static void motor_thrusts(const sim_t *s, float t[4])
{
    int i;
    for (i = 0; i < 4; i++) {
        t[i] = s->p.thrust_max * s->motor[i];
    }
}

void sim_step(sim_t *s, float dt)
{
    float t[4];
    float r[3][3];
    float total;
    float fz;
    float vrel[3];
    float vr;
    float acc[3];
    float tau[3];
    float d[3];
    int i;

    /* motors: first-order lag towards the command */
    for (i = 0; i < 4; i++) {
        float k = dt / (s->p.motor_tau + dt);
        s->motor[i] += (vm_clamp(s->cmd[i], 0.0f, 1.0f) - s->motor[i]) * k;
    }
    motor_thrusts(s, t);
    total = t[0] + t[1] + t[2] + t[3];

    /* translation: thrust along body -z, gravity, quadratic drag against the wind */
    vm_dcm(s->att, r);
    fz = -total;
    for (i = 0; i < 3; i++) {
        vrel[i] = s->vel[i] - s->wind[i];
    }
    vr = vm_norm3(vrel);
    for (i = 0; i < 3; i++) {
        acc[i] = ((r[i][2] * fz) - (s->p.drag * vr * vrel[i])) / s->p.mass;
    }
    acc[2] += VM_GRAVITY;

    if (s->on_ground) {
        if (acc[2] < -0.05f) {
            s->on_ground = false; /* lift-off */
        } else {
            for (i = 0; i < 3; i++) {
                acc[i] = 0.0f;
                s->vel[i] = 0.0f;
            }
        }
    }
    if (!s->on_ground) {
        for (i = 0; i < 3; i++) {
            s->vel[i] += acc[i] * dt;
            s->pos[i] += s->vel[i] * dt;
        }
        if (s->pos[2] >= 0.0f) {
            /* touchdown */
            s->last_touchdown_speed = s->vel[2];
            s->touchdowns++;
            if (s->vel[2] > s->p.crash_speed) {
                s->crashed = true;
            }
            s->pos[2] = 0.0f;
            for (i = 0; i < 3; i++) {
                s->vel[i] = 0.0f;
                acc[i] = 0.0f;
            }
            s->on_ground = true;
        }
    }
    for (i = 0; i < 3; i++) {
        s->acc[i] = acc[i];
    }

    /* rotation: motor torques (quad X: 1 front-right, 2 rear-left, 3 front-left,
     * 4 rear-right; 1 and 2 turn counter-clockwise), damping, gyroscopic coupling */
    tau[0] = s->p.arm * ((t[1] + t[2]) - (t[0] + t[3]));
    tau[1] = s->p.arm * ((t[0] + t[2]) - (t[1] + t[3]));
    tau[2] = s->p.yaw_k * ((t[0] + t[1]) - (t[2] + t[3]));
    if (s->on_ground) {
        /* sitting on its legs: level, no rotation (yaw kept) */
        s->att[0] = 0.0f;
        s->att[1] = 0.0f;
        for (i = 0; i < 3; i++) {
            s->rates[i] = 0.0f;
        }
    } else {
        const float *in = s->p.inertia;
        float w0 = s->rates[0];
        float w1 = s->rates[1];
        float w2 = s->rates[2];
        float cx = (w1 * w2) * (in[1] - in[2]);
        float cy = (w2 * w0) * (in[2] - in[0]);
        float cz = (w0 * w1) * (in[0] - in[1]);
        s->rates[0] += ((tau[0] - (s->p.rot_damp * w0) + cx) / in[0]) * dt;
        s->rates[1] += ((tau[1] - (s->p.rot_damp * w1) + cy) / in[1]) * dt;
        s->rates[2] += ((tau[2] - (s->p.rot_damp * w2) + cz) / in[2]) * dt;
        vm_euler_rates(s->att, s->rates, d);
        for (i = 0; i < 3; i++) {
            s->att[i] += d[i] * dt;
        }
        s->att[0] = vm_wrap_pi(s->att[0]);
        s->att[2] = vm_wrap_2pi(s->att[2]);
    }

    /* battery: 4S 5000 mAh, current grows with the square of the outputs */
    {
        float m2 = 0.0f;
        for (i = 0; i < 4; i++) {
            m2 += s->motor[i] * s->motor[i];
        }
        s->bat_amp = 0.4f + (12.0f * m2);
        s->bat_mah += s->bat_amp * dt * (1000.0f / 3600.0f);
        s->bat_volt = 16.8f - (2.4f * (s->bat_mah / 5000.0f)) - (0.012f * s->bat_amp);
    }
}

void sim_imu(sim_t *s, float gyro[3], float accel[3])
{
    float r[3][3];
    float f[3];
    int i;

    vm_dcm(s->att, r);
    /* specific force in earth frame: acceleration minus gravity */
    f[0] = s->acc[0];
    f[1] = s->acc[1];
    f[2] = s->acc[2] - VM_GRAVITY;
    for (i = 0; i < 3; i++) {
        /* earth to body: the transpose */
        accel[i] = (r[0][i] * f[0]) + (r[1][i] * f[1]) + (r[2][i] * f[2]) + sim_noise(s, 0.05f);
        gyro[i] = s->rates[i] + sim_noise(s, 0.002f);
    }
}

float sim_pressure(sim_t *s, float home_alt_m)
{
    float h = home_alt_m - s->pos[2];
    return (101325.0f * powf(1.0f - (2.25577e-5f * h), 5.25588f)) + sim_noise(s, 1.0f);
}
