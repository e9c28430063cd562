/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file veh_int.h
 * @brief The vehicle's components and their state (internal to vehicle/src/).
 *
 * Components (one file each) and the tasks that run them (tasks.def):
 *   ins.c       imu_read (fast): IMU sample, attitude estimate, inertial prediction
 *   attctl.c    attitude_run (fast): attitude and rate controllers
 *   motors.c    motors_output (fast): mixer, motor outputs
 *   gcs.c       gcs_update: ground-station commands; telemetry_send
 *   link.c      the MAVLink link (gcs_update and telemetry_send call it): commands,
 *               telemetry streams, console lines as STATUSTEXT; its parameters
 *               (link_param.c), mission protocol (mission_link.c), transmit (link_tx.c)
 *   baro.c      the barometer driver (timer proc) and baro_update
 *   gps.c       gps_update
 *   posctl.c    nav_update: flight modes, navigation targets, position controller
 *   auto.c      mission_update and the mission callbacks (AUTO mode)
 *   logger.c    log_write and the log writer (IO proc)
 *   battery.c   the battery monitor: a work item (3 Hz, work queue) reads it over the
 *               shared bus and publishes the readings on the `battery` topic
 *   house.c     housekeeping (battery readings from the topic, health), status_line
 *   sensor_bus.c the shared sensor bus (binary semaphore)
 *   console.c   time and console text (console.h); calls no other component
 * Data between components goes through topics (mt/bus.h, declared below): the state
 * estimate (`estimate`), the attitude and thrust setpoint (`att_sp`), the actuator
 * demand (`actuator`) and the battery readings (`battery`). Each component keeps its own
 * state in its member of veh_t; the flight state (modes, arming, the nav command) is
 * posctl's, shared with auto.c through calls and the nav command.
 * vehicle.c is the topology: it owns veh_t, creates the topics and subscriptions and
 * expands the task table. Calls between the files form no cycle (the console and the
 * logger at the bottom, the topology at the top; tests/vehicle/check_callgraph.py).
 */
#ifndef VEH_INT_H
#define VEH_INT_H

#include <stdbool.h>
#include <stdint.h>

#include "baro_link.h"
#include "console.h"
#include "mt/mt.h"
#include "veh.h"
#include "vmath.h"
#include "vprint.h"

/* ---- airframe (what the vehicle knows of itself) ----------------------------------------- */

#define VEH_MASS 1.5f       /* kg */
#define VEH_THRUST_MAX 7.5f /* N per motor */
#define VEH_ARM 0.1768f     /* m, motor offset along each body axis */
#define VEH_YAW_K 0.016f    /* m, yaw torque per newton */
#define VEH_IXX 0.015f
#define VEH_IYY 0.015f
#define VEH_IZZ 0.026f
#define VEH_MOTOR_IDLE 0.06f /* armed, on the ground */

/* ---- shared sensor bus ---------------------------------------------------------------- */

typedef struct {
    mt_sem_t sem;       /**< binary semaphore used as the bus lock (1 = free) */
    uint32_t transfers; /**< transactions done */
    uint32_t waits;     /**< takes that found the bus busy */
    uint32_t timeouts;  /**< takes that gave up */
} veh_bus_t;

/** Read n bytes of device register reg with the bus held (waits up to timeout_us for it).
 *  Counters are updated under the bus lock. false: bus not obtained or device error. */
bool veh_bus_read(veh_bus_t *b, const veh_platform_t *p, uint8_t dev, uint8_t reg, uint8_t *rx,
                  uint32_t n, uint64_t timeout_us);

/* ---- topics (mt/bus.h): the data the components exchange ------------------------------ */

/** `estimate` (queue of 1): the state estimate. Published by each stage of the estimator
 *  in the main loop: the inertial prediction (ins.c, every tick), the GPS correction
 *  (gps.c) and the barometer correction (baro.c); each stage takes the newest estimate,
 *  corrects it and publishes it whole. Read by attctl, posctl, auto, gcs, house, logger. */
