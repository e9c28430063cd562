/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file wpl.c
 * @brief QGC WPL 110 reader, writer and float-to-kernel conversion (see wpl.h).
 */
#include "wpl.h"

#include "item.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#define WPL_FIELDS 12u
#define WPL_TOKEN_MAX 64u

/* Fill one error or warning record. */
static void fill(mt_wpl_error_t *e, mt_status_t st, uint32_t line, uint32_t field, uint32_t index,
                 const char *fmt, va_list ap) __attribute__((format(printf, 6, 0)));
static void fill(mt_wpl_error_t *e, mt_status_t st, uint32_t line, uint32_t field, uint32_t index,
                 const char *fmt, va_list ap)
{
    e->st = st;
    e->line = line;
    e->field = field;
    e->index = index;
    vsnprintf(e->reason, sizeof e->reason, fmt, ap);
}

void mt_wpl_set_error(mt_wpl_error_t *err, mt_status_t st, uint32_t line, uint32_t field,
                      uint32_t index, const char *fmt, ...)
{
    va_list ap;

    if (err == NULL) {
        return;
    }
    va_start(ap, fmt);
    fill(err, st, line, field, index, fmt, ap);
    va_end(ap);
}

static const char *const k_field_names[WPL_FIELDS] = {
    "seq", "current", "frame", "command", "param1", "param2", "param3", "param4",
    "x (latitude)", "y (longitude)", "z (altitude)", "autocontinue"};

static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/* Unsigned decimal integer, whole token, value <= max. */
static int parse_uint(const char *tok, uint32_t max, uint32_t *out)
{
    uint64_t v = 0u;
    size_t i;

    if (tok[0] == '\0') {
        return 0;
    }
    for (i = 0u; tok[i] != '\0'; i++) {
        if (tok[i] < '0' || tok[i] > '9') {
            return 0;
        }
        v = v * 10u + (uint64_t)(tok[i] - '0');
        if (v > max) {
            return 0;
        }
    }
    *out = (uint32_t)v;
    return 1;
}

/* Decimal floating-point number (strtod syntax, also nan/inf), whole token. */
static int parse_double(const char *tok, double *out)
{
    char *end = NULL;
    double v;

    if (tok[0] == '\0') {
        return 0;
    }
    errno = 0;
    v = strtod(tok, &end);
    if (end == tok || *end != '\0') {
        return 0;
    }
    if (errno == ERANGE && isinf(v) == 0 && v != 0.0) {
        return 0;
    }
    *out = v;
    return 1;
}

const char *mt_wpl_where(char *buf, size_t cap, const char *file, const mt_wpl_error_t *e)
{
    int k = (e->line != 0u) ? snprintf(buf, cap, "%s:%u:", file, (unsigned)e->line)
                            : snprintf(buf, cap, "%s:", file);
    size_t n = (k < 0) ? 0u : (size_t)k;

    if (e->field != 0u && n < cap) {
        k = snprintf(buf + n, cap - n, " field %u:", (unsigned)e->field);
        n += (k < 0) ? 0u : (size_t)k;
    }
    if (e->index != MT_MISSION_NONE && n < cap) {
        (void)snprintf(buf + n, cap - n, " index %u:", (unsigned)e->index);
    }
    return buf;
}

void mt_wpl_warn(mt_wpl_warnings_t *warn, uint32_t line, uint32_t field, uint32_t index, const char *fmt, ...)
{
    va_list ap;
    mt_wpl_error_t *w;

    if (warn == NULL) {
        return;
    }
    if (warn->n >= MT_WPL_MAX_WARNINGS) {
        warn->dropped++;
        return;
    }
    w = &warn->w[warn->n++];
    va_start(ap, fmt);
    fill(w, MT_OK, line, field, index, fmt, ap);
    va_end(ap);
}

/* The line [*start, *end) beginning at *pos; a line ends at LF, CRLF or a lone CR. Advances
 * *pos past the line end. */
static void next_line(const char *text, size_t len, size_t *pos, size_t *start, size_t *end)
{
    size_t p = *pos;

    *start = p;
    while (p < len && text[p] != '\n' && text[p] != '\r') {
        p++;
    }
    *end = p;
    if (p < len && text[p] == '\r') {
        p++;
        if (p < len && text[p] == '\n') {
            p++;
        }
    } else if (p < len) {
        p++;
    }
    *pos = p;
}

