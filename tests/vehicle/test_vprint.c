/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file test_vprint.c
 * @brief The vehicle's console formatter (vehicle/src/vprint.c) against the C library's
 *        printf on the conversions the vehicle uses, and vp_fix/vp_float rounding.
 *        Prints one line per failure; exit status 1 when any.
 */
#include <stdint.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "vprint.h"

static int failures;

static void same(const char *what, const char *got, const char *want)
{
    if (strcmp(got, want) != 0) {
        printf("FAIL %s: \"%s\", expected \"%s\"\n", what, got, want);
        failures++;
    }
}

#define BOTH(...)                                                                \
    do {                                                                         \
        char a[128];                                                             \
        char b[128];                                                             \
        size_t n = vp_snprintf(a, sizeof(a), __VA_ARGS__);                       \
        int m = snprintf(b, sizeof(b), __VA_ARGS__);                             \
        same(#__VA_ARGS__, a, b);                                                \
        if ((int)n != m) {                                                       \
            printf("FAIL length of %s: %zu, expected %d\n", #__VA_ARGS__, n, m); \
            failures++;                                                          \
        }                                                                        \
    } while (0)

int main(void)
{
    char buf[64];
    char small[8];
    int cases = 0;

    BOTH("%d %i %u", -42, 7, 4000000000u);
    BOTH("%5d|%-5d|%05d|%-5s|%5s", -42, 42, -42, "ab", "abc");
    BOTH("%x %X %08x", 255u, 0xBEEFu, 0x1234u);
    BOTH("%ld %lu %lld %llu", -123456789L, 4000000000UL, -9223372036854775807LL - 1,
         18446744073709551615ULL);
    BOTH("%zu %c%c %% %s", (size_t)12345, 'o', 'k', "done");
    BOTH("[%8s] %-15s %7s %6u", "12.345", "imu_read", "fast", 180u);
    BOTH("no conversion");
    cases += 7;

    /* truncation: NUL-terminated, length as if not truncated */
    if ((vp_snprintf(small, sizeof(small), "%s", "0123456789") != 10u) ||
        (strcmp(small, "0123456") != 0)) {
        printf("FAIL truncation: \"%s\"\n", small);
        failures++;
    }
    cases++;

    {
        static const struct {
            int64_t v;
            int64_t scale;
            unsigned d;
            const char *want;
        } t[] = {
            {12345, 1000, 1, "12.3"},
            {12350, 1000, 1, "12.4"},
            {-12350, 1000, 1, "-12.4"},
            {999999, 1000000, 3, "1.000"},
            {1999500, 1000000, 3, "2.000"},
            {0, 1000, 2, "0.00"},
            {-4, 1000, 2, "0.00"},
            {-5, 1000, 2, "-0.01"},
            {7, 1, 0, "7"},
            {-7, 1, 0, "-7"},
            {5, 10, 0, "1"},
            {1000000, 1000000, 3, "1.000"},
            {123456789012345LL, 1000000, 3, "123456789.012"},
            {4294967296LL, 1000, 1, "4294967.3"},
        };
        size_t i;
        for (i = 0u; i < sizeof(t) / sizeof(t[0]); i++) {
            char what[64];
            (void)snprintf(what, sizeof(what), "vp_fix(%lld, %lld, %u)", (long long)t[i].v,
                           (long long)t[i].scale, t[i].d);
            same(what, vp_fix(buf, sizeof(buf), t[i].v, t[i].scale, t[i].d), t[i].want);
            cases++;
        }
    }
    same("vp_float(-2.25, 1)", vp_float(buf, sizeof(buf), -2.25f, 1u), "-2.3");
    same("vp_float(16.8, 2)", vp_float(buf, sizeof(buf), 16.8f, 2u), "16.80");
    same("vp_float(0.04, 1)", vp_float(buf, sizeof(buf), 0.04f, 1u), "0.0");
    /* what int64 cannot hold is said in words (a ground station can send any float) */
    same("vp_float(NaN, 2)", vp_float(buf, sizeof(buf), nanf(""), 2u), "nan");
    same("vp_float(inf, 2)", vp_float(buf, sizeof(buf), HUGE_VALF, 2u), "inf");
    same("vp_float(-inf, 0)", vp_float(buf, sizeof(buf), -HUGE_VALF, 0u), "-inf");
    same("vp_float(1.9e25, 2)", vp_float(buf, sizeof(buf), 1.9e25f, 2u), "out of range");
    same("vp_float(-9.5e16, 2)", vp_float(buf, sizeof(buf), -9.5e16f, 2u), "out of range");
    cases += 3;
    printf("test_vprint: %d cases, %d failures\n", cases, failures);
    return failures != 0;
}
