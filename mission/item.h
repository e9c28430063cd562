/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file item.h
 * @brief One mission item to the kernel's integer command: the float rules of
 *        the mission files (wpl.h), without stdio, so a firmware converts the
 *        items a ground station uploads exactly as the file readers convert a
 *        file's (vehicle/src/mission_link.c). mt_wpl_to_cmd (wpl.h) is this
 *        conversion with the reason as text.
 */
#ifndef MT_MISSION_ITEM_H
#define MT_MISSION_ITEM_H

#include <stdint.h>

#include "mt/mt.h"
#include "wpl.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Why an item was refused. */
typedef enum {
    MT_ITEM_OK = 0,
    MT_ITEM_NOT_A_CMD,      /**< command id above 65535 */
    MT_ITEM_NOT_A_FRAME,    /**< frame above 255 */
    MT_ITEM_INFINITE,       /**< a parameter is infinite */
    MT_ITEM_OUT_OF_RANGE,   /**< a parameter does not fit the kernel's integer */
    MT_ITEM_NAN_NOT_ALLOWED /**< NaN in x, y or z */
} mt_item_why_t;

/** Where and why: the status, the WPL field (3 frame, 4 command, 5..8 param1..4, 9 x,
 *  10 y, 11 z) and the reason. */
typedef struct {
    mt_status_t st;
    uint32_t field;
    mt_item_why_t why;
} mt_item_fault_t;

/** Convert one item (see wpl.h's file comment for the rules). *f is set on every call.
 *  @retval MT_OK
 *  @retval MT_E_MISSION_PARAM inf, NaN outside params 1..4, or out of range
 *  @retval MT_E_MISSION_CMD command id above 65535
 *  @retval MT_E_MISSION_FRAME frame above 255 */
mt_status_t mt_item_to_cmd(const mt_wpl_item_t *it, mt_mission_cmd_t *out, mt_item_fault_t *f);

/** The name of field 3..11 ("frame", "command", "param1".., "x (latitude)", "y (longitude)",
 *  "z (altitude)"), "" for another. */
const char *mt_item_field_name(uint32_t field);

/** The reason in words ("infinite", "out of range", ...). */
const char *mt_item_why_str(mt_item_why_t why);

#ifdef __cplusplus
}
#endif

#endif /* MT_MISSION_ITEM_H */
