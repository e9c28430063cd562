/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file simplat.c
 * @brief The vehicle's platform on the simulated world (see simplat.h).
 */
#include "simplat.h"

#include <string.h>

#include "vmath.h"

#define SIM_SUBSTEP_US 500u   /* physics step */
#define GPS_PERIOD_US 200000u /* 5 Hz fixes */
#define GPS_FIRST_FIX_US 1000000u

static uint32_t load_u32(const uint32_t *p)
{
    return __atomic_load_n(p, __ATOMIC_ACQUIRE);
}

static void store_u32(uint32_t *p, uint32_t v)
{
    __atomic_store_n(p, v, __ATOMIC_RELEASE);
}

/* Device registers from the model (main loop). */
static void update_devices(simplat_t *w)
{
    float pa = sim_pressure(&w->sim, (float)w->home.alt_cm * 0.01f);
    uint32_t p8 = (uint32_t)(vm_clamp(pa, 0.0f, 131071.0f) * 8.0f + 0.5f);
    uint32_t temp = 250u + 400u; /* 25.0 C, offset 40 C, 0.1 C units */
    uint32_t mv = (uint32_t)(vm_clamp(w->sim.bat_volt, 0.0f, 65.0f) * 1000.0f);
    uint32_t ca = (uint32_t)(vm_clamp(w->sim.bat_amp, 0.0f, 655.0f) * 100.0f);

    store_u32(&w->baro_word, ((p8 & 0xFFFFFu) << 12) | (temp & 0xFFFu));
    store_u32(&w->batt_word, ((mv & 0xFFFFu) << 16) | (ca & 0xFFFFu));
}

void simplat_init(simplat_t *w, const veh_home_t *home, uint64_t seed, simplat_wait_fn_t base_wait,
                  void *base_ctx)
{
    sim_params_t p;

    memset(w, 0, sizeof(*w));
    sim_params_default(&p);
    sim_init(&w->sim, &p, seed);
    w->home = *home;
    w->base_wait = base_wait;
    w->base_ctx = base_ctx;
    update_devices(w); /* the devices answer from power-on */
}

void simplat_set_wind(simplat_t *w, float north, float east)
{
    w->sim.wind[0] = north;
    w->sim.wind[1] = east;
}

static void make_fix(simplat_t *w, uint64_t t)
{
    sim_t *s = &w->sim;
    veh_gps_fix_t *f = &w->gps;
    float n = s->pos[0] + sim_noise(s, 0.10f);
    float e = s->pos[1] + sim_noise(s, 0.10f);
    int i;

    f->t_us = t;
    vm_ll_from_ne(w->home.lat, w->home.lon, n, e, &f->lat, &f->lon);
    f->alt_cm = w->home.alt_cm + (int32_t)lroundf((-s->pos[2] + sim_noise(s, 0.3f)) * 100.0f);
    for (i = 0; i < 3; i++) {
        f->vel[i] = s->vel[i] + sim_noise(s, 0.05f);
    }
    f->fix = 3u;
    f->sats = 12u;
    w->gps_new = true;
}

uint64_t simplat_wait(void *ctx)
{
    simplat_t *w = (simplat_t *)ctx;
    uint64_t t = w->base_wait(w->base_ctx);

    if (w->t_us == 0u) {
        w->t_us = t;
        w->boot_us = t;
        w->gps_next_us = t + GPS_FIRST_FIX_US;
    }
    while (w->t_us < t) {
        uint64_t step = t - w->t_us;
        if (step > SIM_SUBSTEP_US) {
            step = SIM_SUBSTEP_US;
        }
        sim_step(&w->sim, (float)step * 1.0e-6f);
        w->t_us += step;
    }
    {
        float gs = vm_norm2(w->sim.vel[0], w->sim.vel[1]);
        if (gs > w->max_speed) {
            w->max_speed = gs;
        }
        if (-w->sim.pos[2] > w->max_alt) {
            w->max_alt = -w->sim.pos[2];
        }
    }
    w->imu.t_us = t;
    sim_imu(&w->sim, w->imu.gyro, w->imu.accel);
    update_devices(w);
    if (t >= w->gps_next_us) {
        make_fix(w, t);
        w->gps_next_us += GPS_PERIOD_US;
    }
    return t;
}

static void cb_imu_read(void *ctx, veh_imu_sample_t *s)
{
    *s = ((simplat_t *)ctx)->imu;
}

static bool cb_gps_read(void *ctx, veh_gps_fix_t *f)
{
    simplat_t *w = (simplat_t *)ctx;
    if (!w->gps_new) {
        return false;
    }
    *f = w->gps;
    w->gps_new = false;
    return true;
}

/* Register maps: baro 0x00: 4 bytes big-endian word; battery 0x00: 4 bytes. */
static bool cb_bus_read(void *ctx, uint8_t dev, uint8_t reg, uint8_t *rx, uint32_t n)
{
    simplat_t *w = (simplat_t *)ctx;
    uint32_t word;
    uint32_t i;
    bool ok = true;

    if (__atomic_exchange_n(&w->bus_busy, 1u, __ATOMIC_ACQ_REL) != 0u) {
        __atomic_fetch_add(&w->collisions, 1u, __ATOMIC_RELAXED);
    }
    if (dev == VEH_DEV_BARO) {
        word = load_u32(&w->baro_word);
    } else if (dev == VEH_DEV_BATT) {
        word = load_u32(&w->batt_word);
    } else {
        word = 0u;
        ok = false;
    }
    if ((reg != 0u) || (n > 4u)) {
        ok = false;
    }
    for (i = 0u; ok && (i < n); i++) {
        rx[i] = (uint8_t)(word >> (24u - (8u * i)));
    }
    __atomic_fetch_add(&w->transactions, 1u, __ATOMIC_RELAXED);
    __atomic_store_n(&w->bus_busy, 0u, __ATOMIC_RELEASE);
    return ok;
}

static void cb_motors_write(void *ctx, const float out[4], bool armed)
{
    simplat_t *w = (simplat_t *)ctx;
    int i;
    for (i = 0; i < 4; i++) {
        w->sim.cmd[i] = armed ? out[i] : 0.0f;
    }
}

static void cb_servo_write(void *ctx, uint8_t channel, uint16_t pwm)
{
    simplat_t *w = (simplat_t *)ctx;
    if ((channel >= 1u) && (channel <= 16u)) {
        w->servo[channel - 1u] = pwm;
        w->servo_writes++;
    }
}

void simplat_fill(simplat_t *w, veh_platform_t *p)
{
    p->ctx = w;
    p->imu_read = cb_imu_read;
    p->gps_read = cb_gps_read;
    p->bus_read = cb_bus_read;
    p->motors_write = cb_motors_write;
    p->servo_write = cb_servo_write;
}
