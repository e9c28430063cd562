/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mission_invoke.c
 * @brief Mission callbacks (assumption A1, see mt_mission_invoke.h). Not analysed by WP.
 */
#include "mt_mission_invoke.h"

bool mt_mission_invoke_cmd(mt_mission_cmd_fn_t fn, void *ctx, uint16_t index,
                           const mt_mission_cmd_t *cmd)
{
    return fn(ctx, index, cmd);
}

void mt_mission_invoke_done(mt_mission_done_fn_t fn, void *ctx)
{
    fn(ctx);
}
