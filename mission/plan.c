/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file plan.c
 * @brief QGroundControl .plan reader and writer, mission part (see plan.h).
 */
#include "plan.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PLAN_FIELD_JUMP_ID 1u
#define PLAN_FIELD_FRAME 3u
#define PLAN_FIELD_COMMAND 4u
#define PLAN_FIELD_PARAM1 5u
#define PLAN_FIELD_AUTOCONTINUE 12u

/* 1-based line and column of text[off]. */
static uint32_t line_of(const char *text, size_t off, uint32_t *col)
{
    uint32_t line = 1u;
    uint32_t c = 1u;
    size_t i;

    for (i = 0u; i < off; i++) {
        if (text[i] == '\n' || (text[i] == '\r' && (i + 1u >= off || text[i + 1u] != '\n'))) {
            line++;
            c = 1u;
        } else if (text[i] != '\r') {
            c++;
        }
    }
    *col = c;
    return line;
}

/* An upper bound of the JSON values cJSON would create: one for the top level plus one
 * after every '[', ',' and ':' outside strings. Runs before cJSON allocates anything. */
static size_t count_values(const char *text, size_t len)
{
    size_t nv = 1u;
    size_t i;
    int in_str = 0;

    for (i = 0u; i < len; i++) {
        char c = text[i];
        if (in_str) {
            if (c == '\\') {
                i++;
            } else if (c == '"') {
                in_str = 0;
            }
        } else if (c == '"') {
            in_str = 1;
        } else if (c == '[' || c == ',' || c == ':') {
            nv++;
        }
    }
    return nv;
}

/* An integer-valued finite number in [0, max]. */
static int get_uint(const cJSON *v, double max, uint32_t *out)
{
    double d;

    if (!cJSON_IsNumber(v)) {
        return 0;
    }
    d = v->valuedouble;
    if (!(d >= 0.0 && d <= max) || floor(d) != d) {
        return 0;
    }
    *out = (uint32_t)d;
    return 1;
}

static size_t array_len(const cJSON *obj, const char *key)
{
    const cJSON *a = cJSON_GetObjectItemCaseSensitive(obj, key);
    return cJSON_IsArray(a) ? (size_t)cJSON_GetArraySize(a) : 0u;
}

/* The one simple item items[k] of the JSON (mission index k + 1) into *it; its doJumpId
 * (or -1) into *jump_id. */
