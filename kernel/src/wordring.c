/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file wordring.c
 * @brief SPSC word ring (see mt/wordring.h): initialisation. push, pop and available are inline
 *        in the header; WP proves them here, in the one kernel file that includes it.
 */
#include "mt/wordring.h"

void mt_wring_init(mt_wring_t *r)
{
    r->tail = 0u;
    r->head_cache = 0u;
    r->rejected = 0u;
    r->head = 0u;
    r->tail_cache = 0u;
    r->unused_ = 0u;
}
