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
    uint32_t said;                           /**< lines said (veh_say) */
    char kept[VEH_SAID_KEEP][VEH_SAID_TEXT]; /**< line seq at kept[(seq - 1) % KEEP] */
} veh_console_t;

static veh_console_t g_console;

void veh_console_init(const veh_platform_t *plat)
{
    g_console.plat = plat;
    g_console.boot_us = mt_port_now_us();
    g_console.said = 0u;
}

bool veh_console_said(uint32_t seq, char text[VEH_SAID_TEXT])
{
    const char *k;
    uint32_t i;

    if ((seq == 0u) || (seq > g_console.said) || ((g_console.said - seq) >= VEH_SAID_KEEP)) {
        return false;
    }
    k = g_console.kept[(seq - 1u) % VEH_SAID_KEEP];
    for (i = 0u; i < VEH_SAID_TEXT; i++) {
        text[i] = k[i];
    }
    return true;
}

uint32_t veh_console_said_count(void)
{
    return g_console.said;
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
    char *keep; /**< NULL, or where the text is also kept for the link (VEH_SAID_TEXT) */
    size_t kn;
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
        if ((l->keep != NULL) && (l->kn + 1u < VEH_SAID_TEXT)) {
            l->keep[l->kn] = s[i];
            l->kn++;
        }
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
    l.keep = NULL;
    l.kn = 0u;
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
    l.keep = NULL;
    l.kn = 0u;
    stamp(&l);
    /* the text after the time stamp is kept for the link, cut to VEH_SAID_TEXT - 1 */
    g_console.said++;
    l.keep = g_console.kept[(g_console.said - 1u) % VEH_SAID_KEEP];
    va_start(ap, fmt);
    (void)vp_vformat(line_sink, &l, fmt, ap);
    va_end(ap);
    l.keep[l.kn] = '\0';
    l.keep = NULL;
    line_sink(&l, "\n", 1u);
    line_flush(&l);
}