static mt_status_t read_simple(const cJSON *obj, size_t k, mt_wpl_item_t *it, double *jump_id,
                               mt_wpl_error_t *err)
{
    const uint32_t idx = (uint32_t)(k + 1u);
    const cJSON *v;
    const cJSON *p;
    uint32_t f;

    memset(it, 0, sizeof *it);
    it->seq = idx;
    v = cJSON_GetObjectItemCaseSensitive(obj, "command");
    if (!get_uint(v, 4294967295.0, &it->command)) {
        mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 0u, PLAN_FIELD_COMMAND, idx,
                         "mission.items[%u].command: %s", (unsigned)k,
                         v == NULL ? "missing" : "not an unsigned integer");
        return MT_E_MISSION_SYNTAX;
    }
    v = cJSON_GetObjectItemCaseSensitive(obj, "frame");
    if (!get_uint(v, 4294967295.0, &it->frame)) {
        mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 0u, PLAN_FIELD_FRAME, idx,
                         "mission.items[%u].frame: %s", (unsigned)k,
                         v == NULL ? "missing" : "not an unsigned integer");
        return MT_E_MISSION_SYNTAX;
    }
    p = cJSON_GetObjectItemCaseSensitive(obj, "params");
    if (!cJSON_IsArray(p) || cJSON_GetArraySize(p) != 7) {
        mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 0u, PLAN_FIELD_PARAM1, idx,
                         "mission.items[%u].params: %s", (unsigned)k,
                         p == NULL ? "missing" : "not an array of 7 numbers (null for NaN)");
        return MT_E_MISSION_SYNTAX;
    }
    f = 0u;
    for (v = p->child; v != NULL; v = v->next, f++) {
        if (cJSON_IsNull(v)) {
            it->p[f] = NAN;
        } else if (cJSON_IsNumber(v) && isfinite(v->valuedouble)) {
            it->p[f] = v->valuedouble;
        } else {
            mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 0u, PLAN_FIELD_PARAM1 + f, idx,
                             "mission.items[%u].params[%u]: %s", (unsigned)k, (unsigned)f,
                             cJSON_IsNumber(v) ? "out of range" : "not a number or null");
            return MT_E_MISSION_SYNTAX;
        }
    }
    v = cJSON_GetObjectItemCaseSensitive(obj, "autoContinue");
    if (!cJSON_IsBool(v)) {
        mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 0u, PLAN_FIELD_AUTOCONTINUE, idx,
                         "mission.items[%u].autoContinue: %s", (unsigned)k,
                         v == NULL ? "missing" : "not true or false");
        return MT_E_MISSION_SYNTAX;
    }
    it->autocontinue = cJSON_IsTrue(v) ? 1u : 0u;
    v = cJSON_GetObjectItemCaseSensitive(obj, "doJumpId");
    *jump_id = -1.0;
    if (v != NULL) {
        uint32_t id = 0u;
        if (!get_uint(v, 4294967295.0, &id)) {
            mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 0u, PLAN_FIELD_JUMP_ID, idx,
                             "mission.items[%u].doJumpId: not an unsigned integer", (unsigned)k);
            return MT_E_MISSION_SYNTAX;
        }
        *jump_id = (double)id;
    }
    return MT_OK;
}

/* DO_JUMP param 1 names a doJumpId (QGC MissionController): replace it by the index of the
 * first simple item with that doJumpId. */
static mt_status_t fix_jumps(mt_wpl_item_t *items, size_t n, const double *jump_id, mt_wpl_error_t *err,
                             mt_wpl_warnings_t *warn)
{
    size_t i;
    size_t j;

    for (i = 1u; i < n; i++) {
        double want;
        if (items[i].command != MT_MAV_CMD_DO_JUMP) {
            continue;
        }
        want = items[i].p[0];
        if (!isfinite(want) || want < 0.0 || want > 4294967295.0) {
            mt_wpl_set_error(err, MT_E_MISSION_JUMP, 0u, PLAN_FIELD_PARAM1, (uint32_t)i,
                             "mission.items[%u].params[0]: DO_JUMP target is not a doJumpId",
                             (unsigned)(i - 1u));
            return MT_E_MISSION_JUMP;
        }
        want = trunc(want); /* QGC: static_cast<int>(param1) */
        for (j = 1u; j < n && jump_id[j] != want; j++) {
        }
        if (j == n) {
            mt_wpl_set_error(
                err, MT_E_MISSION_JUMP, 0u, PLAN_FIELD_PARAM1, (uint32_t)i,
                "mission.items[%u].params[0]: DO_JUMP to doJumpId %.0f: no item has it",
                (unsigned)(i - 1u), want);
            return MT_E_MISSION_JUMP;
        }
        if (items[i].p[0] != (double)j) {
            mt_wpl_warn(warn, 0u, PLAN_FIELD_PARAM1, (uint32_t)i,
                        "mission.items[%u]: DO_JUMP to doJumpId %.0f is index %u", (unsigned)(i - 1u), want,
                        (unsigned)j);
            items[i].p[0] = (double)j;
        }
    }
    return MT_OK;
}

