/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file vprint.h
 * @brief The vehicle's console formatter: a small printf (no floating point, no
 *        heap, no libc stdio) so that the host SITL and the firmware print the
 *        same bytes.
 *
 * Conversions: %d %i %u %x %X %c %s %% with the length modifiers l, ll and z,
 * flags '-' and '0', and a field width. Fixed-point numbers are printed with
 * vp_fix() into a caller buffer and passed as %s.
 */
#ifndef VEH_VPRINT_H
#define VEH_VPRINT_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Output sink: n bytes of text. */
typedef void (*vp_sink_t)(void *ctx, const char *s, size_t n);

/** Format into the sink; returns the number of bytes produced. */
size_t vp_vformat(vp_sink_t sink, void *ctx, const char *fmt, va_list ap);

/** Format into buf (always NUL-terminated when cap > 0); returns the length it
 *  would have had without truncation. */
size_t vp_snprintf(char *buf, size_t cap, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/** Value v in 1/scale units printed with `decimals` digits after the point
 *  (rounded half away from zero): vp_fix(buf, 12345, 1000, 1) is "12.3". */
const char *vp_fix(char *buf, size_t cap, int64_t v, int64_t scale, unsigned decimals);

/** A float printed with `decimals` digits; "nan", "inf", "-inf", or "out of range" when
 *  |x| 10^decimals is 9e18 or more. */
const char *vp_float(char *buf, size_t cap, float x, unsigned decimals);

#ifdef __cplusplus
}
#endif

#endif /* VEH_VPRINT_H */
