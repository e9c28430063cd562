/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mission_diff_driver.c
 * @brief Runs missions and operation scripts through the kernel's mission
 *        sequencer (public API only) and prints every callback, for the
 *        differential test against the AP_Mission reference
 *        (tests/mission_diff/run_diff.py, ap_mission_ref.py).
 *
 * Input (stdin), one block per mission, integers separated by white space:
 *
 *     mission <seed> <p_nav_start> <p_do_start> <p_nav_verify> <p_do_verify> <n>
 *     <id> <frame> <options> <p1> <p2> <p3> <p4> <x> <y> <z>      (n lines, home first)
 *     ops <count>
 *     start | stop | resume | restart | set <i> | update <repeat>   (count lines)
 *     end
 *
 * Output, per mission: "mission <seed>", "load <status> <bad>", then for step k
 * (every API call is one step; "update <r>" is r steps):
 *
 *     U<k> start <idx>            start callback
 *     U<k> verify <idx> <0|1>     verify callback and its answer
 *     U<k> complete               complete callback
 *     U<k> rc <op> <status>       the call's status (update: only when not MT_OK)
 *     U<k> cur <idx|none>         the loaded nav command, when it changed
 *     U<k> count <idx> <n>        a finite jump's counter, when it changed
 *
 * and "end". Callback answers do not depend on call order: answer = splitmix64
 * hash of (seed, step, kind, index) below a per-mille probability (nav or do
 * by AP's id rule), computed identically by run_diff.py.
 */
#include <inttypes.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mt/mission.h"

#define MAX_CMDS 64u
#define KIND_START 0u
#define KIND_VERIFY 1u

typedef struct {
    uint64_t seed;
    uint32_t p_nav_start;
    uint32_t p_do_start;
    uint32_t p_nav_verify;
    uint32_t p_do_verify;
    uint64_t step;
} vehicle_t;

static mt_mission_t g_mission;
static mt_mission_cmd_t g_cmds[MAX_CMDS];

static uint64_t mix64(uint64_t z)
{
    z += UINT64_C(0x9E3779B97F4A7C15);
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

static bool outcome(const vehicle_t *v, uint32_t kind, uint16_t index, uint32_t permille)
{
    uint64_t h = mix64(v->seed);
    h = mix64(h ^ v->step);
    h = mix64(h ^ (((uint64_t)kind << 16) | (uint64_t)index));
    return (uint32_t)(h % 1000u) < permille;
}

/* AP's rule, independent of the kernel's table: nav iff id <= 95 or one of three ids. */
static bool is_nav_id(uint16_t id)
{
    return (id <= 95u) || (id == 213u) || (id == 42702u) || (id == 42703u);
}

static bool on_start(void *ctx, uint16_t index, const mt_mission_cmd_t *cmd)
{
    const vehicle_t *v = (const vehicle_t *)ctx;
    uint32_t p = is_nav_id(cmd->id) ? v->p_nav_start : v->p_do_start;

    printf("U%" PRIu64 " start %u\n", v->step, (unsigned)index);
    return outcome(v, KIND_START, index, p);
}

static bool on_verify(void *ctx, uint16_t index, const mt_mission_cmd_t *cmd)
{
    const vehicle_t *v = (const vehicle_t *)ctx;
    uint32_t p = is_nav_id(cmd->id) ? v->p_nav_verify : v->p_do_verify;
    bool ok = outcome(v, KIND_VERIFY, index, p);

    printf("U%" PRIu64 " verify %u %d\n", v->step, (unsigned)index, ok ? 1 : 0);
    return ok;
}

static void on_complete(void *ctx)
{
    const vehicle_t *v = (const vehicle_t *)ctx;

    printf("U%" PRIu64 " complete\n", v->step);
}

static int read_u64(uint64_t *out)
{
    unsigned long long x;

    if (scanf("%llu", &x) != 1) {
        return 0;
    }
    *out = (uint64_t)x;
    return 1;
}

static int read_i32(int32_t *out)
{
    long x;

    if ((scanf("%ld", &x) != 1) || (x < INT32_MIN) || (x > INT32_MAX)) {
        return 0;
    }
    *out = (int32_t)x;
    return 1;
}

static int read_u32(uint32_t *out, uint32_t max)
{
    uint64_t x;

    if ((read_u64(&x) == 0) || (x > max)) {
        return 0;
    }
    *out = (uint32_t)x;
    return 1;
}

static int read_cmd(mt_mission_cmd_t *c)
{
    uint32_t id = 0u;
    uint32_t frame = 0u;
    uint32_t options = 0u;
    int ok = read_u32(&id, 65535u) && read_u32(&frame, 255u) && read_u32(&options, 255u);

    memset(c, 0, sizeof(*c));
    ok = ok && read_i32(&c->param[0]) && read_i32(&c->param[1]) && read_i32(&c->param[2]) &&
         read_i32(&c->param[3]) && read_i32(&c->x) && read_i32(&c->y) && read_i32(&c->z);
    c->id = (uint16_t)id;
    c->frame = (uint8_t)frame;
    c->options = (uint8_t)options;
    return ok;
}

/* State the reference can observe: the loaded nav command and finite jumps' counters. */
typedef struct {
    uint16_t cur;
    int32_t count[MAX_CMDS];
} seen_t;

static void report_changes(const vehicle_t *v, uint16_t n, seen_t *seen)
{
    uint16_t i;
    uint16_t cur = MT_MISSION_NONE;

    for (i = 0u; i < n; i++) {
        mt_mission_cmd_t c;
        bool is_current = false;

        if ((mt_mission_get(&g_mission, i, &c, &is_current) == MT_OK) && is_current) {
            cur = i;
        }
    }
    if (cur != seen->cur) {
        seen->cur = cur;
        if (cur == MT_MISSION_NONE) {
            printf("U%" PRIu64 " cur none\n", v->step);
        } else {
            printf("U%" PRIu64 " cur %u\n", v->step, (unsigned)cur);
        }
    }
    for (i = 1u; i < n; i++) {
        bool jump =
            (g_cmds[i].id == MT_MAV_CMD_DO_JUMP) || (g_cmds[i].id == MT_MAV_CMD_DO_JUMP_TAG);
        int32_t k;

        if (!jump || (g_cmds[i].param[1] < 0)) {
            continue;
        }
        k = mt_mission_jump_count(&g_mission, i);
        if (k != seen->count[i]) {
            seen->count[i] = k;
            printf("U%" PRIu64 " count %u %" PRId32 "\n", v->step, (unsigned)i, k);
        }
    }
}

static void report_rc(const vehicle_t *v, const char *op, mt_status_t st, bool quiet_ok)
{
    if (!(quiet_ok && (st == MT_OK))) {
        printf("U%" PRIu64 " rc %s %d\n", v->step, op, (int)st);
    }
}

/* One step: the call, its status, the observable changes. */
static int run_op(vehicle_t *v, uint16_t n, seen_t *seen)
{
    char op[16];
    uint64_t arg = 0u;
    uint64_t r;
    uint64_t rep = 1u;
    mt_status_t st;

    if (scanf("%15s", op) != 1) {
        return 0;
    }
    if ((strcmp(op, "set") == 0) || (strcmp(op, "update") == 0)) {
        if ((read_u64(&arg) == 0) || (arg > 65535u)) {
            return 0;
        }
    }
    if (strcmp(op, "update") == 0) {
        rep = arg;
    }
    for (r = 0u; r < rep; r++) {
        v->step++;
        if (strcmp(op, "start") == 0) {
            st = mt_mission_start(&g_mission);
        } else if (strcmp(op, "stop") == 0) {
            st = mt_mission_stop(&g_mission);
        } else if (strcmp(op, "resume") == 0) {
            st = mt_mission_resume(&g_mission);
        } else if (strcmp(op, "restart") == 0) {
            st = mt_mission_restart_current(&g_mission);
        } else if (strcmp(op, "set") == 0) {
            st = mt_mission_set_current(&g_mission, (uint16_t)arg);
        } else if (strcmp(op, "update") == 0) {
            st = mt_mission_update(&g_mission);
        } else {
            return 0;
        }
        report_rc(v, op, st, strcmp(op, "update") == 0);
        report_changes(v, n, seen);
    }
    return 1;
}

static int run_mission(void)
{
    char word[16];
    vehicle_t v;
    uint32_t n;
    uint32_t i;
    uint32_t nops;
    uint16_t bad = 0u;
    mt_status_t st;
    seen_t seen;

    if (scanf("%15s", word) != 1) {
        return 0; /* end of input */
    }
    if ((strcmp(word, "mission") != 0) || (read_u64(&v.seed) == 0) ||
        (read_u32(&v.p_nav_start, 1000u) == 0) || (read_u32(&v.p_do_start, 1000u) == 0) ||
        (read_u32(&v.p_nav_verify, 1000u) == 0) || (read_u32(&v.p_do_verify, 1000u) == 0) ||
        (read_u32(&n, MAX_CMDS) == 0) || (n < 1u)) {
        return -1;
    }
    for (i = 0u; i < n; i++) {
        if (read_cmd(&g_cmds[i]) == 0) {
            return -1;
        }
    }
    if ((scanf("%15s", word) != 1) || (strcmp(word, "ops") != 0) ||
        (read_u32(&nops, 100000u) == 0)) {
        return -1;
    }
    v.step = 0u;
    printf("mission %" PRIu64 "\n", v.seed);
    mt_mission_init(&g_mission, on_start, on_verify, on_complete, &v);
    st = mt_mission_load(&g_mission, g_cmds, (uint16_t)n, &bad);
    printf("load %d %u\n", (int)st, (unsigned)bad);
    seen.cur = MT_MISSION_NONE;
    for (i = 0u; i < MAX_CMDS; i++) {
        seen.count[i] = 0;
    }
    for (i = 0u; i < nops; i++) {
        if (st != MT_OK) {
            char skip[16];
            uint64_t a;

            if (scanf("%15s", skip) != 1) {
                return -1;
            }
            if (((strcmp(skip, "set") == 0) || (strcmp(skip, "update") == 0)) &&
                (read_u64(&a) == 0)) {
                return -1;
            }
            continue;
        }
        if (run_op(&v, (uint16_t)n, &seen) == 0) {
            return -1;
        }
    }
    if ((scanf("%15s", word) != 1) || (strcmp(word, "end") != 0)) {
        return -1;
    }
    printf("end\n");
    return 1;
}

int main(void)
{
    int r;

    while ((r = run_mission()) > 0) {
    }
    if (r < 0) {
        fprintf(stderr, "mission_diff_driver: malformed input\n");
        return 2;
    }
    return 0;
}
