/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file report.h
 * @brief Whole-file check and execution plan (the core of `mt-mission check`).
 *
 * The plan is produced by the kernel sequencer itself (mt/mission.h, which
 * follows AP_Mission), driven by a simulated vehicle under one verify policy:
 * every start succeeds; a do or condition command verifies at its first
 * check; a nav command verifies once every do command between the previous
 * nav command and it has started (the do search has reached it). The plan
 * lists nav, do and condition commands in start order, jumps unrolled exactly
 * as on the vehicle. Each do step says how it started: with the nav advance
 * (the first do command after a nav command starts just before the next nav
 * command, or before the end of the mission) or while a nav command runs
 * (the later ones, one at a time). Only the latter depend on timing: under
 * slower do or condition commands they start later, and those not started
 * when that nav command completes are dropped; the text report says so. A plan longer than max_plan is cut and marked
 * truncated, with the reason: the sequencer is run on (without recording) for
 * up to MT_REPORT_EXTRA_UPDATES more updates; if its state repeats (Brent's
 * cycle detection on the cursors and jump counters) the mission repeats
 * forever, otherwise it is longer than the plan limit (and plan_total says
 * how long when it ended within that budget).
 *
 * Either file format is checked (mfile.h); reader warnings, and a frame that
 * ArduPilot ignores (wpl.h), are listed in warnings.
 */
#ifndef MT_MISSION_REPORT_H
#define MT_MISSION_REPORT_H

#include <stddef.h>
#include <stdint.h>

#include "mfile.h"
#include "wpl.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MT_REPORT_MAX_ERRORS 64u
/** Sequencer updates after the plan limit spent looking for the end or a repetition. */
#define MT_REPORT_EXTRA_UPDATES (1u << 18)

/** Why a plan was cut (mt_report_t.truncated). */
#define MT_REPORT_COMPLETE 0u    /**< not truncated: the plan ends */
#define MT_REPORT_FOREVER 1u     /**< the mission repeats forever */
#define MT_REPORT_OVER_LIMIT 2u  /**< the plan is longer than max_plan */

typedef struct {
    uint16_t index;
    uint16_t command;
    uint8_t kind;    /**< MT_MISSION_KIND_NAV or MT_MISSION_KIND_DO */
    uint16_t during; /**< do step: the nav command that was running when it started, or
                          MT_MISSION_NONE when the nav advance started it; nav: NONE */
} mt_plan_step_t;

typedef struct {
    int valid;
    size_t nerr;
    mt_wpl_error_t errors[MT_REPORT_MAX_ERRORS];
    size_t nitems;
    size_t nplan;
    mt_plan_step_t *plan; /**< caller storage of max_plan steps */
    size_t max_plan;
    int truncated;        /**< MT_REPORT_COMPLETE, MT_REPORT_FOREVER or MT_REPORT_OVER_LIMIT */
    size_t plan_total;    /**< steps of the whole plan; 0 when it does not end (or not found) */
    size_t kernel_max;    /**< set by the caller before rendering: the MT_CFG_MISSION_MAX_CMDS of
                               the kernel the mission is meant for, to say whether it fits
                               (0: not said). The checks themselves use this build's setting. */
    mt_wpl_warnings_t warnings;
} mt_report_t;

/** Parse, convert and validate text; if valid, compute the plan (at most
 *  max_plan steps into plan[]). Returns MT_OK when the mission is valid, else
 *  the status of the first error. */
mt_status_t mt_report_check(const char *text, size_t len, mt_plan_step_t *plan, size_t max_plan,
                            mt_report_t *rep);

/** As mt_report_check, for a file of format fmt (MT_MFILE_AUTO: sniffed). */
mt_status_t mt_report_check_as(mt_mfile_format_t fmt, const char *text, size_t len, mt_plan_step_t *plan,
                               size_t max_plan, mt_report_t *rep);

/** Render a report as text or as JSON into out (snprintf convention). */
size_t mt_report_text(const mt_report_t *rep, const char *file, char *out, size_t cap);
size_t mt_report_json(const mt_report_t *rep, char *out, size_t cap);

#ifdef __cplusplus
}
#endif

#endif /* MT_MISSION_REPORT_H */
