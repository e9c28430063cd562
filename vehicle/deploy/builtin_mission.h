/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file builtin_mission.h
 * @brief The mission compiled into the firmware (no file system): a const
 *        command table, the same as vehicle/missions/builtin.waypoints (a test
 *        checks that the file reader gives exactly this table).
 */
#ifndef VEH_BUILTIN_MISSION_H
#define VEH_BUILTIN_MISSION_H

#include <stdint.h>

#include "mt/mission.h"

#ifdef __cplusplus
extern "C" {
#endif

extern const mt_mission_cmd_t veh_builtin_mission[];
extern const uint16_t veh_builtin_mission_len;

#ifdef __cplusplus
}
#endif

#endif /* VEH_BUILTIN_MISSION_H */
