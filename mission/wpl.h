/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file wpl.h
 * @brief Mission files: the QGC WPL 110 text format (QGroundControl, Mission
 *        Planner, ArduPilot test missions). Host-side C, not kernel code.
 *
 * Format: a header line "QGC WPL 110", then one line per item with 12 fields
 * separated by tabs or spaces:
 *   seq current frame command p1 p2 p3 p4 x y z autocontinue
 * seq counts from 0 (item 0 is home); x/y are latitude/longitude in degrees,
 * z is the altitude in metres. Blank lines and a trailing CR are accepted.
 *
 * Layering: the reader keeps every field exactly (doubles as parsed, so a
 * write-read round trip is bit-exact, NaN included). The kernel never sees a
 * float: mt_wpl_to_cmd converts an item to the kernel's integers and is where
 * the float rules live: inf is never accepted; NaN only in params 1..4 (the
 * kernel's validator then applies AP's per-command NaN rules); params must fit
 * 3 decimals in int32 (|p| < 2147483.647), x/y are rounded to 1e-7 degree and
 * must lie in [-214.7, 214.7] (the kernel checks the lat/lon range), z is
 * rounded to the centimetre and must fit int32.
 */
#ifndef MT_WPL_H
#define MT_WPL_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "mt/mission.h"
#include "mt/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/** One item of a mission file, every field as written. */
typedef struct {
    uint32_t line;     /**< 1-based line number in the file it came from (0 if built) */
    uint32_t seq;
    uint32_t current;  /**< 0 or 1 */
    uint32_t frame;    /**< MAV_FRAME */
    uint32_t command;  /**< MAV_CMD */
    double p[7];       /**< params 1..4, x (lat), y (lon), z (alt) */
    uint32_t autocontinue; /**< 0 or 1 */
} mt_wpl_item_t;

/** Where and why a file (or an item) was rejected. */
typedef struct {
    mt_status_t st;   /**< MT_E_MISSION_SYNTAX for the text, or a validation status */
    uint32_t line;    /**< 1-based line (0: not tied to a line) */
    uint32_t field;   /**< 1-based field (1 seq .. 12 autocontinue), 0: whole line */
    uint32_t index;   /**< mission index, or MT_MISSION_NONE */
    char reason[128];
} mt_wpl_error_t;

/** Parse text[0 .. len-1]. Items go to items[0 .. cap-1]; *n is their number.
 *  Stops at the first syntax error (errors[0]) and returns MT_E_MISSION_SYNTAX;
 *  more than cap items is MT_E_MISSION_SIZE. */
mt_status_t mt_wpl_parse(const char *text, size_t len, mt_wpl_item_t *items, size_t cap, size_t *n,
                         mt_wpl_error_t *err);

/** Write items as a QGC WPL 110 file (shortest decimal that reads back to
 *  the same double). Returns the bytes written (excluding the NUL), or the
 *  bytes needed when out is too small (snprintf convention). */
size_t mt_wpl_write(const mt_wpl_item_t *items, size_t n, char *out, size_t cap);

/** Convert one item to the kernel's integer command (see the file comment).
 *  @retval MT_OK
 *  @retval MT_E_MISSION_PARAM inf, NaN outside params 1..4, or out of range
 *  @retval MT_E_MISSION_CMD command id above 65535
 *  @retval MT_E_MISSION_FRAME frame above 255 */
mt_status_t mt_wpl_to_cmd(const mt_wpl_item_t *it, mt_mission_cmd_t *out, mt_wpl_error_t *err);

/** Short MAVLink name of a command id ("WAYPOINT"), or NULL when unknown. */
const char *mt_wpl_cmd_name(uint32_t id);

#ifdef __cplusplus
}
#endif

#endif /* MT_WPL_H */
