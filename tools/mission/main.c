/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file main.c
 * @brief mt-mission: check a QGC WPL 110 mission file and print its execution plan.
 *
 *   mt-mission check [--json] [--max-plan N] FILE
 *   mt-mission fmt FILE          (rewrite canonically to stdout: the round trip)
 *
 * Exit status: 0 valid, 1 invalid, 2 usage or I/O error.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report.h"
#include "wpl.h"

static int usage(void)
{
    fprintf(stderr, "usage: mt-mission check [--json] [--max-plan N] FILE\n"
                    "       mt-mission fmt FILE\n");
    return 2;
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    size_t cap = 0u;
    size_t n = 0u;

    if (f == NULL) {
        return NULL;
    }
    for (;;) {
        size_t k;
        if (n == cap) {
            char *nb;
            cap = cap ? cap * 2u : 65536u;
            if (cap > (64u << 20)) {
                break; /* 64 MiB is not a mission file */
            }
            nb = realloc(buf, cap);
            if (nb == NULL) {
                break;
            }
            buf = nb;
        }
        k = fread(buf + n, 1u, cap - n, f);
        n += k;
        if (k == 0u) {
            break;
        }
    }
    fclose(f);
    *len = n;
    return buf != NULL ? buf : calloc(1u, 1u);
}


int main(int argc, char **argv)
{
    int json = 0;
    size_t max_plan = 256u;
    const char *file = NULL;
    int i;

    if (argc < 3) {
        return usage();
    }
    if (strcmp(argv[1], "fmt") == 0 && argc == 3) {
        size_t len = 0u;
        size_t n = 0u;
        char *text = slurp(argv[2], &len);
        mt_wpl_item_t *items = calloc(MT_CFG_MISSION_MAX_CMDS, sizeof *items);
        mt_wpl_error_t e;
        if (text == NULL || items == NULL) {
            fprintf(stderr, "mt-mission: cannot read %s\n", argv[2]);
            return 2;
        }
        if (mt_wpl_parse(text, len, items, MT_CFG_MISSION_MAX_CMDS, &n, &e) != MT_OK) {
            fprintf(stderr, "%s:%u: field %u: %s\n", argv[2], (unsigned)e.line, (unsigned)e.field, e.reason);
            return 1;
        }
        size_t need = mt_wpl_write(items, n, NULL, 0u) + 1u;
        char *out = malloc(need);
        mt_wpl_write(items, n, out, need);
        fputs(out, stdout);
        free(out);
        free(items);
        free(text);
        return 0;
    }
    if (strcmp(argv[1], "check") != 0) {
        return usage();
    }
    for (i = 2; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0) {
            json = 1;
        } else if (strcmp(argv[i], "--max-plan") == 0 && i + 1 < argc) {
            char *end = NULL;
            unsigned long v = strtoul(argv[++i], &end, 10);
            if (end == argv[i] || *end != '\0' || v == 0u || v > 1000000u) {
                return usage();
            }
            max_plan = (size_t)v;
        } else if (file == NULL && argv[i][0] != '-') {
            file = argv[i];
        } else {
            return usage();
        }
    }
    if (file == NULL) {
        return usage();
    }
    {
        size_t len = 0u;
        char *text = slurp(file, &len);
        mt_plan_step_t *plan = calloc(max_plan, sizeof *plan);
        mt_report_t *rep = calloc(1u, sizeof *rep);
        size_t need;
        char *out;
        if (text == NULL) {
            fprintf(stderr, "mt-mission: cannot read %s\n", file);
            return 2;
        }
        if (plan == NULL || rep == NULL) {
            return 2;
        }
        (void)mt_report_check(text, len, plan, max_plan, rep);
        need = (json ? mt_report_json(rep, NULL, 0u) : mt_report_text(rep, file, NULL, 0u)) + 1u;
        out = malloc(need);
        if (out == NULL) {
            return 2;
        }
        if (json) {
            mt_report_json(rep, out, need);
        } else {
            mt_report_text(rep, file, out, need);
        }
        fputs(out, stdout);
        i = rep->valid ? 0 : 1;
        free(out);
        free(plan);
        free(rep);
        free(text);
        return i;
    }
}