mt_status_t mt_wpl_parse(const char *text, size_t len, mt_wpl_item_t *items, size_t cap, size_t *n,
                         mt_wpl_error_t *err, mt_wpl_warnings_t *warn)
{
    static const char bom[] = "\xEF\xBB\xBF";
    size_t pos = 0u;
    uint32_t line = 0u;
    uint32_t header_line = 0u;
    uint32_t prev_seq = 0u;

    *n = 0u;
    mt_wpl_set_error(err, MT_OK, 0u, 0u, MT_MISSION_NONE, "ok");
    if (len >= sizeof bom - 1u && memcmp(text, bom, sizeof bom - 1u) == 0) {
        pos = sizeof bom - 1u; /* UTF-8 byte order mark */
    }
    while (pos < len) {
        size_t start;
        size_t end;
        size_t p;
        char tok[WPL_FIELDS][WPL_TOKEN_MAX];
        uint32_t nt = 0u;
        mt_wpl_item_t it;
        uint32_t f;

        next_line(text, len, &pos, &start, &end);
        line++;
        p = start;
        while (p < end && is_space(text[p])) {
            p++;
        }
        if (p < end && text[p] == '#') {
            continue; /* comment */
        }
        /* tokenise the line [start, end) */
        for (;;) {
            size_t k = 0u;
            while (p < end && is_space(text[p])) {
                p++;
            }
            if (p >= end) {
                break;
            }
            if (text[p] == '\0') {
                mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, nt + 1u, MT_MISSION_NONE,
                                 "NUL byte in the file");
                return MT_E_MISSION_SYNTAX;
            }
            if (header_line == 0u) {
                break; /* the header is checked as a whole below */
            }
            if (nt >= WPL_FIELDS) {
                mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, nt + 1u, MT_MISSION_NONE,
                                 "more than %u fields", (unsigned)WPL_FIELDS);
                return MT_E_MISSION_SYNTAX;
            }
            while (p < end && !is_space(text[p])) {
                if (text[p] == '\0') {
                    mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, nt + 1u, MT_MISSION_NONE,
                                     "NUL byte in the file");
                    return MT_E_MISSION_SYNTAX;
                }
                if (k + 1u >= WPL_TOKEN_MAX) {
                    mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, nt + 1u, MT_MISSION_NONE,
                                     "%s: field too long", k_field_names[nt]);
                    return MT_E_MISSION_SYNTAX;
                }
                tok[nt][k++] = text[p++];
            }
            tok[nt][k] = '\0';
            nt++;
        }
        if (header_line == 0u) {
            /* first non-blank line that is not a comment: the header */
            size_t a = start;
            size_t b = end;
            static const char hdr[] = "QGC WPL 110";
            while (a < b && is_space(text[a])) {
                a++;
            }
            while (b > a && is_space(text[b - 1u])) {
                b--;
            }
            if (a == b) {
                continue; /* blank line before the header */
            }
            if ((b - a) != sizeof hdr - 1u || memcmp(text + a, hdr, sizeof hdr - 1u) != 0) {
                mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, 0u, MT_MISSION_NONE,
                                 "missing header: expected \"QGC WPL 110\"");
                return MT_E_MISSION_SYNTAX;
            }
            header_line = line;
            continue;
        }
        if (nt == 0u) {
            continue; /* blank line */
        }
        if (nt < WPL_FIELDS) {
            mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, nt + 1u, MT_MISSION_NONE,
                             "%s: missing (a line has 12 fields, found %u)", k_field_names[nt],
                             (unsigned)nt);
            return MT_E_MISSION_SYNTAX;
        }
        memset(&it, 0, sizeof it);
        it.line = line;
        if (!parse_uint(tok[0], 0xFFFFFFFFu, &it.seq)) {
            mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, 1u, MT_MISSION_NONE,
                             "seq: not an unsigned integer: '%s'", tok[0]);
            return MT_E_MISSION_SYNTAX;
        }
        if (!parse_uint(tok[1], 1u, &it.current)) {
            mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, 2u, (uint32_t)*n,
                             "current: not 0 or 1: '%s'", tok[1]);
            return MT_E_MISSION_SYNTAX;
        }
        if (!parse_uint(tok[2], 0xFFFFFFFFu, &it.frame)) {
            mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, 3u, (uint32_t)*n,
                             "frame: not an unsigned integer: '%s'", tok[2]);
            return MT_E_MISSION_SYNTAX;
        }
        if (!parse_uint(tok[3], 0xFFFFFFFFu, &it.command)) {
            mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, 4u, (uint32_t)*n,
                             "command: not an unsigned integer: '%s'", tok[3]);
            return MT_E_MISSION_SYNTAX;
        }
        for (f = 0u; f < 7u; f++) {
            if (!parse_double(tok[4u + f], &it.p[f])) {
                mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, 5u + f, (uint32_t)*n,
                                 "%s: not a number: '%s'", k_field_names[4u + f], tok[4u + f]);
                return MT_E_MISSION_SYNTAX;
            }
        }
        if (!parse_uint(tok[11], 1u, &it.autocontinue)) {
            mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, 12u, (uint32_t)*n,
                             "autocontinue: not 0 or 1: '%s'", tok[11]);
            return MT_E_MISSION_SYNTAX;
        }
        if (*n >= cap) {
            mt_wpl_set_error(err, MT_E_MISSION_SIZE, line, 0u, (uint32_t)*n, "more than %u items",
                             (unsigned)cap);
            return MT_E_MISSION_SIZE;
        }
        /* items are numbered in file order (mavwp.py renumbers silently; this says so) */
        if (*n == 0u ? it.seq != 0u : it.seq != prev_seq + 1u) {
            mt_wpl_warn(warn, line, 1u, (uint32_t)*n,
                        "seq: %u where %u was expected; renumbered to %u (jump targets use the new numbers)",
                        (unsigned)it.seq, *n == 0u ? 0u : (unsigned)(prev_seq + 1u), (unsigned)*n);
        }
        prev_seq = it.seq;
        it.seq = (uint32_t)*n;
        if (*n == 0u && it.command == 0u) {
            mt_wpl_warn(warn, line, 4u, 0u, "home: command 0 (Mission Planner) read as WAYPOINT (16)");
            it.command = MT_MAV_CMD_WAYPOINT;
        }
        items[*n] = it;
        (*n)++;
    }
    if (header_line == 0u) {
        mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line == 0u ? 1u : line, 0u, MT_MISSION_NONE,
                         "empty file: expected \"QGC WPL 110\"");
        return MT_E_MISSION_SYNTAX;
    }
    if (*n == 0u) {
        mt_wpl_set_error(
            err, MT_E_MISSION_SIZE, header_line, 0u, 0u,
            "no items after the header: a mission needs at least the home entry (index 0)");
        return MT_E_MISSION_SIZE;
    }
    return MT_OK;
}

