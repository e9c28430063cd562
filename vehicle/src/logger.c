/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file logger.c
 * @brief The binary log: records are written by the main loop into a byte
 *        ring (mt/ring.h) and drained by an IO proc into the platform's log
 *        sink (a file in SITL). log_write (50 Hz) writes the attitude and
 *        controller records (from the `estimate` and `att_sp` topics), and the
 *        position at 10 Hz; other components add GPS, barometer, battery,
 *        mission and event records.
 *
 * Record: 'M' 'T' type len payload[len] sum, sum = (type + len + payload
 * bytes) mod 256; integers little-endian; every payload starts with the
 * time in us (uint64). A record that does not fit in the ring is dropped
 * whole and counted (never a partial record).
 */
#include <string.h>

#include "veh_int.h"

#define LOG_MAX_PAYLOAD 64u

void veh_log_init(veh_t *v)
{
    (void)mt_bring_init(&v->log, v->log_store, (uint32_t)sizeof(v->log_store));
}

void veh_log_record(veh_t *v, uint8_t type, const uint8_t *payload, uint8_t len)
{
    uint8_t rec[LOG_MAX_PAYLOAD + 5u];
    uint32_t n = (uint32_t)len + 5u;
    uint32_t fill;
    uint8_t sum;
    uint32_t i;

    if (len > LOG_MAX_PAYLOAD) {
        v->c.log_dropped++;
        return;
    }
    if (mt_bring_space(&v->log) < n) {
        v->c.log_dropped++;
        return;
    }
    rec[0] = 0x4Du;
    rec[1] = 0x54u;
    rec[2] = type;
    rec[3] = len;
    sum = (uint8_t)(type + len);
    for (i = 0u; i < len; i++) {
        rec[4u + i] = payload[i];
        sum = (uint8_t)(sum + payload[i]);
    }
    rec[4u + len] = sum;
    /* only this (producer) side can shrink the space: the whole record fits; zero-copy
     * (reserve, copy into the ring's segments, commit) */
    {
        mt_iovec_t vec[2];
        uint32_t segs = mt_bring_reserve(&v->log, vec, n);
        uint32_t off = 0u;
        for (i = 0u; i < segs; i++) {
            memcpy(vec[i].base, &rec[off], vec[i].len);
            off += vec[i].len;
        }
        (void)mt_bring_commit(&v->log, off);
    }
    v->c.log_records++;
    fill = (uint32_t)sizeof(v->log_store) - mt_bring_space(&v->log);
    if (fill > v->c.log_max_fill) {
        v->c.log_max_fill = fill;
    }
}

static void put(uint8_t *p, uint64_t x, uint32_t bytes)
{
    uint32_t i;
    for (i = 0u; i < bytes; i++) {
        p[i] = (uint8_t)(x >> (8u * i));
    }
}

static uint16_t cdeg(float rad)
{
    return (uint16_t)(int16_t)lroundf(vm_clamp(rad * VM_RAD2DEG * 100.0f, -32767.0f, 32767.0f));
}

void veh_log_cmd(veh_t *v, uint16_t index, uint16_t id, uint8_t event)
{
    uint8_t rec[13];
    put(rec, veh_now(), 8u);
    put(rec + 8, index, 2u);
    put(rec + 10, id, 2u);
    rec[12] = event;
    veh_log_record(v, VEH_LOG_CMD, rec, 13u);
}

void veh_log_event(veh_t *v, uint8_t event, uint8_t arg)
{
    uint8_t rec[10];
    put(rec, veh_now(), 8u);
    rec[8] = event;
    rec[9] = arg;
    veh_log_record(v, VEH_LOG_EV, rec, 10u);
}

uint32_t veh_log_runs(const veh_t *v)
{
    return v->lg.runs;
}

void veh_log_write(veh_t *v)
{
    veh_estimate_msg_t est;
    veh_att_sp_msg_t sp;
    const veh_estimate_msg_t *s = &est;
    uint64_t t = veh_now();
    uint8_t rec[32];

    v->lg.runs++;
    veh_latest(&v->lg.sp_sub, &sp, (uint32_t)sizeof(sp));
    if (!sp.armed) {
        return; /* log while armed only */
    }
    veh_latest(&v->lg.est_sub, &est, (uint32_t)sizeof(est));
    put(rec, t, 8u);
    put(rec + 8, cdeg(s->att[0]), 2u);
    put(rec + 10, cdeg(s->att[1]), 2u);
    put(rec + 12, cdeg(s->att[2]), 2u);
    put(rec + 14, cdeg(sp.att[0]), 2u);
    put(rec + 16, cdeg(sp.att[1]), 2u);
    put(rec + 18, cdeg(sp.att[2]), 2u);
    veh_log_record(v, VEH_LOG_ATT, rec, 20u);

    put(rec + 8, (uint64_t)lroundf(vm_clamp(sp.thrust, 0.0f, 600.0f) * 100.0f), 2u);
    put(rec + 10, (uint32_t)(int32_t)lroundf(-sp.pos[2] * 100.0f), 4u);
    put(rec + 14, (uint16_t)(int16_t)lroundf(vm_clamp(-s->vel[2] * 100.0f, -32767.0f, 32767.0f)),
        2u);
    veh_log_record(v, VEH_LOG_CTUN, rec, 16u);

    if ((v->lg.runs % 5u) == 0u) {
        int i;
        put(rec + 8, (uint32_t)(int32_t)lroundf(s->pos[0] * 100.0f), 4u);
        put(rec + 12, (uint32_t)(int32_t)lroundf(s->pos[1] * 100.0f), 4u);
        put(rec + 16, (uint32_t)(int32_t)lroundf(-s->pos[2] * 100.0f), 4u);
        for (i = 0; i < 3; i++) {
            put(rec + 20 + (2 * i),
                (uint16_t)(int16_t)lroundf(vm_clamp(s->vel[i] * 100.0f, -32767.0f, 32767.0f)), 2u);
        }
        veh_log_record(v, VEH_LOG_POS, rec, 26u);
    }
}

/* IO proc: hand what the ring holds to the sink, zero-copy. */
void veh_log_io_proc(void *arg)
{
    veh_t *v = (veh_t *)arg;
    mt_iovec_t vec[2];
    uint32_t segs = mt_bring_peek_vec(&v->log, vec);
    uint32_t n = 0u;
    uint32_t i;

    for (i = 0u; i < segs; i++) {
        v->plat->log_sink(v->plat->ctx, vec[i].base, vec[i].len);
        n += vec[i].len;
    }
    if (n == 0u) {
        return;
    }
    (void)mt_bring_advance(&v->log, n);
    v->c.log_bytes += n;
}