typedef struct {
    uint64_t t_us;        /**< time of the IMU sample of the newest prediction */
    float dt;             /**< seconds since the previous sample */
    float att[3];         /**< roll, pitch, yaw, rad */
    float rates[3];       /**< body rates, rad/s */
    float pos[3];         /**< NED from home, m */
    float vel[3];         /**< NED, m/s */
    bool pos_ok;          /**< GPS has corrected the estimate */
    bool baro_ok;         /**< the barometer is calibrated (it corrects the altitude) */
    uint32_t gps_fixes;   /**< fixes taken */
    uint64_t gps_last_us; /**< time of the newest fix */
} veh_estimate_msg_t;

/** `att_sp` (queue of 1): the attitude and thrust setpoint, published by posctl.c
 *  whenever it changes them (each nav_update, arming, disarming). Read by attctl and
 *  the logger. */
typedef struct {
    float att[3]; /**< roll, pitch, yaw targets, rad */
    float thrust; /**< total thrust, N */
    float pos[3]; /**< the position target behind it (NED, m; logged) */
    bool armed;
    bool flying; /**< took off since arming: the controllers act */
} veh_att_sp_msg_t;

/** `actuator` (queue of 1): thrust and body torques, published by attctl.c every tick
 *  (the setpoint's thrust and arming state passed on). Read by motors.c. */
typedef struct {
    float thrust;    /**< total, N */
    float torque[3]; /**< N m */
    bool armed;
    bool flying;
} veh_actuator_msg_t;

/** `battery`: battery readings (battery.c -> house.c). */
/* 3 Hz, as the housekeeping loop */
#define VEH_BATTERY_PERIOD_US 333333u
/* two readings retained: a late housekeeping run still gets both; more are counted as missed */
#define VEH_BATTERY_QUEUE 2u
typedef struct {
    uint64_t t_us; /**< time of the read */
    uint32_t mv;   /**< millivolts */
    uint32_t ca;   /**< centiamperes */
} veh_battery_msg_t;

/** The newest message of a topic. Every topic of the main loop gets a first message at
 *  set-up (veh_init), so there always is one; the subscriber belongs to the caller. */
static inline void veh_latest(mt_sub_t *sub, void *out, uint32_t size)
{
    (void)mt_sub_copy_latest(sub, out, size, 0u);
}

/* ---- components' own state (each written by its component only) ----------------------- */

/** ins.c */
typedef struct {
    mt_sub_t est; /**< its own previous estimate (and the corrections since) */
    veh_imu_sample_t imu;
    uint64_t last_imu_us;
} veh_ins_t;

/** gps.c */
typedef struct {
    mt_sub_t est;
    veh_gps_fix_t fix; /**< newest fix */
} veh_gps_t;

/** baro.c (the main-loop side; the driver's state is the link and bus_fail) */
typedef struct {
    mt_sub_t est;
    float alt;      /**< altitude from the barometer, m above the boot pressure */
    float p0;       /**< ground pressure, Pa */
    uint32_t cal_n; /**< samples in the ground calibration */
    float cal_sum;
    bool ok; /**< calibrated */
} veh_baro_t;

/** attctl.c */
typedef struct {
    mt_sub_t est;
    mt_sub_t sp;
    float rate_target[3];
    float rate_i[3];
    float rate_prev_err[3];
} veh_attctl_t;

/** motors.c */
typedef struct {
    mt_sub_t act;
    float motor[4]; /**< outputs 0..1 */
} veh_motors_t;

typedef enum {
    VEH_MODE_STANDBY = 0, /**< disarmed on the ground */
    VEH_MODE_AUTO = 1,    /**< the mission flies the vehicle */
    VEH_MODE_HOLD = 2,    /**< position hold (mission stopped) */
    VEH_MODE_LAND = 3,    /**< land here */
    VEH_MODE_RTL = 4,     /**< return home at VEH_RTL_ALT_MIN or higher, land there */
    VEH_MODE_GUIDED = 5,  /**< the ground station's target: hold, or a commanded takeoff */
} veh_mode_t;

/** Lowest return altitude of RTL (the mode and the mission command), m. */
#define VEH_RTL_ALT_MIN 15.0f

typedef enum {
    VEH_NAV_NONE = 0,
    VEH_NAV_TAKEOFF,
    VEH_NAV_WAYPOINT,
    VEH_NAV_LOITER, /**< LOITER_TIME / LOITER_UNLIM: reach, then hold */
    VEH_NAV_CIRCLE, /**< LOITER_TURNS */
    VEH_NAV_LAND,
    VEH_NAV_RTL,
} veh_nav_kind_t;