void mt_wpl_fmt_double(char *buf, size_t cap, double v)
{
    int prec;

    if (isnan(v)) {
        snprintf(buf, cap, "nan");
        return;
    }
    if (isinf(v)) {
        snprintf(buf, cap, v < 0 ? "-inf" : "inf");
        return;
    }
    if (v == floor(v) && fabs(v) < 1e15) {
        snprintf(buf, cap, "%.0f", v); /* an integer: 20, not 2e+01 (exact below 2^53) */
        return;
    }
    for (prec = 1; prec <= 17; prec++) {
        snprintf(buf, cap, "%.*g", prec, v);
        if (strtod(buf, NULL) == v) {
            return;
        }
    }
}

size_t mt_wpl_write(const mt_wpl_item_t *items, size_t n, char *out, size_t cap)
{
    size_t used = 0u;
    size_t i;
    int k;

#define EMIT(...)                                                                                         \
    do {                                                                                                  \
        k = snprintf(used < cap ? out + used : NULL, used < cap ? cap - used : 0u, __VA_ARGS__);          \
        if (k > 0) {                                                                                      \
            used += (size_t)k;                                                                            \
        }                                                                                                 \
    } while (0)

    EMIT("QGC WPL 110\n");
    for (i = 0u; i < n; i++) {
        const mt_wpl_item_t *it = &items[i];
        char num[7][40];
        int f;
        for (f = 0; f < 7; f++) {
            mt_wpl_fmt_double(num[f], sizeof num[f], it->p[f]);
        }
        EMIT("%u\t%u\t%u\t%u\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%u\n", (unsigned)i, (unsigned)it->current,
             (unsigned)it->frame, (unsigned)it->command, num[0], num[1], num[2], num[3], num[4], num[5],
             num[6], (unsigned)it->autocontinue);
    }
#undef EMIT
    return used;
}

mt_status_t mt_wpl_to_cmd(const mt_wpl_item_t *it, mt_mission_cmd_t *out, mt_wpl_error_t *err)
{
    mt_item_fault_t f;
    mt_status_t st = mt_item_to_cmd(it, out, &f);
    const char *name = mt_item_field_name(f.field);

    if (st == MT_OK) {
        return MT_OK;
    }
    if (f.why == MT_ITEM_NOT_A_CMD) {
        mt_wpl_set_error(err, st, it->line, f.field, it->seq, "command: %u is not a MAV_CMD number",
                         (unsigned)it->command);
    } else if (f.why == MT_ITEM_NOT_A_FRAME) {
        mt_wpl_set_error(err, st, it->line, f.field, it->seq, "frame: %u is not a MAV_FRAME number",
                         (unsigned)it->frame);
    } else if (f.field <= 8u) {
        mt_wpl_set_error(err, st, it->line, f.field, it->seq, "%s: %s (limit: finite, |v| < 2147483.647)",
                         name, mt_item_why_str(f.why));
    } else {
        mt_wpl_set_error(err, st, it->line, f.field, it->seq, "%s: %s", name, mt_item_why_str(f.why));
    }
    return st;
}
