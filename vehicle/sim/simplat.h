/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file simplat.h
 * @brief The vehicle's platform backed by the simulated world: sensors and
 *        devices read from the physics model, motor outputs fed to it. Shared
 *        by the host SITL and the firmware (QEMU has no sensors either).
 *
 * Threads: the model is stepped in the main loop's sample wait (simplat_wait)
 * and read there (IMU, GPS); the bus devices (barometer, battery monitor) are
 * register words written by the main loop with release stores and read by the
 * bus transaction with acquire loads (any thread). The bus itself detects
 * overlapping transactions (a collision means two users without the bus
 * semaphore): `collisions` must stay 0.
 *
 * A deployment embeds simplat_t as the FIRST member of its platform context,
 * so the simplat callbacks can be given that context directly.
 */
#ifndef SIM_SIMPLAT_H
#define SIM_SIMPLAT_H

#include <stdbool.h>
#include <stdint.h>

#include "physics.h"
#include "veh.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The port's sample wait (returns the sample time, us). */
typedef uint64_t (*simplat_wait_fn_t)(void *ctx);

typedef struct {
    sim_t sim;
    veh_home_t home;
    simplat_wait_fn_t base_wait;
    void *base_ctx;
    uint64_t t_us;        /**< time the model has been stepped to (0: not started) */
    uint64_t boot_us;     /**< first sample */
    veh_imu_sample_t imu; /**< the current tick's sample */
    veh_gps_fix_t gps;    /**< latest fix */
    bool gps_new;
    uint64_t gps_next_us;
    uint32_t baro_word;    /**< device register: pressure (1/8 Pa, 20 bits) | temp (12 bits) */
    uint32_t batt_word;    /**< device register: mV (16 bits) | current in 10 mA (16 bits) */
    uint32_t bus_busy;     /**< a transaction is under way */
    uint32_t collisions;   /**< overlapping transactions (must stay 0) */
    uint32_t transactions; /**< bus transactions (32-bit: atomic on Cortex-M too) */
    uint16_t servo[16];
    uint32_t servo_writes;
    float max_speed; /**< fastest ground speed seen, m/s */
    float max_alt;   /**< highest altitude seen, m */
} simplat_t;

/** Set up the world at home; the port's sample wait is base_wait(base_ctx). */
void simplat_init(simplat_t *w, const veh_home_t *home, uint64_t seed, simplat_wait_fn_t base_wait,
                  void *base_ctx);

/** Fill the sensor, device and actuator callbacks of *p (ctx = w). */
void simplat_fill(simplat_t *w, veh_platform_t *p);

/** Sample wait for veh_loop_once (ctx = w): the port's wait, then the world
 *  stepped to the sample time and the IMU sampled. */
uint64_t simplat_wait(void *ctx);

/** Constant wind (m/s, blowing towards the north/east components given). */
void simplat_set_wind(simplat_t *w, float north, float east);

#ifdef __cplusplus
}
#endif

#endif /* SIM_SIMPLAT_H */
