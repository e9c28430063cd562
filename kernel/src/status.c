/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file status.c
 * @brief Status names: one table, indexed by status.
 */
#include "mt/status.h"

#include <stdint.h>

const char *const mt_status_names[(int)MT_STATUS_COUNT + 1] = {
    [MT_OK] = "MT_OK",
    [MT_E_INVALID] = "MT_E_INVALID",
    [MT_E_FULL] = "MT_E_FULL",
    [MT_E_EMPTY] = "MT_E_EMPTY",
    [MT_E_DUPLICATE] = "MT_E_DUPLICATE",
    [MT_E_TIMEOUT] = "MT_E_TIMEOUT",
    [MT_E_BUSY] = "MT_E_BUSY",
    [MT_E_RANGE] = "MT_E_RANGE",
    [MT_E_TASK_ORDER] = "MT_E_TASK_ORDER",
    [MT_E_TASK_RATE] = "MT_E_TASK_RATE",
    [MT_E_TASK_BUDGET] = "MT_E_TASK_BUDGET",
    [MT_E_TASK_COUNT] = "MT_E_TASK_COUNT",
    [MT_E_LOOP_RATE] = "MT_E_LOOP_RATE",
    [MT_E_TASK_FN] = "MT_E_TASK_FN",
    [MT_W_DROPPED_OLDEST] = "MT_W_DROPPED_OLDEST",
    [MT_E_MISSION_CMD] = "MT_E_MISSION_CMD",
    [MT_E_MISSION_PARAM] = "MT_E_MISSION_PARAM",
    [MT_E_MISSION_LOCATION] = "MT_E_MISSION_LOCATION",
    [MT_E_MISSION_FRAME] = "MT_E_MISSION_FRAME",
    [MT_E_MISSION_JUMP] = "MT_E_MISSION_JUMP",
    [MT_E_MISSION_LOOP] = "MT_E_MISSION_LOOP",
    [MT_E_MISSION_SIZE] = "MT_E_MISSION_SIZE",
    [MT_E_MISSION_SYNTAX] = "MT_E_MISSION_SYNTAX",
    [MT_E_STATE] = "MT_E_STATE",
    [MT_W_WQ_MERGED] = "MT_W_WQ_MERGED",
    [MT_E_BUS_MSG_SIZE] = "MT_E_BUS_MSG_SIZE",
    [MT_E_BUS_QUEUE_LEN] = "MT_E_BUS_QUEUE_LEN",
    [MT_E_BUS_STORAGE] = "MT_E_BUS_STORAGE",
    [MT_E_BUS_BEHIND] = "MT_E_BUS_BEHIND",
    [MT_E_BUS_TORN] = "MT_E_BUS_TORN",
    [MT_W_BUS_MISSED] = "MT_W_BUS_MISSED",
    [MT_STATUS_COUNT] = "MT_STATUS_?",
};

const char *mt_status_str(mt_status_t st)
{
    /* compared as unsigned: a compiler may give the enum a signed type, and a value that is
     * not a status may then be negative */
    uint32_t i = (uint32_t)st;

    if (i >= (uint32_t)MT_STATUS_COUNT) {
        i = (uint32_t)MT_STATUS_COUNT;
    }
    return mt_status_names[i];
}
