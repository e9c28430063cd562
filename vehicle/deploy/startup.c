/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file startup.c
 * @brief The start-up, run and end of the vehicle shared by the SITL and the
 *        firmware deployments (startup.h).
 */
#include "startup.h"

#include "vprint.h"

void veh_run_home(veh_home_t *home, const mt_mission_cmd_t *item0)
{
    home->lat = item0->x;
    home->lon = item0->y;
    home->alt_cm = item0->z;
}

mt_status_t veh_run_start(veh_run_t *r, veh_platform_t *plat, simplat_t *world,
                          const veh_home_t *home, const mt_mission_cmd_t *cmds, uint16_t n,
                          uint32_t *bad)
{
    mt_status_t st;

    simplat_fill(world, plat);
    st = veh_init(plat, home, cmds, n, bad);
    r->boot_us = mt_port_now_us();
    r->next_arm_us = r->boot_us + VEH_RUN_ARM_FIRST_US;
    r->end_us = 0u;
    r->reason = NULL;
    return st;
}

bool veh_run_rejected(mt_status_t st, uint32_t bad)
{
    if (st == MT_OK) {
        return false;
    }
    veh_printf("mission rejected by the sequencer: %s at index %u; the vehicle stays "
               "disarmed\n",
               mt_status_str(st), (unsigned)bad);
    return true;
}

veh_gcs_cmd_t veh_run_arm_poll(veh_run_t *r)
{
    uint64_t now = mt_port_now_us();

    if ((veh_phase() == VEH_PHASE_BOOT) && (now >= r->next_arm_us)) {
        r->next_arm_us = now + VEH_RUN_ARM_RETRY_US;
        return VEH_GCS_ARM_AUTO;
    }
    return VEH_GCS_NONE;
}

/* Why the run ends after this tick, or NULL. */
static const char *end_reason(veh_phase_t ph, uint64_t now, uint64_t timeout_us, bool gcs)
{
    if (gcs && (ph != VEH_PHASE_CRASHED) && (now <= timeout_us)) {
        return NULL; /* the ground station's session goes on */
    }
    if (ph == VEH_PHASE_DONE) {
        return "mission complete, vehicle landed and disarmed";
    }
    if (ph == VEH_PHASE_ABORTED) {
        return "vehicle landed and disarmed, mission not complete";
    }
    if (ph == VEH_PHASE_CRASHED) {
        return "crash";
    }
    if ((ph == VEH_PHASE_BOOT) && (now > VEH_RUN_ARM_TIMEOUT_US)) {
        return "the vehicle never armed";
    }
    if (now > timeout_us) {
        return "timeout";
    }
    return NULL; /* flying */
}

bool veh_run_after_tick(veh_run_t *r, const simplat_t *world)
{
    uint64_t now = mt_port_now_us() - r->boot_us;
    veh_phase_t ph;

    if (world->sim.crashed) {
        veh_note_crash(world->sim.last_touchdown_speed);
    }
    ph = veh_phase();
    if ((r->reason == NULL) && (r->max_ticks != 0u) && (veh_sched()->tick >= r->max_ticks)) {
        r->reason = "tick limit reached";
        return false; /* exactly max_ticks ticks */
    }
    if (r->reason == NULL) {
        r->reason = end_reason(ph, now, r->timeout_us, r->gcs_session);
        if (r->reason != NULL) {
            r->end_us = now + r->settle_us;
        }
    }
    return (r->reason == NULL) || (now < r->end_us);
}

void veh_run_drain(void)
{
    (void)mt_proc_dispatch(veh_io_procs());
    (void)mt_proc_dispatch(veh_io_procs());
}

void veh_run_summary(const veh_run_t *r, const simplat_t *world)
{
    char a[16];
    char b[16];

    veh_summary(r->reason);
    veh_printf("world: max altitude %s m, max ground speed %s m/s, touchdowns %u, bus "
               "collisions %u, servo writes %u\n",
               vp_float(a, sizeof(a), world->max_alt, 1u),
               vp_float(b, sizeof(b), world->max_speed, 1u), (unsigned)world->sim.touchdowns,
               (unsigned)world->collisions, (unsigned)world->servo_writes);
}
