/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mfile.c
 * @brief Mission file format choice and dispatch (see mfile.h).
 */
#include "mfile.h"

#include <ctype.h>
#include <string.h>

/* s ends with suffix (lower case), ignoring the case of s. */
static int ends_with(const char *s, const char *suffix)
{
    size_t a = strlen(s);
    size_t b = strlen(suffix);
    size_t i;

    if (a < b) {
        return 0;
    }
    for (i = 0u; i < b; i++) {
        if (tolower((unsigned char)s[a - b + i]) != (unsigned char)suffix[i]) {
            return 0;
        }
    }
    return 1;
}

mt_mfile_format_t mt_mfile_format_of_path(const char *path)
{
    if (ends_with(path, ".plan")) {
        return MT_MFILE_PLAN;
    }
    if (ends_with(path, ".waypoints") || ends_with(path, ".txt") || ends_with(path, ".mission")) {
        return MT_MFILE_WPL;
    }
    return MT_MFILE_AUTO;
}

mt_mfile_format_t mt_mfile_sniff(const char *text, size_t len)
{
    size_t i = 0u;

    if (len >= 3u && memcmp(text, "\xEF\xBB\xBF", 3u) == 0) {
        i = 3u;
    }
    while (i < len && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n')) {
        i++;
    }
    return (i < len && text[i] == '{') ? MT_MFILE_PLAN : MT_MFILE_WPL;
}

mt_status_t mt_mfile_parse(mt_mfile_format_t fmt, const char *text, size_t len, mt_wpl_item_t *items, size_t cap,
                           size_t *n, mt_wpl_error_t *err, mt_wpl_warnings_t *warn)
{
    if (fmt == MT_MFILE_AUTO) {
        fmt = mt_mfile_sniff(text, len);
    }
    if (fmt == MT_MFILE_PLAN) {
        return mt_plan_parse(text, len, items, cap, n, err, warn);
    }
    return mt_wpl_parse(text, len, items, cap, n, err, warn);
}
