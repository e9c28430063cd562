/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file link_int.h
 * @brief Internal to the ground-station link's files: the generated MAVLink headers, the
 *        transmit primitive (link_tx.c), the parameters (link_param.c) and the mission
 *        protocol (mission_link.c). Calls go link.c -> link_param.c -> link_tx.c,
 *        link.c -> mission_link.c -> link_tx.c and link.c -> link_tx.c (no cycle).
 */
#ifndef VEH_LINK_INT_H
#define VEH_LINK_INT_H

#include "veh_int.h"

/* the generated headers: build output ($(BUILD)/mavlink), included as system headers. One
 * channel status for every file that packs messages (link_tx.c defines it): the library keeps
 * a private one per translation unit otherwise, and each file would number its own frames
 * (the sequence a ground station counts lost packets by). The library's mechanism and name. */
#define MAVLINK_EXTERNAL_RX_STATUS
#include "mavlink_types.h"
extern mavlink_status_t m_mavlink_status[MAVLINK_COMM_NUM_BUFFERS];
#include "ardupilotmega/mavlink.h"

#define VEH_LINK_COMPID MAV_COMP_ID_AUTOPILOT1
#define VEH_LINK_CHAN MAVLINK_COMM_0

/* ---- link_tx.c: the transmit ring ---- */
void veh_link_tx_init(void);
/** The frame of m into the transmit ring, whole or not at all (counted in telem_full). */
void veh_link_send(veh_t *v, const mavlink_message_t *m);
/** Milliseconds since boot (the time fields of the streams). */
uint32_t veh_link_boot_ms(void);

/* ---- link_param.c: the parameters ---- */
/** PARAM_VALUE of parameter i (< VEH_NPARAMS). */
void veh_lparam_send(veh_t *v, uint32_t i);
/** PARAM_REQUEST_READ or PARAM_SET (link.c checked its target): handled here (true), or not
 *  one (false). */
bool veh_lparam_on_message(veh_t *v, const mavlink_message_t *m);

/* ---- mission_link.c: the mission protocol ---- */
void veh_mlink_init(void);
/** A mission-protocol message (count, items, requests, ack, clear, set current): handled
 *  here (true), or not one (false). */
bool veh_mlink_on_message(veh_t *v, const mavlink_message_t *m);
/** Each gcs_update: an upload's re-request (1 s without the item) and timeout (8 s). */
void veh_mlink_update(veh_t *v);
/** MISSION_CURRENT as ArduPilot fills it. */
void veh_mlink_send_current(veh_t *v);

#endif /* VEH_LINK_INT_H */
