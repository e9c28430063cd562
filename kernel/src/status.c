/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file status.c
 * @brief Status names.
 */
#include "mt/status.h"

const char *mt_status_str(mt_status_t st)
{
    const char *name;

    switch (st) {
    case MT_OK: name = "MT_OK"; break;
    case MT_E_INVALID: name = "MT_E_INVALID"; break;
    case MT_E_FULL: name = "MT_E_FULL"; break;
    case MT_E_EMPTY: name = "MT_E_EMPTY"; break;
    case MT_E_DUPLICATE: name = "MT_E_DUPLICATE"; break;
    case MT_E_TIMEOUT: name = "MT_E_TIMEOUT"; break;
    case MT_E_BUSY: name = "MT_E_BUSY"; break;
    case MT_E_RANGE: name = "MT_E_RANGE"; break;
    case MT_E_TASK_ORDER: name = "MT_E_TASK_ORDER"; break;
    case MT_E_TASK_RATE: name = "MT_E_TASK_RATE"; break;
    case MT_E_TASK_BUDGET: name = "MT_E_TASK_BUDGET"; break;
    case MT_E_TASK_COUNT: name = "MT_E_TASK_COUNT"; break;
    case MT_E_LOOP_RATE: name = "MT_E_LOOP_RATE"; break;
    case MT_E_TASK_FN: name = "MT_E_TASK_FN"; break;
    case MT_W_DROPPED_OLDEST: name = "MT_W_DROPPED_OLDEST"; break;
    case MT_E_MISSION_CMD: name = "MT_E_MISSION_CMD"; break;
    case MT_E_MISSION_PARAM: name = "MT_E_MISSION_PARAM"; break;
    case MT_E_MISSION_LOCATION: name = "MT_E_MISSION_LOCATION"; break;
    case MT_E_MISSION_FRAME: name = "MT_E_MISSION_FRAME"; break;
    case MT_E_MISSION_JUMP: name = "MT_E_MISSION_JUMP"; break;
    case MT_E_MISSION_LOOP: name = "MT_E_MISSION_LOOP"; break;
    case MT_E_MISSION_SIZE: name = "MT_E_MISSION_SIZE"; break;
    case MT_E_MISSION_SYNTAX: name = "MT_E_MISSION_SYNTAX"; break;
    case MT_E_STATE: name = "MT_E_STATE"; break;
    case MT_W_WQ_MERGED: name = "MT_W_WQ_MERGED"; break;
    case MT_E_BUS_MSG_SIZE: name = "MT_E_BUS_MSG_SIZE"; break;
    case MT_E_BUS_QUEUE_LEN: name = "MT_E_BUS_QUEUE_LEN"; break;
    case MT_E_BUS_STORAGE: name = "MT_E_BUS_STORAGE"; break;
    case MT_E_BUS_BEHIND: name = "MT_E_BUS_BEHIND"; break;
    case MT_E_BUS_TORN: name = "MT_E_BUS_TORN"; break;
    case MT_W_BUS_MISSED: name = "MT_W_BUS_MISSED"; break;
    case MT_STATUS_COUNT:
    default: name = "MT_STATUS_?"; break;
    }
    return name;
}
