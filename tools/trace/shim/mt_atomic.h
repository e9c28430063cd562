/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file tools/trace/shim/mt_atomic.h
 * @brief Trace build only: replaces kernel/port/mt_atomic.h (it comes first on
 *        the include path), so that every acquire load and release store of a
 *        shared ring index goes through the trace harness. The harness yields
 *        to its scheduler before the access (the other side may run), does the
 *        access with the same __atomic builtin as the real header, and logs it.
 */
#ifndef MT_ATOMIC_H
#define MT_ATOMIC_H

#include <stdint.h>

uint32_t mt_trace_load_acquire(const uint32_t *p);
void mt_trace_store_release(uint32_t *p, uint32_t v);

static inline uint32_t mt_load_acquire_u32(const uint32_t *p)
{
    return mt_trace_load_acquire(p);
}

static inline void mt_store_release_u32(uint32_t *p, uint32_t v)
{
    mt_trace_store_release(p, v);
}

#endif /* MT_ATOMIC_H */
