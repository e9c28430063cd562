/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file veh.h
 * @brief The example multirotor: what a deployment (vehicle/deploy/) sees.
 *
 * The vehicle is a set of components (vehicle/src/) wired together by the
 * topology in vehicle.c: the task table (vehicle/tasks.def), one timer proc
 * (the barometer driver), one IO proc (the log writer), the topics the
 * components exchange their data on (mt/bus.h), the mission sequencer and its
 * callbacks. It knows nothing of threads or ports: a deployment
 * provides a veh_platform_t (sensors, actuators, sinks), runs the main loop
 * (veh_loop_once) on its sample wait, and dispatches the two proc sets from
 * whatever threads its port offers. Operating rules:
 * - veh_init once, before any proc set is dispatched;
 * - veh_loop_once only from the main-loop thread; veh_timer_procs() from one
 *   timer thread, veh_io_procs() from one IO thread (single producer and
 *   single consumer of each ring);
 * - every console line comes from the main-loop thread.
 */
#ifndef VEH_H
#define VEH_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "mt/mt.h"

#ifdef __cplusplus
extern "C" {
#endif

/** One IMU sample (body frame FRD, SI units). */
typedef struct {
    uint64_t t_us;
    float gyro[3];  /**< rad/s */
    float accel[3]; /**< specific force, m/s^2 */
} veh_imu_sample_t;

/** One GPS fix. */
typedef struct {
    uint64_t t_us;
    int32_t lat;    /**< 1e-7 degree */
    int32_t lon;    /**< 1e-7 degree */
    int32_t alt_cm; /**< above mean sea level */
    float vel[3];   /**< north, east, down, m/s */
    uint8_t fix;    /**< 0 none, 3 = 3D */
    uint8_t sats;
} veh_gps_fix_t;

/** Devices on the shared sensor bus. */
#define VEH_DEV_BARO 0x76u
#define VEH_DEV_BATT 0x40u

/** Ground-station commands (veh_platform_t.gcs_poll). */
typedef enum {
    VEH_GCS_NONE = 0,
    VEH_GCS_ARM_AUTO = 1, /**< arm and fly the mission in AUTO */
    VEH_GCS_STOP = 2,     /**< stop the mission, hold position */
    VEH_GCS_RESUME = 3,   /**< resume the mission (AUTO) */
    VEH_GCS_LAND = 4,     /**< stop the mission and land here */
} veh_gcs_cmd_t;

/** What the deployment provides. Callbacks run in the thread that calls
 *  them: the main loop, except bus_read (timer thread and main loop) and
 *  log_sink (IO thread). A NULL work hook means "no simulated time". */
typedef struct {
    void *ctx;
    /** The sample of the current tick (taken by the deployment's sample wait). */
    void (*imu_read)(void *ctx, veh_imu_sample_t *s);
    /** A fix not returned before, if any. */
    bool (*gps_read)(void *ctx, veh_gps_fix_t *f);
    /** One transaction on the shared sensor bus: read n bytes from register reg of
     *  device dev. The caller holds the bus (veh_bus_*); false: device error. */
    bool (*bus_read)(void *ctx, uint8_t dev, uint8_t reg, uint8_t *rx, uint32_t n);
    /** Motor outputs 0..1 (4 motors, quad X, ArduPilot numbering). */
    void (*motors_write)(void *ctx, const float out[4], bool armed);
    /** Servo output (DO_SET_SERVO). */
    void (*servo_write)(void *ctx, uint8_t channel, uint16_t pwm);
    /** The binary log's destination (IO thread). */
    void (*log_sink)(void *ctx, const uint8_t *data, uint32_t n);
    /** Console text. */
    void (*console)(void *ctx, const char *s, size_t n);
    /** The next ground-station command, VEH_GCS_NONE when there is none. */
    veh_gcs_cmd_t (*gcs_poll)(void *ctx);
    /** A task body ended: simulated execution time (SITL), see tasks.def. */
    void (*task_work)(void *ctx, uint32_t task, uint32_t cost_min_us, uint32_t cost_max_us);
    /** Print the 1 Hz status line. */
    bool status_lines;
} veh_platform_t;

/** Home: where the vehicle boots (the mission's item 0 when it has one). */
typedef struct {
    int32_t lat;
    int32_t lon;
    int32_t alt_cm; /**< AMSL */
} veh_home_t;

/** Set up every component and the scheduler, load the mission (NULL/0: none).
 *  @retval MT_OK
 *  @retval a scheduler status (the task table is rejected: *bad is the entry)
 *  @retval a mission status (the mission is rejected: *bad is the command index;
 *          the vehicle is set up and stays disarmed)
 *  @retval MT_E_FULL a proc set could not take the vehicle's procs
 *  @retval a topic or work-queue status (the battery monitor could not be set up) */
mt_status_t veh_init(const veh_platform_t *plat, const veh_home_t *home,
                     const mt_mission_cmd_t *cmds, uint16_t n, uint32_t *bad);

/** One main-loop iteration: wait(ctx) for the sample, then the scheduler tick. */
void veh_loop_once(mt_sample_wait_fn_t wait, void *ctx);

/** The proc sets to dispatch: timer (1 kHz) and IO. */
mt_proc_set_t *veh_timer_procs(void);
mt_proc_set_t *veh_io_procs(void);

/** The vehicle's work queue (the battery monitor, 3 Hz): serve it from one
 *  thread (mt_wq_thread_body, e.g. mt_posix_wq_start / mt_chibios_wq_start)
 *  or, without threads, with mt_wq_run_pending() in the main loop's idle
 *  time. Its interval timer is one of the vehicle's timer procs. */
mt_wq_t *veh_work_queue(void);

/** The name of the work item in slot of veh_work_queue() ("battery"), or "unknown". */
const char *veh_work_item_name(uint32_t slot);

/** The ground-station link's byte rings (MAVLink 2, link.c): the deployment writes what it
 *  receives into veh_link_rx() and sends what it reads from veh_link_tx(), from one thread
 *  per ring side (single producer, single consumer; the vehicle's side is the main loop). */
mt_bring_t *veh_link_rx(void);
mt_bring_t *veh_link_tx(void);

/** MAVLink 2 signing on (after veh_init; off by default): every frame sent is signed with
 *  key, and a frame received unsigned, signed with another key or replayed is dropped and
 *  counted (veh_counters_t.link_rx_unsigned). timestamp: the signature clock's start, in
 *  10 us since 2015-01-01 (MAVLink's unit); it then advances with every frame. */
void veh_link_signing(const uint8_t key[32], uint64_t timestamp);

/** Timer-proc period and cost range from tasks.def (for the deployment). */
void veh_timer_spec(uint32_t *period_us, uint32_t *cost_min_us, uint32_t *cost_max_us);

/** The scheduler (reports). */
const mt_sched_t *veh_sched(void);

/** Cost range of task i from tasks.def. */
void veh_task_cost(uint32_t i, uint32_t *cost_min_us, uint32_t *cost_max_us);

/** Where the vehicle is in its life. */
typedef enum {
    VEH_PHASE_BOOT = 0,    /**< disarmed, waiting for the arm command */
    VEH_PHASE_FLYING = 1,  /**< armed */
    VEH_PHASE_DONE = 2,    /**< landed and disarmed after the mission completed */
    VEH_PHASE_ABORTED = 3, /**< landed and disarmed without completing the mission */
    VEH_PHASE_CRASHED = 4, /**< hit the ground too hard (the deployment says so) */
} veh_phase_t;

veh_phase_t veh_phase(void);

/** The deployment's world reports a crash (touchdown too fast). */
void veh_note_crash(float speed_mps);

/** Why the mission is not complete, or "" when it is. */
const char *veh_incomplete_reason(void);

/** Print the flight summary on the console (stop_reason: why the run ended). */
void veh_summary(const char *stop_reason);

/** Console output with the vehicle's formatter (main-loop thread; console.c). */
void veh_printf(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/** Counters the summary and the tests use. */
typedef struct {
    uint32_t cmds_started;         /**< mission commands started (nav and do) */
    uint32_t wps_reached;          /**< nav commands verified */
    uint32_t completions;          /**< mission complete callbacks */
    uint64_t armed_us;             /**< time of arming (0: never) */
    uint64_t disarmed_us;          /**< time of disarming after flight (0: not yet) */
    uint64_t baro_sent;            /**< samples the timer proc published */
    uint64_t baro_received;        /**< samples the main loop took */
    uint32_t baro_dropped;         /**< samples lost on a full ring (drop-oldest) */
    uint32_t baro_bus_fail;        /**< timer-proc reads that could not get the bus */
    uint64_t log_bytes;            /**< bytes the IO proc wrote to the sink */
    uint64_t log_records;          /**< records written to the ring */
    uint32_t log_dropped;          /**< records that did not fit in the ring */
    uint32_t log_max_fill;         /**< highest ring fill seen by the writer */
    uint64_t bus_transfers;        /**< bus transactions */
    uint32_t bus_waits;            /**< bus takes that had to wait */
    uint32_t bus_timeouts;         /**< bus takes that timed out */
    uint64_t telem_packets;        /**< MAVLink messages put in the link's transmit ring */
    uint64_t telem_bytes;          /**< their bytes */
    uint32_t telem_full;           /**< messages not sent: the transmit ring was full */
    uint32_t said_lost;            /**< console lines overwritten before they were sent */
    uint32_t link_rx_msgs;         /**< MAVLink messages received */
    uint32_t link_rx_errors;       /**< frames the parser dropped (bad CRC or signature) */
    uint32_t link_rx_unsigned;     /**< frames dropped by signing (unsigned, wrong key, replayed) */
    uint64_t link_rx_bytes;        /**< bytes taken from the receive ring */
    uint64_t link_rx_frame_bytes;  /**< of those, bytes of valid frames */
    uint32_t link_rx_ignored;      /**< messages received that the vehicle does not handle */
    uint32_t link_param_unknown;   /**< parameter requests or sets naming no parameter */
    uint32_t link_param_refused;   /**< parameter sets out of range (the old value kept) */
    uint32_t link_cmd_unsupported; /**< commands answered MAV_RESULT_UNSUPPORTED */
} veh_counters_t;

const veh_counters_t *veh_counters(void);

#ifdef __cplusplus
}
#endif

#endif /* VEH_H */
