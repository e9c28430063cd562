/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file vmath.h
 * @brief Small float helpers shared by the vehicle and the simulated world.
 */
#ifndef VEH_VMATH_H
#define VEH_VMATH_H

#include <math.h>
#include <stdint.h>

#define VM_PI 3.14159265358979f
#define VM_GRAVITY 9.80665f
#define VM_DEG2RAD (VM_PI / 180.0f)
#define VM_RAD2DEG (180.0f / VM_PI)
#define VM_EARTH_RADIUS 6378137.0f

static inline float vm_clamp(float x, float lo, float hi)
{
    return (x < lo) ? lo : ((x > hi) ? hi : x);
}

static inline float vm_wrap_pi(float a)
{
    while (a > VM_PI) {
        a -= 2.0f * VM_PI;
    }
    while (a < -VM_PI) {
        a += 2.0f * VM_PI;
    }
    return a;
}

static inline float vm_wrap_2pi(float a)
{
    while (a >= 2.0f * VM_PI) {
        a -= 2.0f * VM_PI;
    }
    while (a < 0.0f) {
        a += 2.0f * VM_PI;
    }
    return a;
}

static inline float vm_norm2(float x, float y)
{
    return sqrtf((x * x) + (y * y));
}

static inline float vm_norm3(const float v[3])
{
    return sqrtf((v[0] * v[0]) + (v[1] * v[1]) + (v[2] * v[2]));
}

/* Rotation matrix body (FRD) -> earth (NED) from roll, pitch, yaw (ZYX Euler). */
static inline void vm_dcm(const float att[3], float r[3][3])
{
    float cr = cosf(att[0]);
    float sr = sinf(att[0]);
    float cp = cosf(att[1]);
    float sp = sinf(att[1]);
    float cy = cosf(att[2]);
    float sy = sinf(att[2]);

    r[0][0] = cp * cy;
    r[0][1] = (sr * sp * cy) - (cr * sy);
    r[0][2] = (cr * sp * cy) + (sr * sy);
    r[1][0] = cp * sy;
    r[1][1] = (sr * sp * sy) + (cr * cy);
    r[1][2] = (cr * sp * sy) - (sr * cy);
    r[2][0] = -sp;
    r[2][1] = sr * cp;
    r[2][2] = cr * cp;
}

/* Euler-angle rates from body rates (valid away from pitch = +-90 deg). */
static inline void vm_euler_rates(const float att[3], const float w[3], float d[3])
{
    float cr = cosf(att[0]);
    float sr = sinf(att[0]);
    float cp = cosf(att[1]);
    float tp = tanf(att[1]);

    d[0] = w[0] + (((w[1] * sr) + (w[2] * cr)) * tp);
    d[1] = (w[1] * cr) - (w[2] * sr);
    d[2] = ((w[1] * sr) + (w[2] * cr)) / cp;
}

/* North/east offset in metres of (lat, lon) from (lat0, lon0), all in 1e-7 degree. */
static inline void vm_ne_from_ll(int32_t lat0, int32_t lon0, int32_t lat, int32_t lon, float *n,
                                 float *e)
{
    float k = 1.0e-7f * VM_DEG2RAD * VM_EARTH_RADIUS;
    *n = (float)(lat - lat0) * k;
    *e = (float)(lon - lon0) * k * cosf((float)lat0 * 1.0e-7f * VM_DEG2RAD);
}

/* (lat, lon) in 1e-7 degree of a north/east offset from (lat0, lon0). */
static inline void vm_ll_from_ne(int32_t lat0, int32_t lon0, float n, float e, int32_t *lat,
                                 int32_t *lon)
{
    float k = 1.0e-7f * VM_DEG2RAD * VM_EARTH_RADIUS;
    *lat = lat0 + (int32_t)lroundf(n / k);
    *lon = lon0 + (int32_t)lroundf(e / (k * cosf((float)lat0 * 1.0e-7f * VM_DEG2RAD)));
}

#endif /* VEH_VMATH_H */
