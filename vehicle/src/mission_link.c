/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mission_link.c
 * @brief The MAVLink mission protocol (link.c hands it the messages): upload
 *        (MISSION_COUNT, the vehicle's MISSION_REQUEST_INT for each item,
 *        MISSION_ITEM_INT or MISSION_ITEM, MISSION_ACK), download
 *        (MISSION_REQUEST_LIST, MISSION_COUNT, MISSION_REQUEST_INT or
 *        MISSION_REQUEST, MISSION_ITEM_INT), MISSION_CLEAR_ALL,
 *        MISSION_SET_CURRENT, and MISSION_CURRENT.
 *
 * The protocol follows ArduPilot's (GCS_MAVLink MissionItemProtocol): one
 * upload at a time, from the system that started it (another gets DENIED; the
 * same one may restart with a new count); an item out of sequence gets
 * INVALID_SEQUENCE and the upload goes on; the vehicle asks again for an item
 * after 1 s without it and cancels the upload (OPERATION_CANCELLED) after 8 s;
 * a count of 0 clears the mission; a download during an upload is DENIED;
 * clearing a running mission is an ERROR.
 *
 * Unlike ArduPilot, which writes each item into the mission as it arrives, an
 * upload is staged, converted item by item with the mission file library's
 * rules (mt_item_to_cmd: the same as a .waypoints or .plan file), validated whole
 * by the kernel (mt_mission_check), and only then applied (mt_mission_load, or mt_mission_replace); a
 * rejected upload gets the matching MAV_MISSION_RESULT, a STATUSTEXT with the
 * item index and the reason, and the mission on board stays as it was. A
 * valid upload while the mission runs replaces it in flight, as ArduPilot
 * allows (mt_mission_replace, between two sequencer updates): the vehicle
 * goes on at the same item (started again, as ArduPilot's AUTO restarts the
 * current command when the mission changed) when the new mission has that
 * index, and otherwise holds position (LOITER) and says so.
 */
#include <math.h>
#include <string.h>

#include "item.h"
#include "link_int.h"

#define MLINK_RETRY_US 1000000u   /* ask again for an item after 1 s without it */
#define MLINK_TIMEOUT_US 8000000u /* cancel an upload after 8 s without an item */

typedef struct {
    bool receiving;
    uint16_t count; /* items announced */
    uint16_t next;  /* next item expected */
    uint8_t peer_sys;
    uint8_t peer_comp;
    uint64_t last_item_us;
    uint64_t last_request_us;
    mt_mission_cmd_t cmds[MT_CFG_MISSION_MAX_CMDS]; /* the upload, staged */
} veh_mlink_t;

static veh_mlink_t g_ml;

void veh_mlink_init(void)
{
    (void)memset(&g_ml, 0, sizeof(g_ml));
}

/* ---- sending ------------------------------------------------------------------------------- */

static void send_ack(veh_t *v, uint8_t sys, uint8_t comp, uint8_t result)
{
    mavlink_message_t m;

    (void)mavlink_msg_mission_ack_pack_chan(v->par.sysid, VEH_LINK_COMPID, VEH_LINK_CHAN, &m, sys,
                                            comp, result, (uint8_t)MAV_MISSION_TYPE_MISSION);
    veh_link_send(v, &m);
}

static void send_request(veh_t *v)
{
    mavlink_message_t m;

    (void)mavlink_msg_mission_request_int_pack_chan(v->par.sysid, VEH_LINK_COMPID, VEH_LINK_CHAN,
                                                    &m, g_ml.peer_sys, g_ml.peer_comp, g_ml.next,
                                                    (uint8_t)MAV_MISSION_TYPE_MISSION);
    veh_link_send(v, &m);
    g_ml.last_request_us = veh_now();
}

