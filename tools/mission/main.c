/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file main.c
 * @brief mt-mission: check a mission file (QGC WPL 110 or QGroundControl .plan) and print
 *        its execution plan; convert between the two formats.
 *
 *   mt-mission check [--json] [--max-plan N] [--kernel-max N] FILE
 *                                (--kernel-max: the MT_CFG_MISSION_MAX_CMDS of the target
 *                                 kernel, default MT_TOOL_KERNEL_MAX; says whether it fits)
 *   mt-mission fmt FILE          (rewrite as canonical QGC WPL 110 to stdout: the round trip)
 *   mt-mission convert IN OUT    (the format of each by its extension: .plan, or
 *                                 .waypoints / .txt / .mission for QGC WPL 110)
 *
 * A file named *.plan is read as a .plan, *.waypoints / *.txt / *.mission as WPL; any other
 * name by its content (a .plan starts with '{').
 * Exit status: 0 valid (converted), 1 invalid, 2 usage or I/O error.
 *
 * The tool is built with its own copy of the mission library and the kernel's sequencer, with
 * MT_CFG_MISSION_MAX_CMDS at the kernel's largest setting (mission/mission.mk), so it checks a
 * mission of any size ArduPilot takes, whatever the vehicle's kernel was built with.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mfile.h"
#include "plan.h"
#include "report.h"
#include "wpl.h"

/* The kernel setting a mission is checked against by default: config.h's default. */
#if !defined(MT_TOOL_KERNEL_MAX)
#define MT_TOOL_KERNEL_MAX 700u
#endif

/* Mission files larger than this are not read (a 700-item .plan is well under 1 MiB). */
#define MAX_FILE_BYTES (16u * 1024u * 1024u)

static int usage(void)
{
    fprintf(stderr, "usage: mt-mission check [--json] [--max-plan N] [--kernel-max N] FILE\n"
                    "       mt-mission fmt FILE\n"
                    "       mt-mission convert IN OUT\n"
                    "FILE, IN, OUT: QGC WPL 110 (.waypoints, .txt, .mission) or QGroundControl .plan;\n"
                    "other names are read by their content. Exit: 0 valid, 1 invalid, 2 usage or I/O.\n");
    return 2;
}

/* The whole file, NUL-terminated; NULL (with a message) on an I/O error, a directory, or a
 * file larger than MAX_FILE_BYTES. */
static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    size_t cap = 0u;
    size_t n = 0u;
    int bad = 0;

    if (f == NULL) {
        fprintf(stderr, "mt-mission: cannot read %s: %s\n", path, strerror(errno));
        return NULL;
    }
    for (;;) {
        size_t k;
        if (n == cap) {
            char *nb;
            if (cap >= MAX_FILE_BYTES) {
                fprintf(stderr, "mt-mission: cannot read %s: larger than %u bytes\n", path,
                        (unsigned)MAX_FILE_BYTES);
                bad = 1;
                break;
            }
            cap = cap ? cap * 2u : 65536u;
            nb = realloc(buf, cap + 1u);
            if (nb == NULL) {
                fprintf(stderr, "mt-mission: cannot read %s: out of memory\n", path);
                bad = 1;
                break;
            }
            buf = nb;
        }
        errno = 0;
        k = fread(buf + n, 1u, cap - n, f);
        n += k;
        if (k == 0u) {
            if (ferror(f)) { /* EISDIR for a directory */
                fprintf(stderr, "mt-mission: cannot read %s: %s\n", path,
                        errno != 0 ? strerror(errno) : "read error");
                bad = 1;
            }
            break;
        }
    }
    fclose(f);
    if (bad) {
        free(buf);
        return NULL;
    }
    if (buf == NULL) {
        buf = malloc(1u);
        if (buf == NULL) {
            return NULL;
        }
    }
    buf[n] = '\0';
    *len = n;
    return buf;
}

/* "file:line: field F: index I:" (mt_wpl_where) */
static void print_where(FILE *out, const char *file, const mt_wpl_error_t *e)
{
    char where[MT_WPL_WHERE_MAX];

    fputs(mt_wpl_where(where, sizeof where, file, e), out);
}

static void print_warnings(const char *file, const mt_wpl_warnings_t *w)
{
    size_t i;

    for (i = 0u; i < w->n; i++) {
        print_where(stderr, file, &w->w[i]);
        fprintf(stderr, " warning: %s\n", w->w[i].reason);
    }
    if (w->dropped != 0u) {
        fprintf(stderr, "%s: warning: %u more warnings not shown\n", file, (unsigned)w->dropped);
    }
}

/* Read a mission file of either format into items (MT_CFG_MISSION_MAX_CMDS). Returns 0, or
 * the exit status (1 invalid, 2 I/O) after printing why. */
