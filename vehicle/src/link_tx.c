/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file link_tx.c
 * @brief The ground-station link's transmit side: the byte ring the deployment drains
 *        (veh_link_tx, veh.h) and the one call every sender uses to put a whole MAVLink
 *        frame into it or count it as not sent.
 */
#include <string.h>

#include "link_int.h"

typedef struct {
    mt_bring_t tx;
    uint8_t tx_store[VEH_LINK_TX_BYTES];
} veh_link_tx_t;

static veh_link_tx_t g_tx;

/* the MAVLink library's channel status, shared by the link's files (link_int.h) */
mavlink_status_t m_mavlink_status[MAVLINK_COMM_NUM_BUFFERS];

void veh_link_tx_init(void)
{
    (void)memset(&g_tx, 0, sizeof(g_tx));
    (void)mt_bring_init(&g_tx.tx, g_tx.tx_store, (uint32_t)sizeof(g_tx.tx_store));
}

mt_bring_t *veh_link_tx(void)
{
    return &g_tx.tx;
}

void veh_link_send(veh_t *v, const mavlink_message_t *m)
{
    uint8_t buf[MAVLINK_MAX_PACKET_LEN];
    uint16_t n = mavlink_msg_to_send_buffer(buf, m);

    if (mt_bring_space(&g_tx.tx) < n) {
        v->c.telem_full++;
        return;
    }
    (void)mt_bring_write(&g_tx.tx, buf, n);
    v->c.telem_packets++;
    v->c.telem_bytes += n;
}

uint32_t veh_link_boot_ms(void)
{
    return (uint32_t)((veh_now() - veh_boot_us()) / 1000u);
}
