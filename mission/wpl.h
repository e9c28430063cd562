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
 * z is the altitude in metres.
 *
 * What the reader accepts beyond that, as pymavlink's mavwp.py (MAVProxy) does:
 * a UTF-8 BOM at the start; LF, CRLF and CR-only line ends; blank lines; lines
 * whose first non-blank character is '#' (comments, before or after the
 * header). Items are numbered in file order: a seq that is not the previous
 * seq + 1 (a gap, a repeat, out of order) is renumbered with a warning, so
 * jump targets refer to the renumbered indices. A first item with command 0
 * (Mission Planner's home) is read as WAYPOINT (16), with a warning. A file
 * with a header and no item is an error (MT_E_MISSION_SIZE) on the header line.
 *
 * Layering: the reader keeps every field exactly (doubles as parsed, so a
 * write-read round trip is bit-exact, NaN included). The kernel never sees a
 * float: mt_wpl_to_cmd converts an item to the kernel's integers and is where
 * the float rules live: inf is never accepted; NaN only in params 1..4 (the
 * kernel's validator then applies AP's per-command NaN rules); params must fit
 * 3 decimals in int32 (|p| < 2147483.647), x/y are rounded to 1e-7 degree and
 * must lie in [-214.7, 214.7] (the kernel checks the lat/lon range), z is
 * rounded to the centimetre and must fit int32.
 * Frames: ArduPilot's AP_Mission checks the frame only of commands it stores
 * as a location; a do/condition/jump command without a location ignores it.
 * mt_wpl_to_cmd therefore gives such a command in a frame other than 0, 2, 3,
 * 5, 6, 10, 11 (e.g. 1, LOCAL_NED) the kernel frame 2 (MISSION); the item
 * keeps its frame, so the file round trip is unchanged (the check report
 * lists this as a warning).
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

#define MT_WPL_MAX_WARNINGS 32u

/** Warnings of a reader: accepted, but changed or dropped something. The
 *  first MT_WPL_MAX_WARNINGS are kept, the rest only counted. Each entry uses
 *  mt_wpl_error_t with st == MT_OK. */
typedef struct {
    size_t n;       /**< entries in w[] */
    size_t dropped; /**< warnings beyond MT_WPL_MAX_WARNINGS (counted only) */
    mt_wpl_error_t w[MT_WPL_MAX_WARNINGS];
} mt_wpl_warnings_t;

/** Set *err (NULL: ignored): status, line, field, item index and the formatted reason. */
void mt_wpl_set_error(mt_wpl_error_t *err, mt_status_t st, uint32_t line, uint32_t field,
                      uint32_t index, const char *fmt, ...) __attribute__((format(printf, 6, 7)));

/** Room for mt_wpl_where's text with a path of up to 4000 bytes. */
#define MT_WPL_WHERE_MAX 4096u

/** "file:line: field F: index I:" for e into buf[0 .. cap-1], each part only when set (line 0:
 *  no line, e.g. a .plan item); returns buf. */
const char *mt_wpl_where(char *buf, size_t cap, const char *file, const mt_wpl_error_t *e);

/** Add a warning to warn (NULL: ignored). */
void mt_wpl_warn(mt_wpl_warnings_t *warn, uint32_t line, uint32_t field, uint32_t index, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));

/** Parse text[0 .. len-1]. Items go to items[0 .. cap-1]; *n is their number.
 *  Stops at the first syntax error (*err) and returns MT_E_MISSION_SYNTAX;
 *  more than cap items, or none, is MT_E_MISSION_SIZE. Warnings (renumbered
 *  seq, command-0 home) are appended to *warn; warn may be NULL. */
mt_status_t mt_wpl_parse(const char *text, size_t len, mt_wpl_item_t *items, size_t cap, size_t *n,
                         mt_wpl_error_t *err, mt_wpl_warnings_t *warn);

/** Write items as a QGC WPL 110 file (shortest decimal that reads back to
 *  the same double). Returns the bytes written (excluding the NUL), or the
 *  bytes needed when out is too small (snprintf convention). */
size_t mt_wpl_write(const mt_wpl_item_t *items, size_t n, char *out, size_t cap);

/** Shortest rendering of v that strtod reads back to exactly v: "%.0f" for an integer below
 *  1e15, else the shortest "%.*g"; "nan", "inf", "-inf" for the non-finite values. buf of
 *  at least 40 bytes. */
void mt_wpl_fmt_double(char *buf, size_t cap, double v);

/** 1 when ArduPilot ignores the frame of this command (a do/condition/jump
 *  command that carries no location), else 0. */
int mt_wpl_frame_ignored(uint32_t command);

/** Convert one item to the kernel's integer command (see the file comment).
 *  @retval MT_OK
 *  @retval MT_E_MISSION_PARAM inf, NaN outside params 1..4, or out of range
 *  @retval MT_E_MISSION_CMD command id above 65535
 *  @retval MT_E_MISSION_FRAME frame above 255 */
mt_status_t mt_wpl_to_cmd(const mt_wpl_item_t *it, mt_mission_cmd_t *out, mt_wpl_error_t *err);

/** MAVLink name of a command id without MAV_CMD_ ("NAV_WAYPOINT"; generated table
 *  mav_cmd_names.h: the commands the kernel accepts), or NULL when unknown. */
const char *mt_wpl_cmd_name(uint32_t id);

#ifdef __cplusplus
}
#endif

#endif /* MT_WPL_H */