void veh_mlink_send_current(veh_t *v)
{
    mavlink_message_t m;
    const mt_mission_t *mi = &v->mission;
    uint8_t state;
    uint16_t total = (mi->total > 0u) ? (uint16_t)(mi->total - 1u) : 0u; /* home excluded */
    uint16_t seq = (mi->nav != MT_MISSION_NONE) ? mi->nav : 0u;

    if (mi->total <= 1u) {
        state = (uint8_t)MISSION_STATE_NO_MISSION;
    } else if (mi->state == MT_MISSION_RUNNING) {
        state = (uint8_t)MISSION_STATE_ACTIVE;
    } else if (mi->state == MT_MISSION_COMPLETE) {
        state = (uint8_t)MISSION_STATE_COMPLETE;
    } else {
        state = (uint8_t)MISSION_STATE_NOT_STARTED;
    }
    (void)mavlink_msg_mission_current_pack_chan(v->par.sysid, VEH_LINK_COMPID, VEH_LINK_CHAN, &m,
                                                seq, total, state,
                                                (v->fl.mode == VEH_MODE_AUTO) ? 1u : 2u);
    veh_link_send(v, &m);
}

/* Command i of the mission on board as MISSION_ITEM_INT (params back from fixed point, z in
 * metres). */
static void send_item(veh_t *v, uint8_t sys, uint8_t comp, uint16_t i)
{
    mavlink_message_t m;
    mt_mission_cmd_t c;
    bool current = false;
    float p[4];
    uint32_t k;

    (void)mt_mission_get(&v->mission, i, &c, &current);
    for (k = 0u; k < 4u; k++) {
        p[k] = (c.param[k] == MT_MISSION_PARAM_NAN) ? NAN
                                                    : (float)c.param[k] / (float)MT_MISSION_MILLI;
    }
    (void)mavlink_msg_mission_item_int_pack_chan(
        v->par.sysid, VEH_LINK_COMPID, VEH_LINK_CHAN, &m, sys, comp, i, c.frame, c.id,
        current ? 1u : 0u, (uint8_t)(c.options & 1u), p[0], p[1], p[2], p[3], c.x, c.y,
        (float)c.z / 100.0f, (uint8_t)MAV_MISSION_TYPE_MISSION);
    veh_link_send(v, &m);
}

/* ---- upload -------------------------------------------------------------------------------- */

static void upload_end(void)
{
    g_ml.receiving = false;
}

/* MAV_MISSION_RESULT of a file-layer rejection (mt_item_to_cmd: fields 3 frame, 4 command,
 * 5..11 param1..4, x, y, z). */
static uint8_t result_of_item(const mt_item_fault_t *f)
{
    if (f->st == MT_E_MISSION_FRAME) {
        return (uint8_t)MAV_MISSION_UNSUPPORTED_FRAME;
    }
    if (f->st == MT_E_MISSION_CMD) {
        return (uint8_t)MAV_MISSION_UNSUPPORTED;
    }
    if ((f->field >= 5u) && (f->field <= 11u)) {
        return (uint8_t)((uint32_t)MAV_MISSION_INVALID_PARAM1 + (f->field - 5u));
    }
    return (uint8_t)MAV_MISSION_INVALID;
}

/* MAV_MISSION_RESULT of the kernel's whole-mission rejection of command c. */
static uint8_t result_of_mission(mt_status_t st, const mt_mission_cmd_t *c)
{
    switch (st) {
    case MT_E_MISSION_CMD: return (uint8_t)MAV_MISSION_UNSUPPORTED;
    case MT_E_MISSION_FRAME: return (uint8_t)MAV_MISSION_UNSUPPORTED_FRAME;
    case MT_E_MISSION_LOCATION:
        return (uint8_t)(((c->x < -900000000) || (c->x > 900000000))
                             ? MAV_MISSION_INVALID_PARAM5_X
                             : MAV_MISSION_INVALID_PARAM6_Y);
    case MT_E_MISSION_SIZE: return (uint8_t)MAV_MISSION_NO_SPACE;
    default: return (uint8_t)MAV_MISSION_INVALID;
    }
}

/* All items are in: validated whole and applied by one kernel call (or said
 * why not). A mission that runs is replaced in flight (mt_mission_replace,
 * between two sequencer updates: this task and the sequencer's run on one
 * thread): the vehicle goes on at the same item when the new mission has it,
 * and holds position (LOITER) and says so when it does not. Otherwise it is
 * loaded (mt_mission_load). Either call checks the whole list first and
 * changes nothing when it is refused. */
