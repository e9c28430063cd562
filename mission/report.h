/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file report.h
 * @brief Whole-file check and execution plan (the core of `mt-mission check`).
 *
 * The plan is produced by the kernel sequencer itself (mt/mission.h), driven
 * by a simulated vehicle whose start callbacks succeed and whose verify
 * callbacks succeed as soon as possible: a do command at once, a nav command
 * once the do commands before it have all run. Jumps are therefore unrolled
 * exactly as on the vehicle; a plan longer than max_plan (a repeat-forever
 * loop) is cut and marked truncated.
 */
#ifndef MT_MISSION_REPORT_H
#define MT_MISSION_REPORT_H

#include <stddef.h>
#include <stdint.h>

#include "wpl.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MT_REPORT_MAX_ERRORS 64u

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
    int truncated;
} mt_report_t;

/** Parse, convert and validate text; if valid, compute the plan (at most
 *  max_plan steps into plan[]). Returns MT_OK when the mission is valid, else
 *  the status of the first error. */
mt_status_t mt_report_check(const char *text, size_t len, mt_plan_step_t *plan, size_t max_plan,
                            mt_report_t *rep);

/** Render a report as text or as JSON into out (snprintf convention). */
size_t mt_report_text(const mt_report_t *rep, const char *file, char *out, size_t cap);
size_t mt_report_json(const mt_report_t *rep, char *out, size_t cap);

#ifdef __cplusplus
}
#endif

#endif /* MT_MISSION_REPORT_H */
