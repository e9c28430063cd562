/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file vprint.c
 * @brief The vehicle's console formatter (see vprint.h).
 */
#include "vprint.h"

#include <stdbool.h>

typedef struct {
    vp_sink_t sink;
    void *ctx;
    size_t n;
} vp_out_t;

static void out(vp_out_t *o, const char *s, size_t n)
{
    if (n > 0u) {
        o->sink(o->ctx, s, n);
        o->n += n;
    }
}

static void pad(vp_out_t *o, char c, size_t n)
{
    char run[16];
    size_t i;

    for (i = 0u; i < sizeof(run); i++) {
        run[i] = c;
    }
    while (n > 0u) {
        size_t k = (n < sizeof(run)) ? n : sizeof(run);
        out(o, run, k);
        n -= k;
    }
}

/* Digits of v in base 10 or 16 into the end of buf; returns the start. 32-bit arithmetic
 * while the value fits (a 64-bit division is a library call on 32-bit targets). */
static char *digits(char *end, uint64_t v, unsigned base, bool upper)
{
    const char *d = upper ? "0123456789ABCDEF" : "0123456789abcdef";
    char *p = end;

    while (v > 0xFFFFFFFFu) {
        p--;
        *p = d[v % base];
        v /= base;
    }
    {
        uint32_t w = (uint32_t)v;
        do {
            p--;
            *p = d[w % base];
            w /= base;
        } while (w != 0u);
    }
    return p;
}

static void field(vp_out_t *o, const char *s, size_t len, size_t width, bool left, bool zero,
                  bool neg)
{
    size_t total = len + (neg ? 1u : 0u);
    size_t fill = (width > total) ? (width - total) : 0u;

    if (!left && !zero) {
        pad(o, ' ', fill);
    }
    if (neg) {
        out(o, "-", 1u);
    }
    if (!left && zero) {
        pad(o, '0', fill);
    }
    out(o, s, len);
    if (left) {
        pad(o, ' ', fill);
    }
}

size_t vp_vformat(vp_sink_t sink, void *ctx, const char *fmt, va_list ap)
{
    vp_out_t o = {sink, ctx, 0u};
    const char *p = fmt;

    while (*p != '\0') {
        const char *q = p;
        bool left = false;
        bool zero = false;
        size_t width = 0u;
        unsigned lng = 0u;
        bool zsize = false;
        char buf[24];
        char *end = buf + sizeof(buf);

        while ((*q != '\0') && (*q != '%')) {
            q++;
        }
        out(&o, p, (size_t)(q - p));
        if (*q == '\0') {
            break;
        }
        q++; /* '%' */
        for (;; q++) {
            if (*q == '-') {
                left = true;
            } else if (*q == '0') {
                zero = true;
            } else {
                break;
            }
        }
        while ((*q >= '0') && (*q <= '9')) {
            width = (width * 10u) + (size_t)(*q - '0');
            q++;
        }
        while (*q == 'l') {
            lng++;
            q++;
        }
        if (*q == 'z') {
            zsize = true;
            q++;
        }
        switch (*q) {
        case 'd':
        case 'i': {
            int64_t v;
            uint64_t m;
            char *s;
            if (zsize) {
                v = (int64_t)va_arg(ap, long);
            } else if (lng >= 2u) {
                v = (int64_t)va_arg(ap, long long);
            } else if (lng == 1u) {
                v = (int64_t)va_arg(ap, long);
            } else {
                v = (int64_t)va_arg(ap, int);
            }
            m = (v < 0) ? ((uint64_t)(-(v + 1)) + 1u) : (uint64_t)v;
            s = digits(end, m, 10u, false);
            field(&o, s, (size_t)(end - s), width, left, zero, v < 0);
            break;
        }
        case 'u':
        case 'x':
        case 'X': {
            uint64_t v;
            char *s;
            if (zsize) {
                v = (uint64_t)va_arg(ap, size_t);
            } else if (lng >= 2u) {
                v = (uint64_t)va_arg(ap, unsigned long long);
            } else if (lng == 1u) {
                v = (uint64_t)va_arg(ap, unsigned long);
            } else {
                v = (uint64_t)va_arg(ap, unsigned int);
            }
            s = digits(end, v, (*q == 'u') ? 10u : 16u, *q == 'X');
            field(&o, s, (size_t)(end - s), width, left, zero, false);
            break;
        }
        case 'c': {
            char c = (char)va_arg(ap, int);
            field(&o, &c, 1u, width, left, false, false);
            break;
        }
        case 's': {
            const char *s = va_arg(ap, const char *);
            size_t len = 0u;
            if (s == NULL) {
                s = "(null)";
            }
            while (s[len] != '\0') {
                len++;
            }
            field(&o, s, len, width, left, false, false);
            break;
        }
        case '%': out(&o, "%", 1u); break;
        default:
            /* unknown conversion: print it as written */
            out(&o, p + (q - p) - 1, (*q != '\0') ? 2u : 1u);
            break;
        }
        if (*q == '\0') {
            break;
        }
        p = q + 1;
    }
    return o.n;
}