static void upload_complete(veh_t *v)
{
    uint16_t bad = MT_MISSION_NONE;
    uint16_t n = g_ml.count;
    bool running = v->mission.state == MT_MISSION_RUNNING;
    uint16_t at = v->mission.nav_idx;
    mt_status_t st = running ? mt_mission_replace(&v->mission, g_ml.cmds, n, &bad)
                             : mt_mission_load(&v->mission, g_ml.cmds, n, &bad);

    upload_end();
    if (st != MT_OK) {
        const mt_mission_cmd_t *c = &g_ml.cmds[(bad < n) ? bad : 0u];
        veh_say("mission upload rejected: item %u: %s", (unsigned)bad, mt_status_str(st));
        send_ack(v, g_ml.peer_sys, g_ml.peer_comp, result_of_mission(st, c));
        return;
    }
    v->mission_ok = n >= 2u;
    v->mission_st = v->mission_ok ? MT_OK : MT_E_EMPTY;
    if (!running) {
        veh_say("mission: %u items uploaded", (unsigned)n);
    } else if (v->mission.state == MT_MISSION_STOPPED) {
        veh_set_mode(v, VEH_MODE_HOLD);
        veh_say("mission replaced in flight (%u items): #%u is gone, holding", (unsigned)n,
                (unsigned)at);
    } else {
        veh_say("mission replaced in flight (%u items): continuing at #%u", (unsigned)n,
                (unsigned)at);
    }
    send_ack(v, g_ml.peer_sys, g_ml.peer_comp, (uint8_t)MAV_MISSION_ACCEPTED);
}

static void on_count(veh_t *v, const mavlink_message_t *msg)
{
    mavlink_mission_count_t r;

    mavlink_msg_mission_count_decode(msg, &r);
    if (r.mission_type != (uint8_t)MAV_MISSION_TYPE_MISSION) {
        veh_say("mission upload: only missions (no fence or rally points)");
        send_ack(v, msg->sysid, msg->compid, (uint8_t)MAV_MISSION_UNSUPPORTED);
        return;
    }
    if (g_ml.receiving && ((msg->sysid != g_ml.peer_sys) || (msg->compid != g_ml.peer_comp))) {
        send_ack(v, msg->sysid, msg->compid, (uint8_t)MAV_MISSION_DENIED);
        return;
    }
    if (r.count > MT_CFG_MISSION_MAX_CMDS) {
        upload_end();
        veh_say("mission upload: only %u items are supported", (unsigned)MT_CFG_MISSION_MAX_CMDS);
        send_ack(v, msg->sysid, msg->compid, (uint8_t)MAV_MISSION_NO_SPACE);
        return;
    }
    g_ml.peer_sys = msg->sysid;
    g_ml.peer_comp = msg->compid;
    g_ml.count = r.count;
    g_ml.next = 0u;
    g_ml.last_item_us = veh_now();
    if (r.count == 0u) {
        /* ArduPilot: a count of 0 clears the mission (home stays) */
        if (v->mission.total == 0u) {
            send_ack(v, msg->sysid, msg->compid, (uint8_t)MAV_MISSION_ACCEPTED);
            return;
        }
        g_ml.cmds[0] = v->mission.cmd[0];
        g_ml.count = 1u;
        upload_complete(v);
        return;
    }
    g_ml.receiving = true;
    send_request(v);
}

/* One item in MISSION_ITEM_INT form (MISSION_ITEM is converted to it), as the file library's
 * item: the same conversion and checks as a mission file. */