static mt_status_t read_mission(const cJSON *root, mt_wpl_item_t *items, size_t cap, size_t *n,
                                mt_wpl_error_t *err, mt_wpl_warnings_t *warn)
{
    const cJSON *v;
    const cJSON *mission;
    const cJSON *list;
    const cJSON *home;
    const cJSON *x;
    double *jump_id;
    size_t count;
    size_t k;
    mt_status_t st = MT_OK;

    if (!cJSON_IsObject(root)) {
        mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 1u, 0u, MT_MISSION_NONE,
                         "the top level is not a JSON object");
        return MT_E_MISSION_SYNTAX;
    }
    v = cJSON_GetObjectItemCaseSensitive(root, "fileType");
    if (!cJSON_IsString(v) || strcmp(v->valuestring, "Plan") != 0) {
        mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 0u, 0u, MT_MISSION_NONE, "fileType: %s",
                         v == NULL ? "missing (a .plan has \"fileType\": \"Plan\")"
                                   : "not \"Plan\"");
        return MT_E_MISSION_SYNTAX;
    }
    v = cJSON_GetObjectItemCaseSensitive(root, "version");
    if (!cJSON_IsNumber(v) || v->valuedouble != 1.0) {
        mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 0u, 0u, MT_MISSION_NONE, "version: %s",
                         v == NULL ? "missing" : "not 1 (the only .plan version)");
        return MT_E_MISSION_SYNTAX;
    }
    mission = cJSON_GetObjectItemCaseSensitive(root, "mission");
    if (!cJSON_IsObject(mission)) {
        mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 0u, 0u, MT_MISSION_NONE, "mission: %s",
                         mission == NULL ? "missing" : "not an object");
        return MT_E_MISSION_SYNTAX;
    }
    v = cJSON_GetObjectItemCaseSensitive(mission, "version");
    if (!cJSON_IsNumber(v) || v->valuedouble != 2.0) {
        mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 0u, 0u, MT_MISSION_NONE, "mission.version: %s",
                         v == NULL ? "missing" : "not 2 (QGC's mission format 2 is read)");
        return MT_E_MISSION_SYNTAX;
    }
    home = cJSON_GetObjectItemCaseSensitive(mission, "plannedHomePosition");
    if (!cJSON_IsArray(home) || cJSON_GetArraySize(home) != 3) {
        mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 0u, 0u, 0u, "mission.plannedHomePosition: %s",
                         home == NULL ? "missing" : "not [latitude, longitude, altitude]");
        return MT_E_MISSION_SYNTAX;
    }
    list = cJSON_GetObjectItemCaseSensitive(mission, "items");
    if (!cJSON_IsArray(list)) {
        mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 0u, 0u, MT_MISSION_NONE, "mission.items: %s",
                         list == NULL ? "missing" : "not an array");
        return MT_E_MISSION_SYNTAX;
    }
    count = (size_t)cJSON_GetArraySize(list);
    if (cap == 0u || count > cap - 1u) {
        mt_wpl_set_error(err, MT_E_MISSION_SIZE, 0u, 0u, MT_MISSION_NONE,
                         "mission.items: %u items and the home are more than %u", (unsigned)count,
                         (unsigned)cap);
        return MT_E_MISSION_SIZE;
    }
    /* item 0: the planned home */
    memset(&items[0], 0, sizeof items[0]);
    items[0].current = 1u;
    items[0].command = MT_MAV_CMD_WAYPOINT;
    items[0].autocontinue = 1u;
    k = 0u;
    for (x = home->child; x != NULL; x = x->next, k++) {
        if (!cJSON_IsNumber(x) || !isfinite(x->valuedouble)) {
            mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 0u, 9u + (uint32_t)k, 0u,
                             "mission.plannedHomePosition[%u]: not a number", (unsigned)k);
            return MT_E_MISSION_SYNTAX;
        }
        items[0].p[4u + k] = x->valuedouble;
    }
    jump_id = calloc(count + 1u, sizeof *jump_id);
    if (jump_id == NULL) {
        mt_wpl_set_error(err, MT_E_FULL, 0u, 0u, MT_MISSION_NONE, "out of memory");
        return MT_E_FULL;
    }
    jump_id[0] = -1.0; /* the home is no jump target */
    k = 0u;
    for (x = list->child; x != NULL && st == MT_OK; x = x->next, k++) {
        const cJSON *type = cJSON_GetObjectItemCaseSensitive(x, "type");
        const uint32_t idx = (uint32_t)(k + 1u);
        if (!cJSON_IsObject(x) || !cJSON_IsString(type)) {
            mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, 0u, 0u, idx, "mission.items[%u]: %s",
                             (unsigned)k, cJSON_IsObject(x) ? "no \"type\"" : "not an object");
            st = MT_E_MISSION_SYNTAX;
        } else if (strcmp(type->valuestring, "ComplexItem") == 0) {
            const cJSON *ct = cJSON_GetObjectItemCaseSensitive(x, "complexItemType");
            mt_wpl_set_error(err, MT_E_MISSION_CMD, 0u, 0u, idx,
                             "mission.items[%u]: complex item \"%.24s\" refused: QGC makes its "
                             "waypoints only on upload",
                             (unsigned)k, cJSON_IsString(ct) ? ct->valuestring : "?");
            st = MT_E_MISSION_CMD;
        } else if (strcmp(type->valuestring, "SimpleItem") != 0) {
            mt_wpl_set_error(
                err, MT_E_MISSION_SYNTAX, 0u, 0u, idx,
                "mission.items[%u].type: \"%.24s\" is neither SimpleItem nor ComplexItem",
                (unsigned)k, type->valuestring);
            st = MT_E_MISSION_SYNTAX;
        } else {
            st = read_simple(x, k, &items[idx], &jump_id[idx], err);
        }
    }
    if (st == MT_OK) {
        *n = count + 1u;
        st = fix_jumps(items, *n, jump_id, err, warn);
    }
    free(jump_id);
    if (st != MT_OK) {
        *n = 0u;
        return st;
    }
    /* what the mission does not carry */
    v = cJSON_GetObjectItemCaseSensitive(root, "geoFence");
    if (cJSON_IsObject(v)) {
        size_t polys = array_len(v, "polygons") + (array_len(v, "polygon") > 0u ? 1u : 0u);
        size_t circles = array_len(v, "circles");
        if (polys + circles > 0u) {
            mt_wpl_warn(warn, 0u, 0u, MT_MISSION_NONE,
                        "geoFence: %u polygon(s) and %u circle(s) not carried (the mission only is read)",
                        (unsigned)polys, (unsigned)circles);
        }
    }
    v = cJSON_GetObjectItemCaseSensitive(root, "rallyPoints");
    if (cJSON_IsObject(v) && array_len(v, "points") > 0u) {
        mt_wpl_warn(warn, 0u, 0u, MT_MISSION_NONE,
                    "rallyPoints: %u point(s) not carried (the mission only is read)",
                    (unsigned)array_len(v, "points"));
    }
    return MT_OK;
}

