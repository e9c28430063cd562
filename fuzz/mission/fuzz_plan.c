/* SPDX-License-Identifier: Apache-2.0 */
/* libFuzzer: arbitrary bytes -> .plan reader (cJSON) -> check report; whatever the reader
 * accepts, .plan write -> read and WPL write -> read give the same items, bit for bit. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "plan.h"
#include "report.h"
#include "wpl.h"

#define CAP 256u

static void same_items(const mt_wpl_item_t *a, const mt_wpl_item_t *b, size_t n)
{
    size_t i;

    for (i = 0u; i < n; i++) {
        int f;
        if (a[i].seq != b[i].seq || a[i].current != b[i].current || a[i].frame != b[i].frame ||
            a[i].command != b[i].command || a[i].autocontinue != b[i].autocontinue) {
            abort();
        }
        for (f = 0; f < 7; f++) {
            if (isnan(a[i].p[f]) ? !isnan(b[i].p[f]) : memcmp(&a[i].p[f], &b[i].p[f], sizeof(double)) != 0) {
                abort();
            }
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static mt_wpl_item_t a[CAP];
    static mt_wpl_item_t b[CAP];
    static mt_plan_step_t plan[64];
    static mt_report_t rep;
    mt_wpl_warnings_t warn;
    mt_wpl_error_t e;
    size_t na = 0u;
    size_t nb = 0u;
    size_t len = 0u;
    char *text = NULL;

    (void)mt_report_check_as(MT_MFILE_PLAN, (const char *)data, size, plan, 64u, &rep);
    if (rep.nplan > 64u || (rep.valid && rep.nerr != 0u) || (!rep.valid && rep.nerr == 0u) ||
        rep.warnings.n > MT_WPL_MAX_WARNINGS) {
        abort();
    }
    memset(&warn, 0, sizeof warn);
    if (mt_plan_parse((const char *)data, size, a, CAP, &na, &e, &warn) != MT_OK) {
        if (e.st == MT_OK || na != 0u) {
            abort();
        }
        return 0;
    }
    if (na == 0u || a[0].command != 16u) {
        abort();
    }
    /* .plan round trip */
    if (mt_plan_write(a, na, &text, &len, &e) != MT_OK) {
        abort(); /* the reader produces nothing the writer refuses */
    }
    if (mt_plan_parse(text, len, b, CAP, &nb, &e, NULL) != MT_OK || nb != na) {
        abort();
    }
    same_items(a, b, na);
    free(text);
    /* through WPL */
    len = mt_wpl_write(a, na, NULL, 0u) + 1u;
    text = malloc(len);
    if (text == NULL) {
        return 0;
    }
    mt_wpl_write(a, na, text, len);
    if (mt_wpl_parse(text, len - 1u, b, CAP, &nb, &e, NULL) != MT_OK || nb != na) {
        abort();
    }
    same_items(a, b, na);
    free(text);
    return 0;
}