/** The active nav command as the vehicle flies it. */
typedef struct {
    veh_nav_kind_t kind;
    uint16_t index;   /**< mission index */
    uint16_t id;      /**< MAV_CMD */
    float dest[3];    /**< NED destination (circle: centre) */
    float radius;     /**< acceptance radius, m */
    float hold_s;     /**< hold time after reaching (waypoint, loiter time); < 0: forever */
    float turns;      /**< circle: turns to fly */
    float circle_r;   /**< circle radius, m */
    float circle_dir; /**< +1 clockwise, -1 counter-clockwise */
    float angle;      /**< circle: current angle about the centre */
    float swept;      /**< circle: angle flown */
    uint8_t phase;    /**< sub-state (RTL: climb, return, descend; circle: approach, circle) */
    bool reached;
    uint64_t reached_us;
    bool done;
} veh_navcmd_t;

/** The flight state: modes, arming, the active nav command and the position
 *  controller. posctl.c owns it; auto.c (AUTO mode) fills the nav command and the
 *  guidance parameters (speed, yaw, RTL altitude) when a mission command starts;
 *  gcs.c, house.c and the topology read the mode and the arming state. */
typedef struct {
    mt_sub_t est_sub;       /**< posctl's subscription to `estimate` */
    veh_estimate_msg_t est; /**< newest estimate, taken at each entry point */
    /* the setpoint being built (published on `att_sp`) */
    float att_target[3]; /**< roll, pitch, yaw */
    float thrust;        /**< N, total */
    /* position controller */
    float pc_target[3]; /**< NED position target */
    float pc_vel_ff[3];
    float pc_vel_i[3];
    float pc_alt_i;
    float yaw_cmd; /**< yaw the vehicle is asked to face */
    float yaw_goal;
    float yaw_rate; /**< rad/s slew of yaw_cmd */
    bool yaw_fixed; /**< CONDITION_YAW holds the yaw until the next nav command */
    /* leg (carrot) */
    float leg_origin[3];
    float leg_dest[3];
    float leg_len;
    float leg_s;
    float leg_v;
    bool leg_done;
    float speed_xy;     /**< cruise speed, m/s (WPNAV_SPEED; DO_CHANGE_SPEED until it changes) */
    uint32_t speed_gen; /**< WPNAV_SPEED's set count when speed_xy last took it */
    uint64_t last_nav_us;
    /* modes */
    veh_mode_t mode;
    bool armed;
    bool flying;           /**< took off since arming */
    uint32_t landed_ticks; /**< nav runs with the landing detector true */
    veh_navcmd_t nav;
    float hold_pos[3];
    float land_pos[3];
    float rtl_alt;
} veh_flight_t;

/** The active do/condition command. */
typedef struct {
    uint16_t index;
    uint16_t id;
    uint64_t start_us;
    float value; /**< delay s, distance m, target yaw rad */
    bool active;
} veh_docmd_t;

/** auto.c */
typedef struct {
    mt_sub_t est_sub;
    veh_estimate_msg_t est; /**< newest estimate, taken at each callback */
    veh_docmd_t doc;
    uint16_t reached_index; /**< mission index of the newest nav command verified */
} veh_auto_t;

/** gcs.c */
typedef struct {
    mt_sub_t est_sub;
    bool arm_refused_said;
    char refuse_reason[64];
    bool link_lost; /**< the link-loss action was taken; cleared when the link returns */
} veh_gcs_t;

/** The parameters a ground station reads and sets (link.c serves them; set only there,
 *  read by the components that use them). */
