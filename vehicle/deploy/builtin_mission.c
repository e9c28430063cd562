/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file builtin_mission.c
 * @brief The firmware's built-in mission (see builtin_mission.h): take off to
 *        10 m, two legs at 12 m (the second at 8 m/s), set a servo, loiter
 *        2 s, return to launch. Home: 46.5197 N 6.5657 E, 400 m.
 *        Params are x 1000, lat/lon x 1e7, altitude in cm (mt/mission.h).
 */
#include "builtin_mission.h"

const mt_mission_cmd_t veh_builtin_mission[] = {
    /* id, frame, options, params 1..4, lat, lon, alt */
    {MT_MAV_CMD_WAYPOINT, 0u, 1u, {0, 0, 0, 0}, 465197000, 65657000, 40000},      /* home */
    {MT_MAV_CMD_TAKEOFF, 3u, 1u, {0, 0, 0, 0}, 0, 0, 1000},                       /* 1 */
    {MT_MAV_CMD_WAYPOINT, 3u, 1u, {0, 0, 0, 0}, 465200593, 65657000, 1200},       /* 2 */
    {MT_MAV_CMD_DO_CHANGE_SPEED, 2u, 1u, {1000, 8000, 0, 0}, 0, 0, 0},            /* 3 */
    {MT_MAV_CMD_WAYPOINT, 3u, 1u, {0, 0, 0, 0}, 465200593, 65662222, 1200},       /* 4 */
    {MT_MAV_CMD_DO_SET_SERVO, 2u, 1u, {9000, 1900000, 0, 0}, 0, 0, 0},            /* 5 */
    {MT_MAV_CMD_LOITER_TIME, 3u, 1u, {2000, 0, 0, 0}, 465197000, 65662222, 1200}, /* 6 */
    {MT_MAV_CMD_RETURN_TO_LAUNCH, 3u, 1u, {0, 0, 0, 0}, 0, 0, 0},                 /* 7 */
};

const uint16_t veh_builtin_mission_len =
    (uint16_t)(sizeof(veh_builtin_mission) / sizeof(veh_builtin_mission[0]));