static void on_item(veh_t *v, const mavlink_message_t *msg, const mavlink_mission_item_int_t *it)
{
    mt_wpl_item_t w;
    mt_item_fault_t f;
    mt_status_t st;

    if (!g_ml.receiving || (it->mission_type != (uint8_t)MAV_MISSION_TYPE_MISSION)) {
        v->c.link_rx_ignored++;
        return;
    }
    if ((msg->sysid != g_ml.peer_sys) || (msg->compid != g_ml.peer_comp)) {
        send_ack(v, msg->sysid, msg->compid, (uint8_t)MAV_MISSION_DENIED);
        return;
    }
    if (it->seq != g_ml.next) {
        send_ack(v, msg->sysid, msg->compid, (uint8_t)MAV_MISSION_INVALID_SEQUENCE);
        return; /* the upload goes on: the item is asked for again */
    }
    (void)memset(&w, 0, sizeof(w));
    w.seq = it->seq;
    w.current = it->current;
    w.frame = it->frame;
    w.command = it->command;
    w.p[0] = (double)it->param1;
    w.p[1] = (double)it->param2;
    w.p[2] = (double)it->param3;
    w.p[3] = (double)it->param4;
    w.p[4] = (double)it->x * 1e-7;
    w.p[5] = (double)it->y * 1e-7;
    w.p[6] = (double)it->z;
    w.autocontinue = it->autocontinue;
    st = mt_item_to_cmd(&w, &g_ml.cmds[it->seq], &f);
    if (st != MT_OK) {
        upload_end();
        veh_say("mission upload rejected: item %u: %s: %s", (unsigned)it->seq,
                mt_item_field_name(f.field), mt_item_why_str(f.why));
        send_ack(v, msg->sysid, msg->compid, result_of_item(&f));
        return;
    }
    g_ml.next++;
    g_ml.last_item_us = veh_now();
    if (g_ml.next == g_ml.count) {
        upload_complete(v);
    } else {
        send_request(v);
    }
}

/* ---- download and the rest ----------------------------------------------------------------- */

static void on_request(veh_t *v, const mavlink_message_t *msg, uint16_t seq, uint8_t type)
{
    if (type != (uint8_t)MAV_MISSION_TYPE_MISSION) {
        send_ack(v, msg->sysid, msg->compid, (uint8_t)MAV_MISSION_UNSUPPORTED);
    } else if (g_ml.receiving) {
        send_ack(v, msg->sysid, msg->compid, (uint8_t)MAV_MISSION_DENIED);
    } else if (seq >= v->mission.total) {
        send_ack(v, msg->sysid, msg->compid, (uint8_t)MAV_MISSION_INVALID_SEQUENCE);
    } else {
        send_item(v, msg->sysid, msg->compid, seq);
    }
}

static void on_request_list(veh_t *v, const mavlink_message_t *msg)
{
    mavlink_mission_request_list_t r;
    mavlink_message_t m;

    mavlink_msg_mission_request_list_decode(msg, &r);
    if (r.mission_type != (uint8_t)MAV_MISSION_TYPE_MISSION) {
        send_ack(v, msg->sysid, msg->compid, (uint8_t)MAV_MISSION_UNSUPPORTED);
        return;
    }
    if (g_ml.receiving) {
        send_ack(v, msg->sysid, msg->compid, (uint8_t)MAV_MISSION_DENIED);
        return;
    }
    (void)mavlink_msg_mission_count_pack_chan(v->par.sysid, VEH_LINK_COMPID, VEH_LINK_CHAN, &m,
                                              msg->sysid, msg->compid, v->mission.total,
                                              (uint8_t)MAV_MISSION_TYPE_MISSION);
    veh_link_send(v, &m);
}

static void on_clear_all(veh_t *v, const mavlink_message_t *msg)
{
    mavlink_mission_clear_all_t r;
    mt_mission_cmd_t home[1];
    uint16_t bad = MT_MISSION_NONE;

    mavlink_msg_mission_clear_all_decode(msg, &r);
    if (r.mission_type != (uint8_t)MAV_MISSION_TYPE_MISSION) {
        send_ack(v, msg->sysid, msg->compid, (uint8_t)MAV_MISSION_UNSUPPORTED);
        return;
    }
    if (g_ml.receiving || (v->mission.state == MT_MISSION_RUNNING)) {
        veh_say("mission clear refused: %s",
                g_ml.receiving ? "an upload is under way" : "the mission is running");
        send_ack(v, msg->sysid, msg->compid, (uint8_t)MAV_MISSION_ERROR);
        return;
    }
    if (v->mission.total > 0u) {
        home[0] = v->mission.cmd[0]; /* home stays */
        (void)mt_mission_load(&v->mission, home, 1u, &bad);
    }
    v->mission_ok = false;
    v->mission_st = MT_E_EMPTY;
    veh_say("mission: cleared");
    send_ack(v, msg->sysid, msg->compid, (uint8_t)MAV_MISSION_ACCEPTED);
}

