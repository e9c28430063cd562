/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file item.c
 * @brief One mission item to the kernel's integer command (item.h): the mission
 *        files' float rules, the command names and the frames ArduPilot ignores.
 *        No stdio: linked by the host library and by the firmware.
 */
#include "item.h"

#include "mav_cmd_names.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* The generated row of a command id (mav_cmd_names.h, sorted by id), or NULL. */
static const mt_mav_cmd_name_t *cmd_row(uint32_t id)
{
    size_t lo = 0u, hi = MT_MAV_CMD_NAMES_COUNT;

    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2u;
        if (k_mav_cmd_names[mid].id == id) {
            return &k_mav_cmd_names[mid];
        }
        if (k_mav_cmd_names[mid].id < id) {
            lo = mid + 1u;
        } else {
            hi = mid;
        }
    }
    return NULL;
}

int mt_wpl_frame_ignored(uint32_t command)
{
    const mt_mav_cmd_name_t *row;
    uint8_t kind;

    if (command > 0xFFFFu) {
        return 0;
    }
    kind = mt_mission_kind_of((uint16_t)command);
    if (kind != MT_MISSION_KIND_DO && kind != MT_MISSION_KIND_JUMP && kind != MT_MISSION_KIND_TAG) {
        return 0; /* nav commands, home, unknown ids */
    }
    /* do commands with a location (the kernel's F_LOC, MAVLink's hasLocation): frame matters */
    row = cmd_row(command);
    return (row != NULL && row->location != 0u) ? 0 : 1;
}

/* Frames the kernel accepts for some command (mission_check.c frame_ok). */
static int frame_known(uint32_t frame)
{
    return frame == 0u || frame == 2u || frame == 3u || frame == 5u || frame == 6u ||
           frame == 10u || frame == 11u;
}

/* round(v * scale) into int32, if finite and in range. */
static int to_fixed(double v, double scale, double limit, int32_t *out)
{
    double s;

    if (isfinite(v) == 0) {
        return 0;
    }
    s = v * scale;
    if (!(s > -limit && s < limit)) {
        return 0;
    }
    *out = (int32_t)llround(s);
    return 1;
}

const char *mt_item_field_name(uint32_t field)
{
    static const char *const names[9] = {"frame",        "command",       "param1",
                                         "param2",       "param3",        "param4",
                                         "x (latitude)", "y (longitude)", "z (altitude)"};

    return ((field >= 3u) && (field <= 11u)) ? names[field - 3u] : "";
}

const char *mt_item_why_str(mt_item_why_t why)
{
    switch (why) {
    case MT_ITEM_NOT_A_CMD: return "not a MAV_CMD number";
    case MT_ITEM_NOT_A_FRAME: return "not a MAV_FRAME number";
    case MT_ITEM_INFINITE: return "infinite";
    case MT_ITEM_OUT_OF_RANGE: return "out of range";
    case MT_ITEM_NAN_NOT_ALLOWED: return "NaN is not allowed";
    case MT_ITEM_OK:
    default: return "";
    }
}

static mt_status_t fault(mt_item_fault_t *f, mt_status_t st, uint32_t field, mt_item_why_t why)
{
    f->st = st;
    f->field = field;
    f->why = why;
    return st;
}

mt_status_t mt_item_to_cmd(const mt_wpl_item_t *it, mt_mission_cmd_t *out, mt_item_fault_t *f)
{
    int k;

    memset(out, 0, sizeof *out);
    (void)fault(f, MT_OK, 0u, MT_ITEM_OK);
    if (it->command > 0xFFFFu) {
        return fault(f, MT_E_MISSION_CMD, 4u, MT_ITEM_NOT_A_CMD);
    }
    if (it->frame > 0xFFu) {
        return fault(f, MT_E_MISSION_FRAME, 3u, MT_ITEM_NOT_A_FRAME);
    }
    out->id = (uint16_t)it->command;
    /* a frame ArduPilot ignores is given to the kernel as MISSION (see wpl.h) */
    out->frame =
        (mt_wpl_frame_ignored(it->command) && !frame_known(it->frame)) ? 2u : (uint8_t)it->frame;
    out->options = (uint8_t)(it->autocontinue & 1u);
    for (k = 0; k < 4; k++) {
        if (isnan(it->p[k])) {
            out->param[k] = MT_MISSION_PARAM_NAN;
            continue;
        }
        if (!to_fixed(it->p[k], (double)MT_MISSION_MILLI, 2147483647.0, &out->param[k]) ||
            out->param[k] == MT_MISSION_PARAM_NAN) {
            return fault(f, MT_E_MISSION_PARAM, 5u + (uint32_t)k,
                         isinf(it->p[k]) ? MT_ITEM_INFINITE : MT_ITEM_OUT_OF_RANGE);
        }
    }
    for (k = 4; k < 7; k++) {
        int32_t v = 0;
        double scale = (k < 6) ? 1e7 : 100.0;
        if (isnan(it->p[k]) || !to_fixed(it->p[k], scale, 2147483647.0, &v)) {
            return fault(f, MT_E_MISSION_PARAM, 5u + (uint32_t)k,
                         isnan(it->p[k])   ? MT_ITEM_NAN_NOT_ALLOWED
                         : isinf(it->p[k]) ? MT_ITEM_INFINITE
                                           : MT_ITEM_OUT_OF_RANGE);
        }
        if (k == 4) {
            out->x = v;
        } else if (k == 5) {
            out->y = v;
        } else {
            out->z = v;
        }
    }
    return MT_OK;
}

const char *mt_wpl_cmd_name(uint32_t id)
{
    const mt_mav_cmd_name_t *row = cmd_row(id);

    return row != NULL ? row->name : NULL;
}
