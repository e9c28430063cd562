/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file port_halt.c
 * @brief mt_port_halt() in the CBMC build: the kernel halts only on a contract violation,
 *        so reaching it is a failed property (the other port functions are contract stubs
 *        generated from kernel/port/mt_port.h into mtc_stubs.c).
 */
#include "mtc_logic.h"

void mt_port_halt(const char *reason)
{
    (void)reason;
    __CPROVER_assert(0, "mt_port_halt: reached (a contract violation was detected at run time)");
    __CPROVER_assume(0);
}
