/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file report.h
 * @brief Whole-file check and execution plan (the core of `mt-mission check`).
 *
 * The plan is produced by the kernel sequencer itself (mt/mission.h), driven
 * by a simulated vehicle whose start callbacks succeed and whose verify
 * callbacks succeed as soon as possible: a do command at once, a nav command
 * once the do commands before it have all run. Jumps are therefore unrolled
 * exactly as on the vehicle. A plan longer than max_plan is cut and marked
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
    uint8_t kind; /**< MT_MISSION_KIND_NAV or MT_MISSION_KIND_DO */
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
