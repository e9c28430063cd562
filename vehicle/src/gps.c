/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file gps.c
 * @brief gps_update (10 Hz; the receiver gives 5 fixes a second): takes a new
 *        fix and corrects the horizontal position and velocity estimate: a
 *        stage of the estimator (takes the newest `estimate`, corrects it,
 *        publishes it).
 */
#include "veh_int.h"

#define K_POS 0.5f /* per fix */
#define K_VEL 0.5f
#define K_VD 0.3f
#define K_ALT 0.02f

void veh_gps_update(veh_t *v)
{
    veh_estimate_msg_t est;
    veh_estimate_msg_t *s = &est;
    veh_gps_fix_t f;
    float n;
    float e;
    float alt;
    int i;

    if (!v->plat->gps_read(v->plat->ctx, &f) || (f.fix < 3u)) {
        return;
    }
    veh_latest(&v->gps.est, &est, (uint32_t)sizeof(est));
    v->gps.fix = f;
    s->gps_fixes++;
    s->gps_last_us = f.t_us;
    vm_ne_from_ll(v->home.lat, v->home.lon, f.lat, f.lon, &n, &e);
    alt = (float)(f.alt_cm - v->home.alt_cm) * 0.01f;
    if (!s->pos_ok) {
        s->pos[0] = n;
        s->pos[1] = e;
        for (i = 0; i < 3; i++) {
            s->vel[i] = f.vel[i];
        }
        s->pos_ok = true;
    } else {
        s->pos[0] += K_POS * (n - s->pos[0]);
        s->pos[1] += K_POS * (e - s->pos[1]);
        s->vel[0] += K_VEL * (f.vel[0] - s->vel[0]);
        s->vel[1] += K_VEL * (f.vel[1] - s->vel[1]);
        s->vel[2] += K_VD * (f.vel[2] - s->vel[2]);
        s->pos[2] += K_ALT * ((-alt) - s->pos[2]);
    }
    (void)mt_topic_publish(&v->estimate, &est, (uint32_t)sizeof(est));
    {
        uint8_t rec[21];
        uint32_t w[3] = {(uint32_t)f.lat, (uint32_t)f.lon, (uint32_t)f.alt_cm};
        uint32_t k;
        uint32_t j;
        uint64_t t = veh_now(); /* records carry the time they are written */
        for (k = 0u; k < 8u; k++) {
            rec[k] = (uint8_t)(t >> (8u * k));
        }
        for (j = 0u; j < 3u; j++) {
            for (k = 0u; k < 4u; k++) {
                rec[8u + (4u * j) + k] = (uint8_t)(w[j] >> (8u * k));
            }
        }
        rec[20] = f.sats;
        veh_log_record(v, VEH_LOG_GPS, rec, 21u);
    }
}