static int read_items(const char *path, mt_wpl_item_t *items, size_t *n)
{
    size_t len = 0u;
    char *text = slurp(path, &len);
    mt_wpl_warnings_t *warn = calloc(1u, sizeof *warn);
    mt_wpl_error_t e;
    mt_status_t st;

    if (text == NULL || warn == NULL) {
        free(text);
        free(warn);
        return 2;
    }
    st = mt_mfile_parse(mt_mfile_format_of_path(path), text, len, items, MT_CFG_MISSION_MAX_CMDS, n, &e, warn);
    print_warnings(path, warn);
    free(warn);
    free(text);
    if (st != MT_OK) {
        print_where(stderr, path, &e);
        fprintf(stderr, " %s [%s]\n", e.reason, mt_status_str(e.st));
        return 1;
    }
    return 0;
}

static int write_file(const char *path, const char *text, size_t len)
{
    FILE *f = fopen(path, "wb");

    if (f == NULL) {
        fprintf(stderr, "mt-mission: cannot write %s: %s\n", path, strerror(errno));
        return 2;
    }
    if (fwrite(text, 1u, len, f) != len || fclose(f) != 0) {
        fprintf(stderr, "mt-mission: cannot write %s\n", path);
        return 2;
    }
    return 0;
}

/* The items as text of format fmt (WPL or PLAN) into *out (malloc'd). Returns 0 or an exit
 * status. */
static int render(mt_mfile_format_t fmt, const mt_wpl_item_t *items, size_t n, char **out, size_t *len)
{
    if (fmt == MT_MFILE_PLAN) {
        mt_wpl_error_t e;
        mt_status_t st = mt_plan_write(items, n, out, len, &e);
        if (st != MT_OK) {
            fprintf(stderr, "mt-mission: index %u: %s [%s]\n", (unsigned)e.index, e.reason, mt_status_str(st));
            return st == MT_E_FULL ? 2 : 1;
        }
        return 0;
    }
    *len = mt_wpl_write(items, n, NULL, 0u);
    *out = malloc(*len + 1u);
    if (*out == NULL) {
        return 2;
    }
    (void)mt_wpl_write(items, n, *out, *len + 1u);
    return 0;
}

static int cmd_fmt_convert(const char *in, const char *out_path)
{
    mt_mfile_format_t ofmt = MT_MFILE_WPL;
    mt_wpl_item_t *items = calloc(MT_CFG_MISSION_MAX_CMDS, sizeof *items);
    size_t n = 0u;
    size_t len = 0u;
    char *text = NULL;
    int rc;

    if (out_path != NULL) {
        ofmt = mt_mfile_format_of_path(out_path);
        if (ofmt == MT_MFILE_AUTO) {
            fprintf(stderr, "mt-mission: %s: the output name must end in .plan, .waypoints, .txt or .mission\n",
                    out_path);
            free(items);
            return 2;
        }
    }
    if (items == NULL) {
        return 2;
    }
    rc = read_items(in, items, &n);
    if (rc == 0) {
        rc = render(ofmt, items, n, &text, &len);
    }
    if (rc == 0) {
        if (out_path == NULL) {
            fputs(text, stdout);
        } else {
            rc = write_file(out_path, text, len);
        }
    }
    free(text);
    free(items);
    return rc;
}

static int cmd_check(const char *file, int json, size_t max_plan, size_t kernel_max)
{
    size_t len = 0u;
    char *text = slurp(file, &len);
    mt_plan_step_t *plan = calloc(max_plan, sizeof *plan);
    mt_report_t *rep = calloc(1u, sizeof *rep);
    size_t need;
    char *out = NULL;
    int rc = 2;

    if (text != NULL && plan != NULL && rep != NULL) {
        (void)mt_report_check_as(mt_mfile_format_of_path(file), text, len, plan, max_plan, rep);
        rep->kernel_max = rep->valid ? kernel_max : 0u;
        need = (json ? mt_report_json(rep, NULL, 0u) : mt_report_text(rep, file, NULL, 0u)) + 1u;
        out = malloc(need);
        if (out != NULL) {
            if (json) {
                mt_report_json(rep, out, need);
            } else {
                mt_report_text(rep, file, out, need);
            }
            fputs(out, stdout);
            rc = rep->valid ? 0 : 1;
        }
    }
    free(out);
    free(plan);
    free(rep);
    free(text);
    return rc;
}

int main(int argc, char **argv)
{
    int json = 0;
    size_t max_plan = 256u;
    size_t kernel_max = MT_TOOL_KERNEL_MAX;
    const char *file = NULL;
    int i;

    if (argc < 3) {
        return usage();
    }
    if (strcmp(argv[1], "fmt") == 0 && argc == 3) {
        return cmd_fmt_convert(argv[2], NULL);
    }
    if (strcmp(argv[1], "convert") == 0) {
        return argc == 4 ? cmd_fmt_convert(argv[2], argv[3]) : usage();
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
        } else if (strcmp(argv[i], "--kernel-max") == 0 && i + 1 < argc) {
            char *end = NULL;
            unsigned long v = strtoul(argv[++i], &end, 10);
            if (end == argv[i] || *end != '\0' || v < 2u || v > 32766u) {
                return usage();
            }
            kernel_max = (size_t)v;
        } else if (file == NULL && argv[i][0] != '-') {
            file = argv[i];
        } else {
            return usage();
        }
    }
    if (file == NULL) {
        return usage();
    }
    return cmd_check(file, json, max_plan, kernel_max);
}
