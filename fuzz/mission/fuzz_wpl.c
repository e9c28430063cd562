/* SPDX-License-Identifier: Apache-2.0 */
/* libFuzzer: arbitrary bytes -> mission file reader -> conversion -> validation -> plan. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "report.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static mt_plan_step_t plan[64];
    static mt_report_t rep;
    char *out;
    size_t need;

    (void)mt_report_check((const char *)data, size, plan, 64u, &rep);
    if (rep.nplan > 64u || (rep.valid && rep.nerr != 0u) || (!rep.valid && rep.nerr == 0u)) {
        abort();
    }
    need = mt_report_json(&rep, NULL, 0u) + 1u;
    out = malloc(need);
    if (out != NULL) {
        mt_report_json(&rep, out, need);
        free(out);
    }
    return 0;
}
