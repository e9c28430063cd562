/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file baro_link.h
 * @brief The barometer hand-off: the driver (timer proc, 1 kHz) publishes
 *        samples, the main loop takes them. The one place that knows how
 *        samples cross threads (today an object ring, mt/objring.h; a topic
 *        of the message bus later): the driver and its consumer only see this
 *        interface.
 *
 * Rules: one publisher thread, one consumer thread. A full link drops its
 * oldest sample (the newest pressure matters most) and counts it.
 */
#ifndef VEH_BARO_LINK_H
#define VEH_BARO_LINK_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/objring.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    uint64_t t_us;
    float pressure_pa;
    float temp_c;
} veh_baro_sample_t;

/** Samples the link holds: 20 arrive per 50 Hz consumer run, with room for a late run. */
#define VEH_BARO_LINK_CAP 64u

typedef struct {
    mt_oring_t ring;
    uint8_t store[MT_ORING_STORAGE_BYTES(sizeof(veh_baro_sample_t), VEH_BARO_LINK_CAP)];
    uint32_t published; /**< written by the publisher only */
    uint32_t dropped;   /**< publisher side: pushes into a full link (the oldest goes) */
    uint32_t refused;   /**< publisher side: pushes refused (consumer behind since the last drop) */
} veh_baro_link_t;

/** Set up an empty link. @retval MT_OK */
mt_status_t veh_baro_link_init(veh_baro_link_t *l);

/** Publisher: hand a sample over (never blocks). */
void veh_baro_link_publish(veh_baro_link_t *l, const veh_baro_sample_t *s);

/** Consumer: the oldest sample not taken yet; false when there is none. */
bool veh_baro_link_take(veh_baro_link_t *l, veh_baro_sample_t *s);

/** Consumer: samples discarded as the oldest of a full link (consumer side count). */
uint32_t veh_baro_link_lost(veh_baro_link_t *l);

#ifdef __cplusplus
}
#endif

#endif /* VEH_BARO_LINK_H */
