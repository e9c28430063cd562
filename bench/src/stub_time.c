/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file stub_time.c
 * @brief Stub time source of the ArduPilot-style peers (AP_HAL::micros()
 *        stand-in): one microsecond per call, in its own translation unit so
 *        it is a real call, exactly like the bench port's mt_port_now_us().
 */
#include <stdint.h>

#include "ref_ap.h"

static uint32_t g_ref_now;

uint32_t ref_micros(void)
{
    return ++g_ref_now;
}
