/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file physics.h
 * @brief The simulated world: a quad-X multirotor as a rigid body (thrust and
 *        yaw torque of four motors with first-order lag, gravity, quadratic
 *        drag against the wind, rotational damping, a ground plane) and its
 *        sensors (IMU, barometer, GPS, battery monitor) with deterministic noise.
 *
 * Frames: earth NED with the origin at home on the ground (altitude = -pos[2]),
 * body FRD. SI units. No threads: the caller steps the model.
 */
#ifndef SIM_PHYSICS_H
#define SIM_PHYSICS_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    float mass;        /**< kg */
    float thrust_max;  /**< N per motor */
    float arm;         /**< m, motor offset along each body axis (arm length / sqrt 2) */
    float yaw_k;       /**< m, yaw torque per newton of thrust */
    float inertia[3];  /**< kg m^2 */
    float motor_tau;   /**< s, motor time constant */
    float drag;        /**< N / (m/s)^2 */
    float rot_damp;    /**< N m / (rad/s) */
    float crash_speed; /**< m/s, touchdown faster than this is a crash */
} sim_params_t;

/** The default airframe (1.5 kg, 2:1 thrust to weight). */
void sim_params_default(sim_params_t *p);

typedef struct {
    sim_params_t p;
    float pos[3];   /**< NED, m */
    float vel[3];   /**< m/s */
    float acc[3];   /**< kinematic acceleration, m/s^2 */
    float att[3];   /**< roll, pitch, yaw, rad */
    float rates[3]; /**< body rates, rad/s */
    float motor[4]; /**< actual motor outputs 0..1 */
    float cmd[4];   /**< commanded outputs */
    float wind[3];  /**< m/s, NED */
    bool on_ground;
    uint32_t touchdowns;
    float last_touchdown_speed; /**< m/s */
    bool crashed;
    float bat_volt; /**< V */
    float bat_amp;  /**< A */
    float bat_mah;  /**< used */
    uint64_t rng;   /**< noise generator state */
} sim_t;

void sim_init(sim_t *s, const sim_params_t *p, uint64_t seed);

/** Advance dt seconds with the commanded outputs held. */
void sim_step(sim_t *s, float dt);

/** Gaussian-like noise with standard deviation sigma (deterministic). */
float sim_noise(sim_t *s, float sigma);

/** IMU reading now: gyro (rad/s) and specific force (m/s^2), body frame, with noise. */
void sim_imu(sim_t *s, float gyro[3], float accel[3]);

/** Static pressure (Pa) at the vehicle for a home at home_alt_m AMSL, with noise. */
float sim_pressure(sim_t *s, float home_alt_m);

#ifdef __cplusplus
}
#endif

#endif /* SIM_PHYSICS_H */
