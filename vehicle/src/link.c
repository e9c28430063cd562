/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file link.c
 * @brief The ground-station link: MAVLink 2 (ardupilotmega dialect, C headers
 *        generated at build time by pymavlink's mavgen) over two SPSC byte
 *        rings that the deployment connects to its socket or UART.
 *
 * veh_link_receive (gcs_update, 400 Hz) parses what the ground station sent,
 * answers the parameter protocol and sends the events (MISSION_ITEM_REACHED,
 * every console line as STATUSTEXT), one per run; veh_link_stream
 * (telemetry_send, 10 Hz) sends the periodic streams, at most three messages
 * per run. Nothing is dropped silently: a message that does not fit in the
 * transmit ring is counted (veh_counters_t.telem_full), a console line
 * overwritten before it was sent is counted (said_lost), a frame the parser
 * drops is counted (link_rx_errors, also SYS_STATUS.errors_comm), and every
 * byte received outside a valid frame shows as link_rx_bytes -
 * link_rx_frame_bytes.
 *
 * Identity and modes (documented in vehicle/README.md): HEARTBEAT says a
 * quadrotor (MAV_TYPE_QUADROTOR) with an ArduPilot-style autopilot
 * (MAV_AUTOPILOT_ARDUPILOTMEGA), so ground stations name the modes with
 * ArduCopter's custom-mode numbers: STANDBY -> STABILIZE (0), AUTO -> AUTO (3),
 * GUIDED -> GUIDED (4), HOLD -> LOITER (5), LAND -> LAND (9), RTL -> RTL (6).
 */
#include <string.h>

#include "link_int.h"

#define LINK_COMPID VEH_LINK_COMPID
#define LINK_CHAN VEH_LINK_CHAN
#define LINK_RX_PER_RUN 280u /* bytes parsed per gcs_update: one full MAVLink 2 frame */

typedef struct {
    mt_bring_t rx;
    uint8_t rx_store[VEH_LINK_RX_BYTES];
    mavlink_message_t rx_msg; /* the parser's frame under construction */
    mavlink_status_t rx_status;
    uint32_t stream_runs;  /* telemetry_send runs */
    uint32_t said_sent;    /* console lines handled (sent or lost) */
    uint32_t reached_sent; /* waypoints reported (MISSION_ITEM_REACHED) */
    uint16_t param_next;   /* next index of a PARAM_REQUEST_LIST answer; VEH_NPARAMS: idle */
    bool gcs_seen;         /* a ground station's HEARTBEAT has come in */
    uint64_t gcs_last_us;  /* time of the newest */
    bool cmd_pending;      /* cmd received, not yet taken by gcs_update */
    veh_command_t cmd;
} veh_link_t;

static veh_link_t g_link;

/* MAVLink 2 signing (off until veh_link_signing): the key, the outgoing timestamp, the
 * timestamps of the streams seen */
static mavlink_signing_t g_sign;
static mavlink_signing_streams_t g_sign_streams;

/* ---- transmit ---------------------------------------------------------------------------- */

static uint32_t custom_mode(veh_mode_t m)
{
    switch (m) {
    case VEH_MODE_AUTO: return (uint32_t)COPTER_MODE_AUTO;
    case VEH_MODE_GUIDED: return (uint32_t)COPTER_MODE_GUIDED;
    case VEH_MODE_HOLD: return (uint32_t)COPTER_MODE_LOITER;
    case VEH_MODE_LAND: return (uint32_t)COPTER_MODE_LAND;
    case VEH_MODE_RTL: return (uint32_t)COPTER_MODE_RTL;
    case VEH_MODE_STANDBY:
    default: return (uint32_t)COPTER_MODE_STABILIZE;
    }
}

static void send_heartbeat(veh_t *v)
{
    mavlink_message_t m;
    uint8_t base = (uint8_t)(MAV_MODE_FLAG_CUSTOM_MODE_ENABLED | MAV_MODE_FLAG_STABILIZE_ENABLED);
    uint8_t state = (uint8_t)MAV_STATE_STANDBY;

    if (v->fl.mode == VEH_MODE_AUTO) {
        base = (uint8_t)(base | MAV_MODE_FLAG_GUIDED_ENABLED | MAV_MODE_FLAG_AUTO_ENABLED);
    } else if (v->fl.mode == VEH_MODE_GUIDED) {
        base = (uint8_t)(base | MAV_MODE_FLAG_GUIDED_ENABLED);
    } else {
        /* the other modes fly no ground-station target */
    }
    if (v->fl.armed) {
        base = (uint8_t)(base | MAV_MODE_FLAG_SAFETY_ARMED);
    }
    /* as ArduCopter: STANDBY on the ground (armed or not), ACTIVE in the air, CRITICAL while a
     * failsafe holds (here the link-loss one); QGroundControl takes armed and ACTIVE as flying */
    if (v->fl.flying) {
        state = (uint8_t)MAV_STATE_ACTIVE;
    }
    if (v->gcs.link_lost && (v->par.fs_gcs_enable != (uint8_t)VEH_FS_GCS_CONTINUE)) {
        state = (uint8_t)MAV_STATE_CRITICAL; /* FS_GCS_ENABLE 0: no failsafe, as ArduCopter */
    }
    if (v->crashed) {
        state = (uint8_t)MAV_STATE_EMERGENCY;
    }
    (void)mavlink_msg_heartbeat_pack_chan(
        v->par.sysid, LINK_COMPID, LINK_CHAN, &m, (uint8_t)MAV_TYPE_QUADROTOR,
        (uint8_t)MAV_AUTOPILOT_ARDUPILOTMEGA, base, custom_mode(v->fl.mode), state);
    veh_link_send(v, &m);
}

#define SENSORS                                                                                \
    ((uint32_t)MAV_SYS_STATUS_SENSOR_3D_GYRO | (uint32_t)MAV_SYS_STATUS_SENSOR_3D_ACCEL |      \
     (uint32_t)MAV_SYS_STATUS_SENSOR_ABSOLUTE_PRESSURE | (uint32_t)MAV_SYS_STATUS_SENSOR_GPS | \
     (uint32_t)MAV_SYS_STATUS_SENSOR_BATTERY)

static void send_sys_status(veh_t *v, const veh_estimate_msg_t *est)
{
    mavlink_message_t m;
    uint32_t health =
        (uint32_t)MAV_SYS_STATUS_SENSOR_3D_GYRO | (uint32_t)MAV_SYS_STATUS_SENSOR_3D_ACCEL;
    float volts = vm_clamp(veh_battery_volts(v), 0.0f, 60.0f);
    float amps = vm_clamp(veh_battery_amps(v), 0.0f, 300.0f);

    if (est->baro_ok) {
        health |= (uint32_t)MAV_SYS_STATUS_SENSOR_ABSOLUTE_PRESSURE;
    }
    if (est->pos_ok) {
        health |= (uint32_t)MAV_SYS_STATUS_SENSOR_GPS;
    }
    if (veh_battery_ok(v)) {
        health |= (uint32_t)MAV_SYS_STATUS_SENSOR_BATTERY;
    }
    /* no fence: present and enabled clear, health set (not breached), as ArduPilot reports
     * it; a clear health bit reads as a breach to ground stations (MAVProxy says so) */
    health |= (uint32_t)MAV_SYS_STATUS_GEOFENCE;
    (void)mavlink_msg_sys_status_pack_chan(
        v->par.sysid, LINK_COMPID, LINK_CHAN, &m, SENSORS, SENSORS, health,
        (uint16_t)mt_sched_load_permille(&v->sched), (uint16_t)lroundf(volts * 1000.0f),
        (int16_t)lroundf(amps * 100.0f), -1, 0u,
        (uint16_t)((v->c.link_rx_errors > 65535u) ? 65535u : v->c.link_rx_errors), 0u, 0u, 0u, 0u,
        0u, 0u, 0u);
    veh_link_send(v, &m);
}

static void send_attitude(veh_t *v, const veh_estimate_msg_t *est)
{
    mavlink_message_t m;

    (void)mavlink_msg_attitude_pack_chan(v->par.sysid, LINK_COMPID, LINK_CHAN, &m,
                                         veh_link_boot_ms(), est->att[0], est->att[1], est->att[2],
                                         est->rates[0], est->rates[1], est->rates[2]);
    veh_link_send(v, &m);
}

static int16_t cms(float mps)
{
    return (int16_t)lroundf(vm_clamp(mps, -300.0f, 300.0f) * 100.0f);
}

static uint16_t centideg(float rad)
{
    long d = lroundf(vm_wrap_2pi(rad) * VM_RAD2DEG * 100.0f);
    return (uint16_t)((d >= 36000L) ? 0L : d);
}

static void send_global_position(veh_t *v, const veh_estimate_msg_t *est)
{
    mavlink_message_t m;
    int32_t lat;
    int32_t lon;
    int32_t rel_mm = (int32_t)lroundf(-est->pos[2] * 1000.0f);

    vm_ll_from_ne(v->home.lat, v->home.lon, est->pos[0], est->pos[1], &lat, &lon);
    (void)mavlink_msg_global_position_int_pack_chan(
        v->par.sysid, LINK_COMPID, LINK_CHAN, &m, veh_link_boot_ms(), lat, lon,
        v->home.alt_cm * 10 + rel_mm, rel_mm, cms(est->vel[0]), cms(est->vel[1]), cms(est->vel[2]),
        centideg(est->att[2]));
    veh_link_send(v, &m);
}

static void send_gps_raw(veh_t *v)
{
    mavlink_message_t m;
    const veh_gps_fix_t *f = &v->gps.fix;
    float gs = vm_norm2(f->vel[0], f->vel[1]);
    uint16_t cog = (gs > 0.2f) ? centideg(atan2f(f->vel[1], f->vel[0])) : UINT16_MAX;

    (void)mavlink_msg_gps_raw_int_pack_chan(
        v->par.sysid, LINK_COMPID, LINK_CHAN, &m, f->t_us, f->fix, f->lat, f->lon, f->alt_cm * 10,
        UINT16_MAX, UINT16_MAX, (uint16_t)lroundf(vm_clamp(gs, 0.0f, 600.0f) * 100.0f), cog,
        f->sats, 0, 0u, 0u, 0u, 0u, 0u);
    veh_link_send(v, &m);
}

/* MISSION_ITEM_REACHED for the newest nav command verified, once; false: nothing new. */
static bool send_reached(veh_t *v)
{
    mavlink_message_t m;

    if (g_link.reached_sent == v->c.wps_reached) {
        return false;
    }
    g_link.reached_sent = v->c.wps_reached;
    (void)mavlink_msg_mission_item_reached_pack_chan(v->par.sysid, LINK_COMPID, LINK_CHAN, &m,
                                                     v->au.reached_index);
    veh_link_send(v, &m);
    return true;
}

/* A console line's severity: warnings and refusals above plain information. */
static uint8_t severity_of(const char *text)
{
    if ((strstr(text, "refused") != NULL) || (strstr(text, "rejected") != NULL) ||
        (strstr(text, "low") != NULL) || (strstr(text, "lost") != NULL)) {
        return (uint8_t)MAV_SEVERITY_WARNING;
    }
    if (strstr(text, "crash") != NULL) {
        return (uint8_t)MAV_SEVERITY_CRITICAL;
    }
    return (uint8_t)MAV_SEVERITY_INFO;
}

/* One console line as STATUSTEXT: up to 50 characters in one message (id 0); a longer line
 * in chunks of 50 with the same non-zero id and chunk_seq 0, 1, ..., the last one shorter
 * than 50 (NUL-terminated; empty when the length is a multiple of 50), so the ground station
 * can reassemble it. */
static void send_line(veh_t *v, uint32_t seq, const char *text)
{
    const size_t w = MAVLINK_MSG_STATUSTEXT_FIELD_TEXT_LEN;
    size_t len = strlen(text);
    size_t off = 0u;
    uint16_t id = (len <= w) ? 0u : (uint16_t)((seq % 65535u) + 1u);
    uint8_t sev = severity_of(text);
    uint8_t chunk = 0u;
    size_t n;

    do {
        char part[MAVLINK_MSG_STATUSTEXT_FIELD_TEXT_LEN + 1u];
        mavlink_message_t m;

        n = ((len - off) > w) ? w : (len - off);
        (void)memset(part, 0, sizeof(part));
        (void)memcpy(part, &text[off], n);
        (void)mavlink_msg_statustext_pack_chan(v->par.sysid, LINK_COMPID, LINK_CHAN, &m, sev, part,
                                               id, chunk);
        veh_link_send(v, &m);
        off += n;
        chunk++;
    } while ((id != 0u) && (n == w));
}

/* The oldest console line not sent yet, as STATUSTEXT; lines overwritten before their turn
 * are counted as lost (all of them at once). */
static void send_said(veh_t *v)
{
    char text[VEH_SAID_TEXT];
    uint32_t said = veh_console_said_count();

    if ((said - g_link.said_sent) > VEH_SAID_KEEP) {
        v->c.said_lost += (said - g_link.said_sent) - VEH_SAID_KEEP;
        g_link.said_sent = said - VEH_SAID_KEEP;
    }
    if (g_link.said_sent == said) {
        return;
    }
    g_link.said_sent++;
    if (veh_console_said(g_link.said_sent, text)) {
        send_line(v, g_link.said_sent, text);
    }
}

/* ---- receive (a target of 0 is a broadcast) ---------------------------------------- */

/* The target (system, component) is this vehicle; on_message checks it once for every
 * message that has one, before any handler. */
static bool for_us(const veh_t *v, uint8_t sys, uint8_t comp)
{
    return ((sys == v->par.sysid) || (sys == 0u)) && ((comp == LINK_COMPID) || (comp == 0u));
}

/* ---- commands: decoded here, run by gcs_update (gcs.c), acknowledged here ---------------- */

static void ack(veh_t *v, uint8_t sys, uint8_t comp, uint16_t command, uint8_t result)
{
    mavlink_message_t m;

    (void)mavlink_msg_command_ack_pack_chan(v->par.sysid, LINK_COMPID, LINK_CHAN, &m, command,
                                            result, 0u, 0, sys, comp);
    veh_link_send(v, &m);
}

/* The vehicle's mode for an ArduCopter custom mode number, or -1. */
static int mode_of(uint32_t custom)
{
    switch (custom) {
    case (uint32_t)COPTER_MODE_STABILIZE: return (int)VEH_MODE_STANDBY;
    case (uint32_t)COPTER_MODE_AUTO: return (int)VEH_MODE_AUTO;
    case (uint32_t)COPTER_MODE_GUIDED: return (int)VEH_MODE_GUIDED;
    case (uint32_t)COPTER_MODE_LOITER: return (int)VEH_MODE_HOLD;
    case (uint32_t)COPTER_MODE_RTL: return (int)VEH_MODE_RTL;
    case (uint32_t)COPTER_MODE_LAND: return (int)VEH_MODE_LAND;
    default: return -1;
    }
}

/* SET_MODE has no command number: answered as DO_SET_MODE, as ArduPilot does. */
static uint16_t ack_id(uint16_t command)
{
    return (command == 0u) ? (uint16_t)MAV_CMD_DO_SET_MODE : command;
}

/* COMMAND_LONG, COMMAND_INT (command, param1, param2, param7 or z) or SET_MODE (command 0,
 * base mode, custom mode): the supported ones wait for gcs_update, one at a time; the rest are
 * answered here. */
static void on_command(veh_t *v, const mavlink_message_t *m, uint16_t command, const float p[3])
{
    veh_command_t c;

    (void)memset(&c, 0, sizeof(c));
    c.command = command;
    c.sys = m->sysid;
    c.comp = m->compid;
    c.p[0] = p[0];
    c.p[1] = p[1];
    c.alt = p[2];
    switch (command) {
    case MAV_CMD_COMPONENT_ARM_DISARM: c.kind = VEH_CMD_ARM; break;
    case 0u: /* SET_MODE */
    case MAV_CMD_DO_SET_MODE: {
        int mode =
            (isfinite(p[1]) && (p[1] >= 0.0f) && (p[1] < 256.0f)) ? mode_of((uint32_t)p[1]) : -1;
        if (mode < 0) {
            veh_say("gcs: mode %s refused: not a mode of this vehicle",
                    vp_float((char[24]){0}, 24u, p[1], 0u));
            ack(v, c.sys, c.comp, ack_id(command), (uint8_t)MAV_RESULT_FAILED);
            return;
        }
        c.kind = VEH_CMD_MODE;
        c.custom_mode = (uint32_t)mode;
        break;
    }
    case MAV_CMD_MISSION_START: c.kind = VEH_CMD_MISSION_START; break;
    case MAV_CMD_NAV_RETURN_TO_LAUNCH: c.kind = VEH_CMD_RTL; break;
    case MAV_CMD_NAV_LAND: c.kind = VEH_CMD_LAND; break;
    case MAV_CMD_DO_SET_MISSION_CURRENT: c.kind = VEH_CMD_SET_CURRENT; break;
    case MAV_CMD_NAV_TAKEOFF: c.kind = VEH_CMD_TAKEOFF; break;
    default:
        v->c.link_cmd_unsupported++;
        ack(v, c.sys, c.comp, command, (uint8_t)MAV_RESULT_UNSUPPORTED);
        return;
    }
    if (g_link.cmd_pending) {
        ack(v, c.sys, c.comp, ack_id(command), (uint8_t)MAV_RESULT_TEMPORARILY_REJECTED);
        return;
    }
    g_link.cmd = c;
    g_link.cmd_pending = true;
}

bool veh_link_take_command(veh_command_t *c)
{
    if (!g_link.cmd_pending) {
        return false;
    }
    *c = g_link.cmd;
    g_link.cmd_pending = false;
    return true;
}

void veh_link_command_ack(veh_t *v, const veh_command_t *c, veh_cmd_result_t r)
{
    uint8_t res = (r == VEH_CMD_DONE)     ? (uint8_t)MAV_RESULT_ACCEPTED
                  : (r == VEH_CMD_DENIED) ? (uint8_t)MAV_RESULT_DENIED
                                          : (uint8_t)MAV_RESULT_FAILED;

    ack(v, c->sys, c->comp, ack_id(c->command), res);
}

bool veh_link_gcs_seen(uint64_t *last_us)
{
    *last_us = g_link.gcs_last_us;
    return g_link.gcs_seen;
}

/* MAVLink FTP (clients try it first for parameters and missions): every request is answered
 * NAK UnknownCommand at once, so the client falls back to the plain protocols without waiting
 * for its timeout. Payload: seq (2, little-endian), session, opcode, size, req_opcode,
 * burst_complete, padding, offset (4), data. */
#define FTP_OP_NAK 129u
#define FTP_ERR_UNKNOWN_COMMAND 7u
static void on_ftp(veh_t *v, const mavlink_message_t *m)
{
    mavlink_file_transfer_protocol_t r;
    uint8_t out[MAVLINK_MSG_FILE_TRANSFER_PROTOCOL_FIELD_PAYLOAD_LEN];
    mavlink_message_t a;
    uint16_t seq;

    mavlink_msg_file_transfer_protocol_decode(m, &r);
    seq = (uint16_t)(((uint32_t)r.payload[0] | ((uint32_t)r.payload[1] << 8)) + 1u);
    (void)memset(out, 0, sizeof(out));
    out[0] = (uint8_t)(seq & 0xFFu);
    out[1] = (uint8_t)(seq >> 8);
    out[2] = r.payload[2];        /* session */
    out[3] = (uint8_t)FTP_OP_NAK; /* opcode */
    out[4] = 1u;                  /* size: one error byte */
    out[5] = r.payload[3];        /* the request's opcode */
    out[12] = FTP_ERR_UNKNOWN_COMMAND;
    (void)mavlink_msg_file_transfer_protocol_pack_chan(v->par.sysid, LINK_COMPID, LINK_CHAN, &a, 0u,
                                                       m->sysid, m->compid, out);
    veh_link_send(v, &a);
}

/* SETUP_SIGNING, as ArduPilot handles it: the key and the timestamp take effect at once, for
 * every frame after this one; an all-zero key with timestamp 0 turns signing off. While signing
 * is on only a signed frame gets here (the parser drops the rest), so only the key holder can
 * change or remove the key. The key lives in RAM until the vehicle restarts (ArduPilot keeps it
 * in its storage). */
static void on_setup_signing(const mavlink_message_t *m)
{
    mavlink_setup_signing_t r;
    bool zero = true;
    size_t i;

    mavlink_msg_setup_signing_decode(m, &r);
    for (i = 0u; i < sizeof(r.secret_key); i++) {
        zero = zero && (r.secret_key[i] == 0u);
    }
    if (zero && (r.initial_timestamp == 0u)) {
        g_link.rx_status.signing = NULL;
        g_link.rx_status.signing_streams = NULL;
        mavlink_get_channel_status(LINK_CHAN)->signing = NULL;
        mavlink_get_channel_status(LINK_CHAN)->signing_streams = NULL;
        veh_say("link: signing off (SETUP_SIGNING from %u/%u)", (unsigned)m->sysid,
                (unsigned)m->compid);
        return;
    }
    veh_link_signing(r.secret_key, r.initial_timestamp);
    veh_say("link: signing on (SETUP_SIGNING from %u/%u)", (unsigned)m->sysid, (unsigned)m->compid);
}

static void on_message(veh_t *v, const mavlink_message_t *m)
{
    const mavlink_msg_entry_t *e = mavlink_get_msg_entry(m->msgid);

    v->c.link_rx_msgs++;
    /* a message addressed to another system or component is not ours, whatever it is (as
     * ArduPilot's routing: a mission upload for vehicle 2 must not load on vehicle 1) */
    if ((e != NULL) && ((e->flags & (uint8_t)MAV_MSG_ENTRY_FLAG_HAVE_TARGET_SYSTEM) != 0u)) {
        uint8_t comp = ((e->flags & (uint8_t)MAV_MSG_ENTRY_FLAG_HAVE_TARGET_COMPONENT) != 0u)
                           ? _MAV_RETURN_uint8_t(m, e->target_component_ofs)
                           : 0u;
        if (!for_us(v, _MAV_RETURN_uint8_t(m, e->target_system_ofs), comp)) {
            v->c.link_rx_ignored++;
            return;
        }
    }
    switch (m->msgid) {
    case MAVLINK_MSG_ID_HEARTBEAT:
        if (m->sysid == v->par.sysid) {
            break; /* our own id: not a ground station */
        }
        if (!g_link.gcs_seen) {
            g_link.gcs_seen = true;
            veh_say("link: ground station %u/%u connected", (unsigned)m->sysid,
                    (unsigned)m->compid);
        }
        g_link.gcs_last_us = veh_now();
        break;
    case MAVLINK_MSG_ID_COMMAND_LONG: {
        mavlink_command_long_t c;
        mavlink_msg_command_long_decode(m, &c);
        {
            const float p[3] = {c.param1, c.param2, c.param7};
            on_command(v, m, c.command, p);
        }
        break;
    }
    case MAVLINK_MSG_ID_COMMAND_INT: {
        mavlink_command_int_t c;
        mavlink_msg_command_int_decode(m, &c);
        if ((c.command == (uint16_t)MAV_CMD_NAV_TAKEOFF) &&
            (c.frame != (uint8_t)MAV_FRAME_GLOBAL_RELATIVE_ALT)) {
            /* as ArduCopter: the altitude is above home, any other frame is a bad parameter */
            veh_say("gcs: takeoff refused: frame %u (only GLOBAL_RELATIVE_ALT)", (unsigned)c.frame);
            ack(v, m->sysid, m->compid, c.command, (uint8_t)MAV_RESULT_DENIED);
        } else {
            const float p[3] = {c.param1, c.param2, c.z};
            on_command(v, m, c.command, p);
        }
        break;
    }
    case MAVLINK_MSG_ID_SET_MODE: {
        mavlink_set_mode_t c;
        mavlink_msg_set_mode_decode(m, &c);
        if ((c.base_mode & (uint8_t)MAV_MODE_FLAG_CUSTOM_MODE_ENABLED) != 0u) {
            const float p[3] = {(float)c.base_mode, (float)c.custom_mode, 0.0f};
            on_command(v, m, 0u, p);
        }
        break;
    }
    case MAVLINK_MSG_ID_PARAM_REQUEST_LIST: g_link.param_next = 0u; break;
    case MAVLINK_MSG_ID_FILE_TRANSFER_PROTOCOL: on_ftp(v, m); break;
    case MAVLINK_MSG_ID_SETUP_SIGNING: on_setup_signing(m); break;
    default:
        if (!veh_lparam_on_message(v, m) && !veh_mlink_on_message(v, m)) {
            v->c.link_rx_ignored++;
        }
        break;
    }
}

/* ---- entry points ------------------------------------------------------------------------ */

void veh_link_init(void)
{
    (void)memset(&g_link, 0, sizeof(g_link));
    (void)mt_bring_init(&g_link.rx, g_link.rx_store, (uint32_t)sizeof(g_link.rx_store));
    g_link.param_next = VEH_NPARAMS;
    veh_link_tx_init();
    veh_mlink_init();
}

void veh_link_signing(const uint8_t key[32], uint64_t timestamp)
{
    (void)memset(&g_sign, 0, sizeof(g_sign));
    (void)memset(&g_sign_streams, 0, sizeof(g_sign_streams));
    (void)memcpy(g_sign.secret_key, key, sizeof(g_sign.secret_key));
    g_sign.flags = (uint8_t)MAVLINK_SIGNING_FLAG_SIGN_OUTGOING;
    g_sign.link_id = (uint8_t)LINK_CHAN;
    g_sign.timestamp = timestamp;
    g_sign.accept_unsigned_callback = NULL; /* an unsigned frame is dropped, whatever it is */
    g_link.rx_status.signing = &g_sign;
    g_link.rx_status.signing_streams = &g_sign_streams;
    mavlink_get_channel_status(LINK_CHAN)->signing = &g_sign; /* every frame sent is signed */
    mavlink_get_channel_status(LINK_CHAN)->signing_streams = &g_sign_streams;
}

mt_bring_t *veh_link_rx(void)
{
    return &g_link.rx;
}

void veh_link_receive(veh_t *v)
{
    uint8_t buf[LINK_RX_PER_RUN];
    uint32_t n = mt_bring_read(&g_link.rx, buf, (uint32_t)sizeof(buf));
    uint32_t i;

    v->c.link_rx_bytes += n;
    for (i = 0u; i < n; i++) {
        mavlink_message_t m;
        mavlink_status_t st;
        uint8_t r = mavlink_frame_char_buffer(&g_link.rx_msg, &g_link.rx_status, buf[i], &m, &st);
        if (r == MAVLINK_FRAMING_OK) {
            v->c.link_rx_frame_bytes += mavlink_msg_get_send_buffer_length(&m);
            on_message(v, &m);
        } else if (r == MAVLINK_FRAMING_BAD_SIGNATURE) {
            v->c.link_rx_unsigned++; /* signing on: unsigned, wrong key or replayed */
        } else if (r != MAVLINK_FRAMING_INCOMPLETE) {
            v->c.link_rx_errors++; /* a whole frame dropped: bad CRC */
        }
    }
    veh_mlink_update(v);
    /* one answer or event per run, so a burst costs no run more than one message (two
     * STATUSTEXT chunks for a long line): a parameter of a list, else a reached item, else
     * a console line */
    if (g_link.param_next < VEH_NPARAMS) {
        veh_lparam_send(v, g_link.param_next);
        g_link.param_next++;
    } else if (!send_reached(v)) {
        send_said(v);
    }
}

void veh_link_stream(veh_t *v)
{
    veh_estimate_msg_t est;
    uint32_t r = g_link.stream_runs;

    g_link.stream_runs++;
    veh_latest(&v->gcs.est_sub, &est, (uint32_t)sizeof(est));
    /* 10 Hz: ATTITUDE; 5 Hz: GLOBAL_POSITION_INT and GPS_RAW_INT in turn; 1 Hz: HEARTBEAT,
     * SYS_STATUS, MISSION_CURRENT on different runs; events: MISSION_ITEM_REACHED and
     * the console lines */
    send_attitude(v, &est);
    if ((r % 2u) == 0u) {
        send_global_position(v, &est);
    } else {
        send_gps_raw(v);
    }
    switch (r % 10u) {
    case 0u: send_heartbeat(v); break;
    case 3u: send_sys_status(v, &est); break;
    case 6u: veh_mlink_send_current(v); break;
    default: break;
    }
}