typedef struct {
    char *buf;
    size_t cap;
    size_t len;
} vp_buf_t;

static void buf_sink(void *ctx, const char *s, size_t n)
{
    vp_buf_t *b = (vp_buf_t *)ctx;
    size_t i;

    for (i = 0u; i < n; i++) {
        if ((b->len + 1u) < b->cap) {
            b->buf[b->len] = s[i];
        }
        b->len++;
    }
}

size_t vp_snprintf(char *buf, size_t cap, const char *fmt, ...)
{
    vp_buf_t b = {buf, cap, 0u};
    va_list ap;

    va_start(ap, fmt);
    (void)vp_vformat(buf_sink, &b, fmt, ap);
    va_end(ap);
    if (cap > 0u) {
        buf[(b.len < cap) ? b.len : (cap - 1u)] = '\0';
    }
    return b.len;
}

const char *vp_fix(char *buf, size_t cap, int64_t v, int64_t scale, unsigned decimals)
{
    uint32_t p10 = 1u;
    uint64_t m;
    uint64_t q;
    uint64_t rm;
    uint64_t f;
    char frac[12];
    unsigned i;
    bool neg = v < 0;

    if (decimals > 9u) {
        decimals = 9u;
    }
    for (i = 0u; i < decimals; i++) {
        p10 *= 10u;
    }
    m = neg ? ((uint64_t)(-(v + 1)) + 1u) : (uint64_t)v;
    /* integer part and remainder; 32-bit arithmetic when it fits (64-bit division is a
     * library call on 32-bit targets) */
    if ((m <= 0xFFFFFFFFu) && ((uint64_t)scale <= 0xFFFFFFFFu)) {
        q = (uint32_t)m / (uint32_t)scale;
        rm = (uint32_t)m % (uint32_t)scale;
    } else {
        q = m / (uint64_t)scale;
        rm = m % (uint64_t)scale;
    }
    /* the fraction, rounded half away from zero (rm < scale) */
    if (((uint64_t)scale <= 0x7FFFFFFFu) && (rm <= (0xFFFFFFFFu / 2u / p10))) {
        f = (((uint32_t)rm * p10) + ((uint32_t)scale / 2u)) / (uint32_t)scale;
    } else {
        f = ((rm * p10) + ((uint64_t)scale / 2u)) / (uint64_t)scale;
    }
    if (f >= p10) {
        f -= p10;
        q++;
    }
    neg = neg && ((q != 0u) || (f != 0u));
    if (decimals == 0u) {
        (void)vp_snprintf(buf, cap, "%s%llu", neg ? "-" : "", (unsigned long long)q);
        return buf;
    }
    {
        uint32_t fr = (uint32_t)f;
        for (i = 0u; i < decimals; i++) {
            frac[decimals - 1u - i] = (char)('0' + (char)(fr % 10u));
            fr /= 10u;
        }
        frac[decimals] = '\0';
    }
    (void)vp_snprintf(buf, cap, "%s%llu.%s", neg ? "-" : "", (unsigned long long)q, frac);
    return buf;
}

const char *vp_float(char *buf, size_t cap, float x, unsigned decimals)
{
    float s = 1.0f;
    float y;
    unsigned i;

    for (i = 0u; i < decimals; i++) {
        s *= 10.0f;
    }
    /* to an integer count of 1/s units, rounded half away from zero; what int64 cannot hold
     * (NaN, the infinities, |x| s of 9e18 or more: a ground station's PARAM_SET can carry any
     * float) is said in words, never converted */
    y = x * s;
    if (!(y < 9.0e18f) || !(y > -9.0e18f)) {
        const char *w = (x != x) ? "nan" : (x - x != 0.0f) ? ((x > 0.0f) ? "inf" : "-inf")
                                                            : "out of range";
        (void)vp_snprintf(buf, cap, "%s", w);
        return buf;
    }
    y = (y >= 0.0f) ? (y + 0.5f) : (y - 0.5f);
    return vp_fix(buf, cap, (int64_t)y, (int64_t)s, decimals);
}
