/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file plan.h
 * @brief Mission files: the mission part of a QGroundControl .plan file (JSON,
 *        QGC dev guide "Plan File Format"). Host-side C, not kernel code; the
 *        JSON is read and written with cJSON (Debian libcjson-dev).
 *
 * Read: top level {"fileType": "Plan", "version": 1, "mission": {...}} with
 * mission {"version": 2, "plannedHomePosition": [lat, lon, alt], "items": [...]}.
 * The home becomes item 0 (WAYPOINT 16, frame 0, current 1, params 1..4 zero);
 * items[k] becomes item k + 1. A "SimpleItem" carries "command", "frame",
 * "params" (7 numbers, null for NaN), "autoContinue" (bool) and an optional
 * "doJumpId"; as QGC does, a DO_JUMP's param 1 names the doJumpId of its target
 * and is replaced by the target's index (a warning when that changes it). A
 * "ComplexItem" (survey, corridor scan, structure scan, landing pattern) is
 * refused: QGC expands it into simple items only when it uploads. A non-empty
 * "geoFence" or "rallyPoints" is a warning: not carried. Other keys (cruise
 * speed, Altitude/AltitudeMode, ...) are ignored.
 *
 * Errors: line and column (in the reason) for JSON syntax; otherwise line 0,
 * the mission index, the WPL field number of the key (3 frame, 4 command,
 * 5..11 params[0..6], 12 autoContinue, 1 doJumpId) and a reason that starts
 * with the JSON path ("mission.items[2].frame: ...").
 *
 * Write: the inverse; doJumpId = index, NaN params as null, numbers as the
 * shortest decimal that reads back to the same double (so .plan -> read ->
 * write -> read keeps every value bit for bit, -0 included); an infinite value
 * cannot be written (JSON has none). "current" and the home's frame and
 * params 1..4 are not part of the format.
 *
 * Limits (no allocation grows with the input beyond them): MT_PLAN_MAX_BYTES
 * of text, MT_PLAN_MAX_VALUES JSON values (counted before cJSON runs), cJSON's
 * own nesting limit, and the caller's item capacity.
 */
#ifndef MT_MISSION_PLAN_H
#define MT_MISSION_PLAN_H

#include <stddef.h>
#include <stdint.h>

#include "wpl.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MT_PLAN_MAX_BYTES (8u * 1024u * 1024u)
#define MT_PLAN_MAX_VALUES (256u * 1024u)

/** Parse a .plan text (see the file comment). Items go to items[0 .. cap-1].
 *  @retval MT_OK
 *  @retval MT_E_MISSION_SYNTAX not JSON, or a key missing or of the wrong type
 *  @retval MT_E_MISSION_SIZE text or JSON too large, or more than cap items
 *  @retval MT_E_MISSION_CMD a complex item
 *  @retval MT_E_MISSION_JUMP a DO_JUMP names no item's doJumpId
 *  @retval MT_E_FULL out of memory */
mt_status_t mt_plan_parse(const char *text, size_t len, mt_wpl_item_t *items, size_t cap, size_t *n,
                          mt_wpl_error_t *err, mt_wpl_warnings_t *warn);

/** Write items[0 .. n-1] (item 0: home) as a .plan text into *out (malloc'd,
 *  NUL-terminated, the caller frees it), its length in *len.
 *  @retval MT_OK
 *  @retval MT_E_MISSION_SIZE n == 0 (no home)
 *  @retval MT_E_MISSION_PARAM an infinite value (index and field in *err)
 *  @retval MT_E_FULL out of memory */
mt_status_t mt_plan_write(const mt_wpl_item_t *items, size_t n, char **out, size_t *len, mt_wpl_error_t *err);

#ifdef __cplusplus
}
#endif

#endif /* MT_MISSION_PLAN_H */
