/* SPDX-License-Identifier: Apache-2.0 */
/* The trace drivers' deterministic PRNG (xorshift64*): one sequence per seed. */
#ifndef TRACE_RNG_H
#define TRACE_RNG_H

#include <stdint.h>

/* Next value in [0, n) from the state *s (n > 0, *s != 0). */
static inline uint32_t trace_rnd(uint64_t *s, uint32_t n)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return (uint32_t)(((*s * 2685821657736338717ull) >> 33) % n);
}

#endif /* TRACE_RNG_H */
