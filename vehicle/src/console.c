/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file console.c
 * @brief The console component (console.h): time and text output. Owns the
 *        boot time and the platform's console sink; depends on no other
 *        component.
 */
#include <stdarg.h>

#include "console.h"
#include "mt/mt.h"
#include "vprint.h"

typedef struct {
    const veh_platform_t *plat;
    uint64_t boot_us;
} veh_console_t;

static veh_console_t g_console;

void veh_console_init(const veh_platform_t *plat)
{
    g_console.plat = plat;
    g_console.boot_us = mt_port_now_us();
}

uint64_t veh_now(void)
{
    return mt_port_now_us();
}

uint64_t veh_boot_us(void)
{
    return g_console.boot_us;
}

/* Console output is formatted into a line buffer and handed to the platform in one piece
 * (a console call per fragment costs a ring operation each on the firmware). */
typedef struct {
    const veh_platform_t *p;
    size_t n;
    char buf[192];
} veh_line_t;

static void line_flush(veh_line_t *l)
{
    if (l->n > 0u) {
        l->p->console(l->p->ctx, l->buf, l->n);
        l->n = 0u;
    }
}

static void line_sink(void *ctx, const char *s, size_t n)
{
    veh_line_t *l = (veh_line_t *)ctx;
    size_t i;

    for (i = 0u; i < n; i++) {
        if (l->n == sizeof(l->buf)) {
            line_flush(l);
        }
        l->buf[l->n] = s[i];
        l->n++;
    }
}

static size_t text_len(const char *s)
{
    size_t k = 0u;
    while (s[k] != '\0') {
        k++;
    }
    return k;
}

/* "[" + the time since boot, right-aligned in 8 characters + "] " */
static void stamp(veh_line_t *l)
{
    char t[24];
    uint64_t now = veh_now();
    size_t k;

    (void)vp_fix(t, sizeof(t),
                 (int64_t)((now >= g_console.boot_us) ? (now - g_console.boot_us) : 0u), 1000000,
                 3u);
    line_sink(l, "[", 1u);
    for (k = text_len(t); k < 8u; k++) {
        line_sink(l, " ", 1u);
    }
    line_sink(l, t, text_len(t));
    line_sink(l, "] ", 2u);
}

void veh_printf(const char *fmt, ...)
{
    veh_line_t l;
    va_list ap;

    l.p = g_console.plat;
    l.n = 0u;
    va_start(ap, fmt);
    (void)vp_vformat(line_sink, &l, fmt, ap);
    va_end(ap);
    line_flush(&l);
}

void veh_say(const char *fmt, ...)
{
    veh_line_t l;
    va_list ap;

    l.p = g_console.plat;
    l.n = 0u;
    stamp(&l);
    va_start(ap, fmt);
    (void)vp_vformat(line_sink, &l, fmt, ap);
    va_end(ap);
    line_sink(&l, "\n", 1u);
    line_flush(&l);
}