static void on_set_current(veh_t *v, const mavlink_message_t *msg)
{
    mavlink_mission_set_current_t r;
    mt_status_t st;

    mavlink_msg_mission_set_current_decode(msg, &r);
    st = mt_mission_set_current(&v->mission, r.seq);
    if (st == MT_OK) {
        veh_say("mission: current item set to #%u", (unsigned)r.seq);
    } else {
        veh_say("mission: set current #%u refused (%s)", (unsigned)r.seq, mt_status_str(st));
    }
    veh_mlink_send_current(v);
}

bool veh_mlink_on_message(veh_t *v, const mavlink_message_t *m)
{
    switch (m->msgid) {
    case MAVLINK_MSG_ID_MISSION_COUNT: on_count(v, m); break;
    case MAVLINK_MSG_ID_MISSION_ITEM_INT: {
        mavlink_mission_item_int_t it;
        mavlink_msg_mission_item_int_decode(m, &it);
        on_item(v, m, &it);
        break;
    }
    case MAVLINK_MSG_ID_MISSION_ITEM: {
        /* the float form: x and y in degrees */
        mavlink_mission_item_t f;
        mavlink_mission_item_int_t it;
        mavlink_msg_mission_item_decode(m, &f);
        (void)memset(&it, 0, sizeof(it));
        it.seq = f.seq;
        it.frame = f.frame;
        it.command = f.command;
        it.current = f.current;
        it.autocontinue = f.autocontinue;
        it.param1 = f.param1;
        it.param2 = f.param2;
        it.param3 = f.param3;
        it.param4 = f.param4;
        it.x = (int32_t)lround((double)f.x * 1e7);
        it.y = (int32_t)lround((double)f.y * 1e7);
        it.z = f.z;
        it.mission_type = f.mission_type;
        on_item(v, m, &it);
        break;
    }
    case MAVLINK_MSG_ID_MISSION_REQUEST_LIST: on_request_list(v, m); break;
    case MAVLINK_MSG_ID_MISSION_REQUEST_INT: {
        mavlink_mission_request_int_t r;
        mavlink_msg_mission_request_int_decode(m, &r);
        on_request(v, m, r.seq, r.mission_type);
        break;
    }
    case MAVLINK_MSG_ID_MISSION_REQUEST: {
        mavlink_mission_request_t r;
        mavlink_msg_mission_request_decode(m, &r);
        on_request(v, m, r.seq, r.mission_type);
        break;
    }
    case MAVLINK_MSG_ID_MISSION_ACK: break; /* the end of a download */
    case MAVLINK_MSG_ID_MISSION_CLEAR_ALL: on_clear_all(v, m); break;
    case MAVLINK_MSG_ID_MISSION_SET_CURRENT: on_set_current(v, m); break;
    default: return false;
    }
    return true;
}

void veh_mlink_update(veh_t *v)
{
    uint64_t now;

    if (!g_ml.receiving) {
        return;
    }
    now = veh_now();
    if ((now - g_ml.last_item_us) > MLINK_TIMEOUT_US) {
        upload_end();
        veh_say("mission upload cancelled: no item #%u for 8 s", (unsigned)g_ml.next);
        send_ack(v, g_ml.peer_sys, g_ml.peer_comp, (uint8_t)MAV_MISSION_OPERATION_CANCELLED);
    } else if ((now - g_ml.last_request_us) > MLINK_RETRY_US) {
        send_request(v);
    }
}
