/* SPDX-License-Identifier: Apache-2.0 */
/* libFuzzer: whatever the reader accepts, write -> read gives the same items. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "wpl.h"

#define CAP 256u

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static mt_wpl_item_t a[CAP];
    static mt_wpl_item_t b[CAP];
    size_t na = 0u;
    size_t nb = 0u;
    size_t need;
    size_t i;
    char *text;
    mt_wpl_error_t e;

    if (mt_wpl_parse((const char *)data, size, a, CAP, &na, &e, NULL) != MT_OK) {
        return 0;
    }
    need = mt_wpl_write(a, na, NULL, 0u) + 1u;
    text = malloc(need);
    if (text == NULL) {
        return 0;
    }
    mt_wpl_write(a, na, text, need);
    if (mt_wpl_parse(text, need - 1u, b, CAP, &nb, &e, NULL) != MT_OK || nb != na) {
        abort();
    }
    for (i = 0u; i < na; i++) {
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
    free(text);
    return 0;
}
