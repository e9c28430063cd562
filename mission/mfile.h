/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mfile.h
 * @brief Mission files of either format: QGC WPL 110 text (wpl.h) or a
 *        QGroundControl .plan (plan.h), chosen by the file name or the content.
 *        Host-side C, not kernel code.
 */
#ifndef MT_MISSION_MFILE_H
#define MT_MISSION_MFILE_H

#include <stddef.h>

#include "plan.h"
#include "wpl.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    MT_MFILE_AUTO = 0, /**< decide by the content (mt_mfile_sniff) */
    MT_MFILE_WPL = 1,  /**< QGC WPL 110 text */
    MT_MFILE_PLAN = 2  /**< QGroundControl .plan (JSON) */
} mt_mfile_format_t;

/** By the name's extension (case-insensitive): ".plan" PLAN; ".waypoints",
 *  ".txt", ".mission" WPL; anything else AUTO. */
mt_mfile_format_t mt_mfile_format_of_path(const char *path);

/** By the content: PLAN when the first character that is not white space
 *  (after a UTF-8 BOM) is '{', else WPL. */
mt_mfile_format_t mt_mfile_sniff(const char *text, size_t len);

/** Parse text in format fmt (AUTO: sniffed); see mt_wpl_parse / mt_plan_parse. */
mt_status_t mt_mfile_parse(mt_mfile_format_t fmt, const char *text, size_t len, mt_wpl_item_t *items, size_t cap,
                           size_t *n, mt_wpl_error_t *err, mt_wpl_warnings_t *warn);

#ifdef __cplusplus
}
#endif

#endif /* MT_MISSION_MFILE_H */