mt_status_t mt_plan_parse(const char *text, size_t len, mt_wpl_item_t *items, size_t cap, size_t *n,
                          mt_wpl_error_t *err, mt_wpl_warnings_t *warn)
{
    static const char bom[] = "\xEF\xBB\xBF";
    const char *end = NULL;
    const char *nul;
    size_t skip = 0u;
    uint32_t line;
    uint32_t col = 0u;
    cJSON *root;
    mt_status_t st;

    *n = 0u;
    mt_wpl_set_error(err, MT_OK, 0u, 0u, MT_MISSION_NONE, "ok");
    if (len > MT_PLAN_MAX_BYTES) {
        mt_wpl_set_error(err, MT_E_MISSION_SIZE, 1u, 0u, MT_MISSION_NONE, "larger than %u bytes",
                         (unsigned)MT_PLAN_MAX_BYTES);
        return MT_E_MISSION_SIZE;
    }
    if (len >= sizeof bom - 1u && memcmp(text, bom, sizeof bom - 1u) == 0) {
        skip = sizeof bom - 1u; /* UTF-8 byte order mark */
    }
    nul = memchr(text, '\0', len);
    if (nul != NULL) {
        line = line_of(text, (size_t)(nul - text), &col);
        mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, 0u, MT_MISSION_NONE,
                         "NUL byte in the file (column %u)", (unsigned)col);
        return MT_E_MISSION_SYNTAX;
    }
    if (count_values(text, len) > MT_PLAN_MAX_VALUES) {
        mt_wpl_set_error(err, MT_E_MISSION_SIZE, 1u, 0u, MT_MISSION_NONE,
                         "more than %u JSON values", (unsigned)MT_PLAN_MAX_VALUES);
        return MT_E_MISSION_SIZE;
    }
    root = cJSON_ParseWithLengthOpts(text + skip, len - skip, &end, 0);
    if (root != NULL && end != NULL) {
        while (end < text + len && (*end == ' ' || *end == '\t' || *end == '\r' || *end == '\n')) {
            end++;
        }
        if (end < text + len) {
            line = line_of(text, (size_t)(end - text), &col);
            mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, 0u, MT_MISSION_NONE,
                             "JSON: text after the top-level value (column %u)", (unsigned)col);
            cJSON_Delete(root);
            return MT_E_MISSION_SYNTAX;
        }
    }
    if (root == NULL) {
        size_t off = (end != NULL && end >= text && end <= text + len) ? (size_t)(end - text) : len;
        size_t k = off;
        /* cJSON points at the last byte when it runs out of text: say so, at the end */
        while (k < len && (text[k] == ' ' || text[k] == '\t' || text[k] == '\r' || text[k] == '\n')) {
            k++;
        }
        if (k >= len) {
            off = len;
        }
        line = line_of(text, off, &col);
        mt_wpl_set_error(err, MT_E_MISSION_SYNTAX, line, 0u, MT_MISSION_NONE,
                         "JSON: %s (column %u)",
                         off >= len        ? "unexpected end of the file"
                         : off + 1u >= len ? "syntax error or end of the file at the last character"
                                           : "syntax error",
                         (unsigned)col);
        return MT_E_MISSION_SYNTAX;
    }
    st = read_mission(root, items, cap, n, err, warn);
    cJSON_Delete(root);
    return st;
}

