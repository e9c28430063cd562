/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_mission_invoke.h
 * @brief The mission module's indirect calls (kernel-private), in the style
 *        of mt_invoke.h.
 *
 * Proof assumption A1 (mission): a vehicle callback returns, and writes
 * neither the mission object nor the kernel lock state (it may read the
 * mission through the query functions). The bodies (mission_invoke.c) are the
 * plain calls and are excluded from WP. The requires clause `callback_id` is
 * the property "no callback ever sees a jump command": every call site must
 * prove it.
 */
#ifndef MT_MISSION_INVOKE_H
#define MT_MISSION_INVOKE_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/mission.h"
#include "mt_spec.h"

/** Call fn(ctx, index, cmd) (a start or verify callback). */
/*@ requires callable: fn != \null;
    requires cmd: \valid_read(cmd);
    requires callback_id: MtMissionIsCallbackId(cmd->id);
    assigns MtPortNow, MtPortWakes;
    ensures time_moves_forward: MtPortNow >= \old(MtPortNow);
*/
bool mt_mission_invoke_cmd(mt_mission_cmd_fn_t fn, void *ctx, uint16_t index,
                           const mt_mission_cmd_t *cmd);

/** Call fn(ctx) (the mission-complete callback). */
/*@ requires callable: fn != \null;
    assigns MtPortNow, MtPortWakes;
    ensures time_moves_forward: MtPortNow >= \old(MtPortNow);
*/
void mt_mission_invoke_done(mt_mission_done_fn_t fn, void *ctx);

#endif /* MT_MISSION_INVOKE_H */
