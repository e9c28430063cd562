/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file battery.c
 * @brief The battery monitor: an interval work item (3 Hz) on the vehicle's
 *        work queue reads the monitor over the shared sensor bus and publishes
 *        each reading on the `battery` topic; housekeeping (main loop)
 *        consumes the readings (house.c; its subscription is set up by the
 *        topology, vehicle.c).
 *
 * The work item runs in the queue's thread (hal_posix, hal_chibios) or, in
 * simulated time, in the main loop's idle time (vehicle/deploy/sitl). It
 * touches only the sensor bus (under its semaphore), the topic (under the
 * kernel lock) and its own failure count: the vehicle state belongs to the
 * main loop.
 */
#include "veh_int.h"

#define BAT_BUS_TIMEOUT_US 2000u

static const mt_topic_desc_t g_battery_desc =
    MT_TOPIC_DESC("battery", veh_battery_msg_t, VEH_BATTERY_QUEUE, 0u);

/* The run function of the work item (argument: the vehicle). */
static void battery_work(void *arg)
{
    veh_t *v = (veh_t *)arg;
    uint8_t rx[4];

    if (veh_bus_read(&v->bus, v->plat, VEH_DEV_BATT, 0u, rx, 4u, BAT_BUS_TIMEOUT_US)) {
        veh_battery_msg_t m;
        uint32_t w = ((uint32_t)rx[0] << 24) | ((uint32_t)rx[1] << 16) | ((uint32_t)rx[2] << 8) |
                     (uint32_t)rx[3];
        m.t_us = mt_port_now_us();
        m.mv = w >> 16;
        m.ca = w & 0xFFFFu;
        /* a plain topic of this message size accepts every publish; a refusal
         * would be counted in the topic's `rejected` (the summary prints it) */
        (void)mt_topic_publish(&v->battery_topic, &m, (uint32_t)sizeof(m));
    } else {
        v->battery_read_fail++;
    }
}

mt_status_t veh_battery_init(veh_t *v)
{
    mt_status_t st = mt_topic_init(&v->battery_topic, &g_battery_desc, v->battery_store,
                                   (uint32_t)sizeof(v->battery_store));
    if (st != MT_OK) {
        return st;
    }
    mt_wq_init(&v->wq, "veh_lp", MT_PRIO_IO, 1);
    mt_work_init(&v->battery_work, battery_work, v);
    st = mt_wq_attach(&v->wq, &v->battery_work);
    if (st == MT_OK) {
        st = mt_work_schedule_interval(&v->battery_work, VEH_BATTERY_PERIOD_US, 0u);
    }
    return st;
}