#define VEH_PARAM_SYSID 0u           /**< SYSID_THISMAV: the MAVLink system id (1..255) */
#define VEH_PARAM_WPNAV_SPEED 1u     /**< WPNAV_SPEED: cruise speed, cm/s (50..1500) */
#define VEH_PARAM_FS_GCS_ENABLE 2u   /**< FS_GCS_ENABLE: link loss: 0 go on, 1 RTL, 5 LAND */
#define VEH_PARAM_FS_GCS_TIMEOUT 3u  /**< FS_GCS_TIMEOUT: link lost after it, s (2..120) */
#define VEH_PARAM_PILOT_TKOFF_ALT 4u /**< PILOT_TKOFF_ALT: takeoff altitude, cm (0..1000) */
#define VEH_NPARAMS 5u
#define VEH_FS_GCS_CONTINUE 0u
#define VEH_FS_GCS_RTL 1u
#define VEH_FS_GCS_LAND 5u
typedef struct {
    uint8_t sysid;
    float wpnav_speed_cms;
    uint8_t fs_gcs_enable;
    float fs_gcs_timeout_s;
    float pilot_tkoff_alt_cm;
    uint32_t gen[VEH_NPARAMS]; /**< per parameter: incremented by every accepted set */
} veh_params_t;

/** house.c (the battery state from the `battery` topic and the health warnings) */
typedef struct {
    mt_sub_t est_sub;
    mt_sub_t battery_sub; /**< every battery reading (mt_sub_copy_next) */
    float bat_volt;
    float bat_amp;
    bool bat_ok;
    bool bat_low_said;
    bool bat_stale_said;
    uint64_t bat_last_us; /**< time of the newest reading taken */
    uint32_t status_runs;
} veh_house_t;

/** logger.c (main-loop side) */
typedef struct {
    mt_sub_t est_sub;
    mt_sub_t sp_sub;
    uint32_t runs; /**< log_write runs */
} veh_logger_t;

typedef struct {
    const veh_platform_t *plat;
    veh_home_t home; /**< constant after veh_init */
    /* topics */
    mt_topic_t estimate;
    veh_estimate_msg_t estimate_store[1];
    mt_topic_t att_sp;
    veh_att_sp_msg_t att_sp_store[1];
    mt_topic_t actuator;
    veh_actuator_msg_t actuator_store[1];
    /* components */
    veh_ins_t ins;
    veh_gps_t gps;
    veh_baro_t baro;
    veh_attctl_t att;
    veh_motors_t mot;
    veh_flight_t fl;
    veh_auto_t au;
    veh_gcs_t gcs;
    veh_house_t house;
    veh_logger_t lg;
    veh_params_t par;
    bool crashed; /**< the deployment reported a crash (veh_note_crash) */
    /* threads' hand-offs */
    veh_bus_t bus;
    veh_baro_link_t baro_link;
    uint32_t baro_bus_fail; /**< timer proc: bus not obtained (timer thread only) */
    mt_bring_t log;
    uint8_t log_store[8192];
    mt_mission_t mission;
    bool mission_ok;        /**< a mission is loaded */
    mt_status_t mission_st; /**< status of the load */
    uint32_t mission_bad;   /**< offending index of a rejected load */
    mt_sched_t sched;
    mt_proc_set_t timer_procs;
    mt_proc_set_t io_procs;
    /* battery monitor: a work item on the vehicle's work queue, readings on a topic */
    mt_wq_t wq;
    mt_work_t battery_work;
    mt_topic_t battery_topic;
    veh_battery_msg_t battery_store[VEH_BATTERY_QUEUE];
    uint32_t battery_read_fail; /**< work item: bus reads that failed (queue thread) */
    veh_counters_t c;
} veh_t;

/* ---- component entry points ------------------------------------------------------------ */

/* task bodies (tasks.def): veh_<name> */
void veh_imu_read(veh_t *v);
void veh_attitude_run(veh_t *v);
void veh_motors_output(veh_t *v);
void veh_gcs_update(veh_t *v);
void veh_baro_update(veh_t *v);
void veh_gps_update(veh_t *v);
void veh_nav_update(veh_t *v);
void veh_mission_update(veh_t *v);
void veh_telemetry_send(veh_t *v);
void veh_log_write(veh_t *v);
void veh_housekeeping(veh_t *v);
void veh_status_line(veh_t *v);

/* procs */
void veh_baro_timer_proc(void *arg); /**< timer thread, 1 kHz */
void veh_log_io_proc(void *arg);     /**< IO thread */

/* battery monitor (battery.c): topic, work queue and interval item */
mt_status_t veh_battery_init(veh_t *v);

