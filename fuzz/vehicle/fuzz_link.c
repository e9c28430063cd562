/* SPDX-License-Identifier: Apache-2.0 */
/*
 * libFuzzer target: the vehicle's MAVLink link (vehicle/src/link.c, mission_link.c, the
 * commands in gcs.c) fed through its receive ring, the whole vehicle running in simulated time
 * on the host port. First byte even: the rest is raw bytes on the link (framing, CRC, lengths,
 * noise). Odd: the rest is a list of messages, each a selector byte (one of the message ids the
 * vehicle handles), a length byte and payload bytes, sent as valid MAVLink 2 frames (so the
 * fuzzer reaches the handlers behind the CRC: parameters, mission protocol, commands, FTP).
 * Each input runs the main loop until the ring is drained and a few ticks more; the vehicle's
 * state carries over between inputs (as a long session with a misbehaving ground station).
 * ASan and UBSan find memory errors and undefined behaviour; the asserts below the invariants
 * of the link's rings.
 */
#include <assert.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "ardupilotmega/mavlink.h"
#include "mt/mt.h"
#include "mt_posix.h"
#include "simplat.h"
#include "startup.h"
#include "veh.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static simplat_t g_world; /* first member of the platform context (simplat.h) */
static veh_platform_t g_plat;
static veh_run_t g_run;

/* The port's sample wait in simulated time: 2.5 ms on, the timer procs (barometer, the work
 * queue's timer), the work queue (battery) and the IO procs (log) run meanwhile, so the
 * vehicle's pre-arm checks can pass and commands reach their flying paths. */
static uint64_t sample_wait(void *ctx)
{
    int k;

    (void)ctx;
    for (k = 0; k < 2; k++) {
        mt_posix_sim_advance(1250u);
        (void)mt_proc_dispatch(veh_timer_procs());
        (void)mt_wq_run_pending(veh_work_queue(), MT_CFG_WQ_MAX_ITEMS);
        (void)mt_proc_dispatch(veh_io_procs());
    }
    return mt_port_now_us();
}

static void sink_text(void *ctx, const char *s, size_t n)
{
    (void)ctx;
    (void)s;
    (void)n;
}

static void sink_log(void *ctx, const uint8_t *d, uint32_t n)
{
    (void)ctx;
    (void)d;
    (void)n;
}

static veh_gcs_cmd_t no_event(void *ctx)
{
    (void)ctx;
    return VEH_GCS_NONE;
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    veh_home_t home = {465197000, 65657000, 40000};
    uint32_t bad = 0u;

    (void)argc;
    (void)argv;
    mt_posix_sim_enable(1000000u);
    simplat_init(&g_world, &home, 1u, sample_wait, NULL);
    memset(&g_plat, 0, sizeof(g_plat));
    g_plat.console = sink_text;
    g_plat.log_sink = sink_log;
    g_plat.gcs_poll = no_event;
    g_run.timeout_us = UINT64_MAX;
    g_run.gcs_session = true;
    (void)veh_run_start(&g_run, &g_plat, &g_world, &home, NULL, 0u, &bad);
    return 0;
}

/* the messages the vehicle handles, for the structured form */
static const uint32_t k_ids[] = {
    MAVLINK_MSG_ID_HEARTBEAT,          MAVLINK_MSG_ID_PARAM_REQUEST_LIST,
    MAVLINK_MSG_ID_PARAM_REQUEST_READ, MAVLINK_MSG_ID_PARAM_SET,
    MAVLINK_MSG_ID_COMMAND_LONG,       MAVLINK_MSG_ID_COMMAND_INT,
    MAVLINK_MSG_ID_SET_MODE,           MAVLINK_MSG_ID_MISSION_COUNT,
    MAVLINK_MSG_ID_MISSION_ITEM_INT,   MAVLINK_MSG_ID_MISSION_ITEM,
    MAVLINK_MSG_ID_MISSION_REQUEST_LIST, MAVLINK_MSG_ID_MISSION_REQUEST_INT,
    MAVLINK_MSG_ID_MISSION_REQUEST,    MAVLINK_MSG_ID_MISSION_ACK,
    MAVLINK_MSG_ID_MISSION_CLEAR_ALL,  MAVLINK_MSG_ID_MISSION_SET_CURRENT,
    MAVLINK_MSG_ID_FILE_TRANSFER_PROTOCOL, MAVLINK_MSG_ID_SYSTEM_TIME,
};

/* One main-loop tick; what the vehicle sent is read and dropped (the ground station). */
static void tick(void)
{
    uint8_t sink[512];

    veh_loop_once(simplat_wait, &g_world);
    while (mt_bring_read(veh_link_tx(), sink, (uint32_t)sizeof(sink)) > 0u) {
    }
}

/* Feed bytes to the receive ring, one tick per ring's worth. */
static void feed(const uint8_t *p, size_t n)
{
    mt_bring_t *rx = veh_link_rx();

    while (n > 0u) {
        uint32_t w = mt_bring_write(rx, p, (n > 4096u) ? 4096u : (uint32_t)n);
        p += w;
        n -= w;
        tick();
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint8_t frame[MAVLINK_MAX_PACKET_LEN];
    size_t i = 1u;
    int k;

    if (size == 0u) {
        return 0;
    }
    if ((data[0] & 1u) == 0u) {
        feed(data + 1, size - 1u);
    } else {
        while (i + 2u <= size) {
            const mavlink_msg_entry_t *e;
            mavlink_message_t m;
            uint8_t len = data[i + 1u];
            uint16_t n;

            memset(&m, 0, sizeof(m));
            m.msgid = k_ids[data[i] % (sizeof(k_ids) / sizeof(k_ids[0]))];
            e = mavlink_get_msg_entry(m.msgid);
            i += 2u;
            if (e == NULL) {
                continue;
            }
            if (len > e->max_msg_len) {
                len = e->max_msg_len;
            }
            if ((size_t)len > size - i) {
                len = (uint8_t)(size - i);
            }
            memcpy(_MAV_PAYLOAD_NON_CONST(&m), data + i, len);
            i += len;
            /* addressed to the vehicle (1/1), so the handlers past the link's target check see
             * the input, unless the selector byte's top bit keeps the payload's own target */
            if (((data[i - len - 2u] & 0x80u) == 0u) &&
                ((e->flags & MAV_MSG_ENTRY_FLAG_HAVE_TARGET_SYSTEM) != 0u)) {
                _MAV_PAYLOAD_NON_CONST(&m)[e->target_system_ofs] = 1;
                if ((e->flags & MAV_MSG_ENTRY_FLAG_HAVE_TARGET_COMPONENT) != 0u) {
                    _MAV_PAYLOAD_NON_CONST(&m)[e->target_component_ofs] = 1;
                }
            }
            /* from a ground station (255/190) */
            (void)mavlink_finalize_message_chan(&m, 255u, 190u, MAVLINK_COMM_1, e->min_msg_len,
                                                e->max_msg_len, e->crc_extra);
            n = mavlink_msg_to_send_buffer(frame, &m);
            feed(frame, n);
        }
    }
    for (k = 0; k < 8; k++) {
        tick(); /* the rest of the ring parsed (280 bytes per tick), the answers sent */
    }
    assert(mt_bring_valid(veh_link_rx()) && mt_bring_valid(veh_link_tx()));
    return 0;
}