/* ------------------------------------------------------------------ writer */

/* A number as cJSON raw text: the shortest exact decimal, null for NaN. */
static cJSON *number(double v)
{
    char buf[48];

    if (isnan(v)) {
        return cJSON_CreateNull();
    }
    mt_wpl_fmt_double(buf, sizeof buf, v);
    return cJSON_CreateRaw(buf);
}

/* Add to obj, remembering a failed allocation in *ok. */
static void add(cJSON *obj, const char *key, cJSON *v, int *ok)
{
    if (v == NULL || !cJSON_AddItemToObject(obj, key, v)) {
        cJSON_Delete(v);
        *ok = 0;
    }
}

static void push(cJSON *arr, cJSON *v, int *ok)
{
    if (v == NULL || !cJSON_AddItemToArray(arr, v)) {
        cJSON_Delete(v);
        *ok = 0;
    }
}

mt_status_t mt_plan_write(const mt_wpl_item_t *items, size_t n, char **out, size_t *len, mt_wpl_error_t *err)
{
    cJSON *root;
    cJSON *mission;
    cJSON *list;
    cJSON *home;
    cJSON *fence;
    cJSON *rally;
    size_t i;
    int ok = 1;

    *out = NULL;
    *len = 0u;
    mt_wpl_set_error(err, MT_OK, 0u, 0u, MT_MISSION_NONE, "ok");
    if (n == 0u) {
        mt_wpl_set_error(err, MT_E_MISSION_SIZE, 0u, 0u, 0u,
                         "no items: a .plan needs the home (index 0)");
        return MT_E_MISSION_SIZE;
    }
    for (i = 0u; i < n; i++) {
        int f;
        for (f = (i == 0u ? 4 : 0); f < 7; f++) {
            if (isinf(items[i].p[f]) || (i == 0u && isnan(items[i].p[f]))) {
                mt_wpl_set_error(err, MT_E_MISSION_PARAM, items[i].line, 5u + (uint32_t)f,
                                 (uint32_t)i, "param %d: %s (a .plan cannot hold it)", f + 1,
                                 isnan(items[i].p[f]) ? "NaN in the home position" : "infinite");
                return MT_E_MISSION_PARAM;
            }
        }
    }
    root = cJSON_CreateObject();
    mission = cJSON_CreateObject();
    list = cJSON_CreateArray();
    home = cJSON_CreateArray();
    fence = cJSON_CreateObject();
    rally = cJSON_CreateObject();
    if (root == NULL || mission == NULL || list == NULL || home == NULL || fence == NULL || rally == NULL) {
        cJSON_Delete(root);
        cJSON_Delete(mission);
        cJSON_Delete(list);
        cJSON_Delete(home);
        cJSON_Delete(fence);
        cJSON_Delete(rally);
        mt_wpl_set_error(err, MT_E_FULL, 0u, 0u, MT_MISSION_NONE, "out of memory");
        return MT_E_FULL;
    }
    /* keys in QGC's (alphabetical) order */
    add(root, "fileType", cJSON_CreateString("Plan"), &ok);
    add(fence, "circles", cJSON_CreateArray(), &ok);
    add(fence, "polygons", cJSON_CreateArray(), &ok);
    add(fence, "version", cJSON_CreateNumber(2), &ok);
    add(root, "geoFence", fence, &ok);
    add(root, "groundStation", cJSON_CreateString("Metronome mt-mission"), &ok);
    add(mission, "cruiseSpeed", cJSON_CreateNumber(15), &ok);
    add(mission, "firmwareType", cJSON_CreateNumber(3), &ok); /* MAV_AUTOPILOT_ARDUPILOTMEGA */
    add(mission, "hoverSpeed", cJSON_CreateNumber(5), &ok);
    for (i = 1u; i < n && ok; i++) {
        const mt_wpl_item_t *it = &items[i];
        cJSON *o = cJSON_CreateObject();
        cJSON *p = cJSON_CreateArray();
        int f;
        if (o == NULL || p == NULL) {
            cJSON_Delete(o);
            cJSON_Delete(p);
            ok = 0;
            break;
        }
        add(o, "autoContinue", cJSON_CreateBool(it->autocontinue != 0u), &ok);
        add(o, "command", cJSON_CreateNumber((double)it->command), &ok);
        add(o, "doJumpId", cJSON_CreateNumber((double)i), &ok);
        add(o, "frame", cJSON_CreateNumber((double)it->frame), &ok);
        for (f = 0; f < 7; f++) {
            push(p, number(it->p[f]), &ok);
        }
        add(o, "params", p, &ok);
        add(o, "type", cJSON_CreateString("SimpleItem"), &ok);
        push(list, o, &ok);
    }
    add(mission, "items", list, &ok);
    for (i = 4u; i < 7u; i++) {
        push(home, number(items[0].p[i]), &ok);
    }
    add(mission, "plannedHomePosition", home, &ok);
    add(mission, "vehicleType", cJSON_CreateNumber(2), &ok); /* MAV_TYPE_QUADROTOR */
    add(mission, "version", cJSON_CreateNumber(2), &ok);
    add(root, "mission", mission, &ok);
    add(rally, "points", cJSON_CreateArray(), &ok);
    add(rally, "version", cJSON_CreateNumber(2), &ok);
    add(root, "rallyPoints", rally, &ok);
    add(root, "version", cJSON_CreateNumber(1), &ok);
    if (ok) {
        *out = cJSON_Print(root);
    }
    cJSON_Delete(root);
    if (*out == NULL) {
        mt_wpl_set_error(err, MT_E_FULL, 0u, 0u, MT_MISSION_NONE, "out of memory");
        return MT_E_FULL;
    }
    *len = strlen(*out);
    return MT_OK;
}
