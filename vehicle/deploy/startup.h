/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file startup.h
 * @brief What both deployments (deploy/sitl, deploy/chibios) do the same way
 *        around the vehicle: set it up on the simulated world, ask it to arm
 *        like a ground station would, end the run by the same rules and print
 *        the same summary. The deployments keep what differs: the port, the
 *        threads, the console and log sinks, the mission source and their own
 *        checks.
 *
 * Uses only the kernel's public API, the vehicle (veh.h) and the world
 * (simplat.h): no port header, so both builds compile it unchanged. Main-loop
 * thread only.
 */
#ifndef VEH_STARTUP_H
#define VEH_STARTUP_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/mt.h"
#include "simplat.h"
#include "veh.h"

#ifdef __cplusplus
extern "C" {
#endif

#define VEH_RUN_ARM_FIRST_US 1000000u    /**< first arm request after boot */
#define VEH_RUN_ARM_RETRY_US 500000u     /**< then one every so often while disarmed */
#define VEH_RUN_ARM_TIMEOUT_US 15000000u /**< never armed by then: the run ends */

/** One run of the vehicle: its clock and the end-of-run rules. */
typedef struct {
    uint64_t timeout_us;  /**< give up this long after boot */
    uint64_t settle_us;   /**< run on this long after the end (the log drains) */
    uint64_t max_ticks;   /**< stop after exactly this many ticks (0: no limit) */
    uint64_t boot_us;     /**< set by veh_run_start */
    uint64_t next_arm_us; /**< the ground station's next arm request */
    uint64_t end_us;      /**< since boot: when the run stops */
    const char *reason;   /**< why the run ends; NULL while it goes on */
    bool gcs_session;     /**< a ground station is connected (MAVLink): only a crash, the
                               timeout or the tick limit end the run */
} veh_run_t;

/** Home from a mission's item 0 (its location). */
void veh_run_home(veh_home_t *home, const mt_mission_cmd_t *item0);

/** Complete *plat with the world's sensors, devices and actuators (simplat_fill:
 *  plat->ctx becomes the world, which must be the first member of the deployment's
 *  context), set the vehicle up (veh_init, same results) and start the run's clock.
 *  The deployment fills the rest of *plat (console, log sink, telemetry, ground
 *  station, task work, status lines) and timeout_us, settle_us and max_ticks of *r. */
mt_status_t veh_run_start(veh_run_t *r, veh_platform_t *plat, simplat_t *world,
                          const veh_home_t *home, const mt_mission_cmd_t *cmds, uint16_t n,
                          uint32_t *bad);

/** The sequencer rejected the mission (st from veh_run_start): say so and return true.
 *  false when st is MT_OK. */
bool veh_run_rejected(mt_status_t st, uint32_t bad);

/** The ground station's arm requests (for the deployment's gcs_poll): VEH_GCS_ARM_AUTO
 *  from VEH_RUN_ARM_FIRST_US after boot, every VEH_RUN_ARM_RETRY_US while the vehicle
 *  waits to arm; VEH_GCS_NONE otherwise. */
veh_gcs_cmd_t veh_run_arm_poll(veh_run_t *r);

/** After each main-loop iteration: a crash of the world is reported to the vehicle and
 *  the end rules are applied (mission complete, landed, crashed, never armed, timeout,
 *  tick limit). false: the run is over (r->reason says why). */
bool veh_run_after_tick(veh_run_t *r, const simplat_t *world);

/** Drain the IO procs (the log) from the caller, once the IO thread has stopped. */
void veh_run_drain(void);

/** The flight summary and the world's line. */
void veh_run_summary(const veh_run_t *r, const simplat_t *world);

#ifdef __cplusplus
}
#endif

#endif /* VEH_STARTUP_H */
