/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file baro.c
 * @brief The barometer: a driver run as a 1 kHz timer proc (reads the device
 *        over the shared bus and publishes each sample on the baro link) and
 *        baro_update (50 Hz, main loop): takes the samples, averages them,
 *        calibrates the ground pressure, gives the altitude and corrects the
 *        vertical estimate: a stage of the estimator (takes the newest
 *        `estimate`, corrects it, publishes it).
 */
#include "veh_int.h"

#define BUS_TIMEOUT_US 200u /* the timer proc never waits longer for the bus */
#define CAL_SAMPLES 1000u   /* one second of samples at boot */
#define K_POS 0.04f         /* vertical correction per 50 Hz run (time constant 1 s) */
#define K_VEL 0.02f

void veh_baro_timer_proc(void *arg)
{
    veh_t *v = (veh_t *)arg;
    uint8_t rx[4];
    veh_baro_sample_t smp;
    uint32_t word;

    if (!veh_bus_read(&v->bus, v->plat, VEH_DEV_BARO, 0u, rx, 4u, BUS_TIMEOUT_US)) {
        /* bus not obtained in time, or a device error */
        v->baro_bus_fail++;
        return;
    }
    word = ((uint32_t)rx[0] << 24) | ((uint32_t)rx[1] << 16) | ((uint32_t)rx[2] << 8) |
           (uint32_t)rx[3];
    smp.t_us = mt_port_now_us();
    smp.pressure_pa = (float)(word >> 12) * 0.125f;
    smp.temp_c = ((float)(word & 0xFFFu) * 0.1f) - 40.0f;
    if ((smp.pressure_pa < 30000.0f) || (smp.pressure_pa > 120000.0f)) {
        v->baro_bus_fail++; /* implausible reading: a failed read, not a sample */
        return;
    }
    veh_baro_link_publish(&v->baro_link, &smp);
}

void veh_baro_update(veh_t *v)
{
    veh_baro_t *b = &v->baro;
    veh_estimate_msg_t est;
    veh_baro_sample_t smp;
    float sum = 0.0f;
    uint32_t n = 0u;

    while (veh_baro_link_take(&v->baro_link, &smp)) {
        sum += smp.pressure_pa;
        n++;
    }
    v->c.baro_received += n;
    if (n == 0u) {
        return;
    }
    if (!b->ok) {
        b->cal_sum += sum;
        b->cal_n += n;
        if (b->cal_n >= CAL_SAMPLES) {
            b->p0 = b->cal_sum / (float)b->cal_n;
            b->ok = true;
            veh_latest(&b->est, &est, (uint32_t)sizeof(est));
            est.baro_ok = true;
            (void)mt_topic_publish(&v->estimate, &est, (uint32_t)sizeof(est));
        }
        return;
    }
    b->alt = 44330.77f * (1.0f - powf((sum / (float)n) / b->p0, 0.190263f));
    veh_latest(&b->est, &est, (uint32_t)sizeof(est));
    {
        float e = b->alt - (-est.pos[2]);
        est.pos[2] -= K_POS * e;
        est.vel[2] -= K_VEL * e;
    }
    (void)mt_topic_publish(&v->estimate, &est, (uint32_t)sizeof(est));
    if ((veh_log_runs(v) % 5u) == 0u) {
        uint8_t rec[16];
        int32_t alt_cm = (int32_t)lroundf(b->alt * 100.0f);
        uint32_t p8 = (uint32_t)((sum / (float)n) * 8.0f);
        uint64_t t = veh_now(); /* records carry the time they are written */
        uint32_t i;
        for (i = 0u; i < 8u; i++) {
            rec[i] = (uint8_t)(t >> (8u * i));
        }
        for (i = 0u; i < 4u; i++) {
            rec[8u + i] = (uint8_t)(p8 >> (8u * i));
            rec[12u + i] = (uint8_t)((uint32_t)alt_cm >> (8u * i));
        }
        veh_log_record(v, VEH_LOG_BARO, rec, 16u);
    }
}
