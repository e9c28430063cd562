/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file baro_link.c
 * @brief Barometer hand-off over an object ring (see baro_link.h).
 */
#include "baro_link.h"

mt_status_t veh_baro_link_init(veh_baro_link_t *l)
{
    l->published = 0u;
    l->dropped = 0u;
    l->refused = 0u;
    return mt_oring_init(&l->ring, l->store, (uint32_t)sizeof(veh_baro_sample_t),
                         VEH_BARO_LINK_CAP);
}

void veh_baro_link_publish(veh_baro_link_t *l, const veh_baro_sample_t *s)
{
    mt_status_t st = mt_oring_push_drop_oldest(&l->ring, s);

    if (st == MT_W_DROPPED_OLDEST) {
        l->dropped++;
    } else if (st == MT_E_FULL) {
        l->refused++; /* the consumer has not caught up since the last drop */
    } else {
        /* stored */
    }
    l->published++;
}

bool veh_baro_link_take(veh_baro_link_t *l, veh_baro_sample_t *s)
{
    return mt_oring_pop(&l->ring, s) == MT_OK;
}

uint32_t veh_baro_link_lost(veh_baro_link_t *l)
{
    return l->ring.lost;
}
