/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file sensor_bus.c
 * @brief The shared sensor bus: the barometer driver (timer thread) and the
 *        battery monitor (a work item, work-queue thread) use one bus; a binary
 *        semaphore (mt/sem.h) initialised free is its lock, so transactions
 *        never overlap (the simulated bus counts overlaps as collisions).
 */
#include "veh_int.h"

bool veh_bus_read(veh_bus_t *b, const veh_platform_t *p, uint8_t dev, uint8_t reg, uint8_t *rx,
                  uint32_t n, uint64_t timeout_us)
{
    mt_status_t st = mt_sem_wait(&b->sem, 0u);
    bool ok;

    if (st != MT_OK) {
        /* busy: wait for the other user to give it back */
        st = mt_sem_wait(&b->sem, timeout_us);
        if (st != MT_OK) {
            /* not held: only this thread's own count is touched, atomically */
            __atomic_fetch_add(&b->timeouts, 1u, __ATOMIC_RELAXED);
            return false;
        }
        b->waits++;
    }
    ok = p->bus_read(p->ctx, dev, reg, rx, n);
    b->transfers++;
    mt_sem_signal(&b->sem);
    return ok;
}