/* battery state (house.c) */
bool veh_battery_ok(const veh_t *v);
float veh_battery_volts(const veh_t *v);
float veh_battery_amps(const veh_t *v);

/* ground-station commands (link.c decodes them, gcs.c runs them, link.c acknowledges) */
typedef enum {
    VEH_CMD_ARM = 0, /**< p[0] 1 arm, 0 disarm; p[1] 21196 forces a disarm in flight */
    VEH_CMD_MODE,    /**< custom_mode (ArduCopter's numbers, link.c) */
    VEH_CMD_MISSION_START,
    VEH_CMD_RTL,
    VEH_CMD_LAND,
    VEH_CMD_SET_CURRENT, /**< p[0] the mission index */
    VEH_CMD_TAKEOFF,     /**< alt: the altitude above home to climb to, m */
} veh_cmd_kind_t;

typedef enum {
    VEH_CMD_DONE = 0, /**< MAV_RESULT_ACCEPTED */
    VEH_CMD_FAILED,   /**< MAV_RESULT_FAILED: not now (the reason is said) */
    VEH_CMD_DENIED,   /**< MAV_RESULT_DENIED: never in this state (the reason is said) */
} veh_cmd_result_t;

typedef struct {
    veh_cmd_kind_t kind;
    uint16_t command; /**< the MAV_CMD it came as (0: SET_MODE) */
    uint8_t sys;      /**< who sent it (the COMMAND_ACK goes there) */
    uint8_t comp;
    float p[2];
    float alt;            /**< param7 (COMMAND_INT: z), m */
    uint32_t custom_mode; /**< VEH_CMD_MODE: the vehicle's mode it maps to (veh_mode_t) */
} veh_command_t;

/* ground-station link (link.c): MAVLink 2 over the rings of veh_link_rx / veh_link_tx */
#define VEH_LINK_RX_BYTES 1024u
#define VEH_LINK_TX_BYTES 4096u
void veh_link_init(void);
void veh_params_default(veh_params_t *p);
void veh_link_receive(veh_t *v); /**< gcs_update: parse, answer, one event message */
void veh_link_stream(veh_t *v);  /**< telemetry_send: the periodic streams */
/** The command received and not yet run (one at a time; a second one meanwhile is answered
 *  TEMPORARILY_REJECTED by the link); false: none. */
bool veh_link_take_command(veh_command_t *c);
/** COMMAND_ACK for c with its result. */
void veh_link_command_ack(veh_t *v, const veh_command_t *c, veh_cmd_result_t r);
/** A ground station's heartbeat has come in (ever), and the time of the newest. */
bool veh_link_gcs_seen(uint64_t *last_us);

/* AUTO mode (auto.c) */
void veh_auto_init(veh_t *v);
bool veh_auto_start(veh_t *v);
const char *veh_cmd_name(uint16_t id);

/* position control and modes (posctl.c) */
void veh_set_mode(veh_t *v, veh_mode_t m);
void veh_leg_start(veh_t *v, const float dest[3]);
float veh_dist_xy(const float a[3], const float b[3]);
float veh_dist3(const float a[3], const float b[3]);
void veh_disarm(veh_t *v, const char *why);
bool veh_arm(veh_t *v);
const char *veh_mode_name(veh_mode_t m);
/** GUIDED or HOLD, armed, not flying: climb to alt m above home here, then hold there. */
void veh_user_takeoff(veh_t *v, float alt);

/* log records (logger.c), main-loop thread only */
#define VEH_LOG_ATT 1u
#define VEH_LOG_POS 2u
#define VEH_LOG_CTUN 3u
#define VEH_LOG_BARO 4u
#define VEH_LOG_GPS 5u
#define VEH_LOG_CMD 6u
#define VEH_LOG_EV 7u
#define VEH_LOG_BATT 8u
void veh_log_init(veh_t *v);
void veh_log_record(veh_t *v, uint8_t type, const uint8_t *payload, uint8_t len);
void veh_log_cmd(veh_t *v, uint16_t index, uint16_t id, uint8_t event);
void veh_log_event(veh_t *v, uint8_t event, uint8_t arg);
uint32_t veh_log_runs(const veh_t *v); /**< log_write runs so far (decimation of records) */

#endif /* VEH_INT_H */
