/* SPDX-License-Identifier: Apache-2.0 */
/* libFuzzer: arbitrary command lists -> validation; accepted ones are run with
 * arbitrary verify outcomes and arbitrary stop/resume/set_current/restart,
 * checking the sequencer invariants (mt/mission.h, ardupilot.md §4.5) after
 * every call. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mt/mission.h"

#define NCMD 24u

typedef struct {
    const uint8_t *p;
    size_t n;
    mt_mission_t *m;
    uint32_t starts, verifies, completes;
} env_t;

static uint8_t take(env_t *e)
{
    uint8_t v = 0u;
    if (e->n > 0u) {
        v = *e->p++;
        e->n--;
    }
    return v;
}

static void check_cb(env_t *e, uint16_t i, const mt_mission_cmd_t *c)
{
    /* no callback sees a jump; the index is a real command */
    if (c->id == MT_MAV_CMD_DO_JUMP || c->id == MT_MAV_CMD_DO_JUMP_TAG || c->id == MT_MAV_CMD_JUMP_TAG) {
        abort();
    }
    if (i == 0u || i >= e->m->total || c != &e->m->cmd[i]) {
        abort();
    }
}

static bool start_cb(void *ctx, uint16_t i, const mt_mission_cmd_t *c)
{
    env_t *e = ctx;
    check_cb(e, i, c);
    e->starts++;
    return (take(e) & 7u) != 0u;
}

static bool verify_cb(void *ctx, uint16_t i, const mt_mission_cmd_t *c)
{
    env_t *e = ctx;
    check_cb(e, i, c);
    /* verify only on the loaded commands */
    if (i != e->m->nav && i != e->m->do_cmd) {
        abort();
    }
    e->verifies++;
    return (take(e) & 1u) != 0u;
}

static void done_cb(void *ctx)
{
    ((env_t *)ctx)->completes++;
}

static void invariants(const mt_mission_t *m)
{
    uint16_t i;
    if (m->state > MT_MISSION_COMPLETE || m->total > MT_CFG_MISSION_MAX_CMDS) {
        abort();
    }
    if (m->nav != MT_MISSION_NONE && (m->nav < 1u || m->nav >= m->total || m->kind[m->nav] != MT_MISSION_KIND_NAV)) {
        abort();
    }
    /* the active do command (or a JUMP_TAG in the do slot) needs an active nav command */
    if (m->do_cmd != MT_MISSION_NONE &&
        (m->do_cmd < 1u || m->do_cmd >= m->total ||
         (m->kind[m->do_cmd] != MT_MISSION_KIND_DO && m->kind[m->do_cmd] != MT_MISSION_KIND_TAG) ||
         m->nav == MT_MISSION_NONE || m->do_cmd != m->do_idx)) {
        abort();
    }
    if (m->nav != MT_MISSION_NONE && m->nav != m->nav_idx) {
        abort();
    }
    if (m->nav_idx != MT_MISSION_NONE &&
        (m->nav_idx < 1u || m->nav_idx >= m->total || m->kind[m->nav_idx] != MT_MISSION_KIND_NAV)) {
        abort();
    }
    for (i = 1u; i < m->total; i++) {
        if (m->kind[i] == MT_MISSION_KIND_JUMP && m->repeat[i] >= 0 &&
            (m->count[i] < 0 || m->count[i] > m->repeat[i])) {
            abort();
        }
    }
}

static const uint16_t k_ids[16] = {16, 22, 21, 20, 82, 19, 183, 178, 112, 115, 177, 177, 600, 601, 189, 9999};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static mt_mission_t m;
    static mt_mission_t before;
    mt_mission_cmd_t cmds[NCMD];
    env_t e = {data, size, &m, 0u, 0u, 0u};
    uint16_t n;
    uint16_t bad;
    uint16_t i;
    uint32_t op;
    mt_status_t st;

    mt_mission_init(&m, start_cb, verify_cb, done_cb, &e);
    n = (uint16_t)(1u + take(&e) % NCMD);
    memset(cmds, 0, sizeof cmds);
    for (i = 0u; i < n; i++) {
        uint8_t k = take(&e);
        cmds[i].id = i == 0u ? 16u : k_ids[k & 15u];
        cmds[i].frame = (take(&e) & 1u) ? 3u : 2u;
        cmds[i].param[0] = ((int32_t)(take(&e) % 32u) - 2) * MT_MISSION_MILLI;
        cmds[i].param[1] = ((int32_t)(take(&e) % 8u) - 2) * MT_MISSION_MILLI;
        if (cmds[i].id == 183u) {
            cmds[i].param[1] = 1500 * MT_MISSION_MILLI;
        }
        if ((k & 0xF0u) == 0xF0u) {
            cmds[i].param[3] = MT_MISSION_PARAM_NAN;
        }
    }
    st = mt_mission_load(&m, cmds, n, &bad);
    if ((st == MT_OK) != (bad == MT_MISSION_NONE) || (st != MT_OK && bad >= n)) {
        abort();
    }
    if (st != MT_OK) {
        return 0;
    }
    invariants(&m);
    for (op = 0u; op < 400u && e.n > 0u; op++) {
        uint8_t c = take(&e);
        uint8_t s0 = m.state;
        uint32_t done0 = e.completes;
        switch (c % 16u) {
        case 0:
            (void)mt_mission_start(&m);
            break;
        case 1:
            (void)mt_mission_stop(&m);
            break;
        case 2:
            (void)mt_mission_resume(&m);
            break;
        case 3: {
            uint16_t to = (uint16_t)(take(&e) % (NCMD + 2u));
            memcpy(&before, &m, sizeof m);
            st = mt_mission_set_current(&m, to);
            if (st != MT_OK && memcmp(&before, &m, sizeof m) != 0) {
                abort(); /* failed calls have no side effects */
            }
            break;
        }
        case 4:
            (void)mt_mission_restart_current(&m);
            break;
        case 5: {
            uint16_t out;
            memcpy(&before, &m, sizeof m);
            (void)mt_mission_next_nav(&m, (uint16_t)(take(&e) % (NCMD + 1u)), &out);
            if (memcmp(&before, &m, sizeof m) != 0) {
                abort(); /* look-ahead is pure */
            }
            break;
        }
        default:
            (void)mt_mission_update(&m);
            break;
        }
        invariants(&m);
        /* complete called exactly on the transition into COMPLETE */
        if (e.completes != done0 && !(e.completes == done0 + 1u && m.state == MT_MISSION_COMPLETE)) {
            abort();
        }
        if (s0 == MT_MISSION_RUNNING && m.state == MT_MISSION_COMPLETE && e.completes != done0 + 1u) {
            abort();
        }
        if (e.completes != m.completions) {
            abort();
        }
    }
    return 0;
}
