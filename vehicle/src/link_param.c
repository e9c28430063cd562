/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file link_param.c
 * @brief The link's parameters: the table (ArduPilot's names, types, ranges; documented in
 *        vehicle/README.md, "MAVLink"), PARAM_VALUE, and PARAM_REQUEST_READ and PARAM_SET as
 *        link.c hands them here. A set is taken only in range and always answered with the
 *        value in force; refused sets and unknown names are counted.
 */
#include <string.h>

#include "link_int.h"

typedef struct {
    const char *name; /* ArduPilot's name for the same setting */
    uint8_t type;     /* MAV_PARAM_TYPE_* it is announced with */
    float min;
    float max;
} veh_param_def_t;

/* Index order is PARAM_VALUE's param_index. */
static const veh_param_def_t k_params[VEH_NPARAMS] = {
    {"SYSID_THISMAV", MAV_PARAM_TYPE_INT16, 1.0f, 255.0f},
    {"WPNAV_SPEED", MAV_PARAM_TYPE_REAL32, 50.0f, 1500.0f},
    {"FS_GCS_ENABLE", MAV_PARAM_TYPE_INT8, 0.0f, 5.0f},
    {"FS_GCS_TIMEOUT", MAV_PARAM_TYPE_REAL32, 2.0f, 120.0f},
    {"PILOT_TKOFF_ALT", MAV_PARAM_TYPE_REAL32, 0.0f, 1000.0f},
};

static float param_get(const veh_t *v, uint32_t i)
{
    switch (i) {
    case VEH_PARAM_SYSID: return (float)v->par.sysid;
    case VEH_PARAM_WPNAV_SPEED: return v->par.wpnav_speed_cms;
    case VEH_PARAM_FS_GCS_ENABLE: return (float)v->par.fs_gcs_enable;
    case VEH_PARAM_PILOT_TKOFF_ALT: return v->par.pilot_tkoff_alt_cm;
    case VEH_PARAM_FS_GCS_TIMEOUT:
    default: return v->par.fs_gcs_timeout_s;
    }
}

/* x is a value parameter i may take (in range; FS_GCS_ENABLE: one of its actions). */
static bool param_ok(uint32_t i, float x)
{
    if (!isfinite(x) || (x < k_params[i].min) || (x > k_params[i].max)) {
        return false;
    }
    if (i == VEH_PARAM_FS_GCS_ENABLE) {
        return (x == (float)VEH_FS_GCS_CONTINUE) || (x == (float)VEH_FS_GCS_RTL) ||
               (x == (float)VEH_FS_GCS_LAND);
    }
    return true;
}

static void param_set(veh_t *v, uint32_t i, float x)
{
    switch (i) {
    case VEH_PARAM_SYSID: v->par.sysid = (uint8_t)x; break;
    case VEH_PARAM_WPNAV_SPEED: v->par.wpnav_speed_cms = x; break;
    case VEH_PARAM_FS_GCS_ENABLE: v->par.fs_gcs_enable = (uint8_t)x; break;
    case VEH_PARAM_PILOT_TKOFF_ALT: v->par.pilot_tkoff_alt_cm = x; break;
    case VEH_PARAM_FS_GCS_TIMEOUT:
    default: v->par.fs_gcs_timeout_s = x; break;
    }
    v->par.gen[i]++;
}

/* Index of the parameter named id (16 bytes, NUL-terminated unless all 16 are used), or
 * VEH_NPARAMS. */
static uint32_t param_find(const char id[16])
{
    uint32_t i;

    for (i = 0u; i < VEH_NPARAMS; i++) {
        size_t n = strlen(k_params[i].name);
        if ((memcmp(id, k_params[i].name, n) == 0) && ((n == 16u) || (id[n] == '\0'))) {
            return i;
        }
    }
    return VEH_NPARAMS;
}

void veh_params_default(veh_params_t *p)
{
    p->sysid = 1u;
    p->wpnav_speed_cms = 500.0f;
    p->fs_gcs_enable = (uint8_t)VEH_FS_GCS_RTL;
    p->fs_gcs_timeout_s = 5.0f;
    p->pilot_tkoff_alt_cm = 0.0f; /* ArduCopter's default */
    (void)memset(p->gen, 0, sizeof(p->gen));
}

void veh_lparam_send(veh_t *v, uint32_t i)
{
    mavlink_message_t m;
    char id[17];

    (void)memset(id, 0, sizeof(id));
    (void)strncpy(id, k_params[i].name, 16u);
    (void)mavlink_msg_param_value_pack_chan(v->par.sysid, VEH_LINK_COMPID, VEH_LINK_CHAN, &m, id,
                                            param_get(v, i), k_params[i].type,
                                            (uint16_t)VEH_NPARAMS, (uint16_t)i);
    veh_link_send(v, &m);
}

static void on_param_request_read(veh_t *v, const mavlink_message_t *m)
{
    mavlink_param_request_read_t r;
    uint32_t i;

    mavlink_msg_param_request_read_decode(m, &r);
    i = (r.param_index >= 0) ? (uint32_t)r.param_index : param_find(r.param_id);
    if (i < VEH_NPARAMS) {
        veh_lparam_send(v, i);
    } else {
        v->c.link_param_unknown++;
    }
}

/* PARAM_SET: a known name with a value in range is set; the answer is always the PARAM_VALUE
 * now in force (the old value when refused), as ArduPilot and the protocol do. */
static void on_param_set(veh_t *v, const mavlink_message_t *m)
{
    mavlink_param_set_t r;
    uint32_t i;
    float x;

    mavlink_msg_param_set_decode(m, &r);
    i = param_find(r.param_id);
    if (i >= VEH_NPARAMS) {
        v->c.link_param_unknown++;
        return;
    }
    x = r.param_value;
    if ((k_params[i].type != MAV_PARAM_TYPE_REAL32) && isfinite(x)) {
        x = roundf(x);
    }
    if (param_ok(i, x)) {
        param_set(v, i, x);
        veh_say("param: %s set to %s", k_params[i].name, vp_float((char[24]){0}, 24u, x, 2u));
    } else {
        v->c.link_param_refused++;
        veh_say("param: %s refused (%s: range %s .. %s%s)", k_params[i].name,
                vp_float((char[24]){0}, 24u, x, 2u),
                vp_float((char[24]){0}, 24u, k_params[i].min, 0u),
                vp_float((char[24]){0}, 24u, k_params[i].max, 0u),
                (i == VEH_PARAM_FS_GCS_ENABLE) ? "; 0, 1 or 5" : "");
    }
    veh_lparam_send(v, i);
}

bool veh_lparam_on_message(veh_t *v, const mavlink_message_t *m)
{
    switch (m->msgid) {
    case MAVLINK_MSG_ID_PARAM_REQUEST_READ: on_param_request_read(v, m); return true;
    case MAVLINK_MSG_ID_PARAM_SET: on_param_set(v, m); return true;
    default: return false;
    }
}
