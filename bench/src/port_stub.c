/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file port_stub.c
 * @brief Bench-only port (replaces hal_posix/port.c in the stub binaries).
 *
 * Time is a counter that moves one microsecond per mt_port_now_us() call (the
 * ArduPilot-style peers use the same stub, bench/src/stub_time.c), so the
 * scheduler and proc figures measure the kernel's own work, not the host
 * clock or the hal_posix mutex around it. The lock is a flag (one thread).
 * Nothing here may block: suspend returns a timeout at once.
 */
#include <stdio.h>
#include <stdlib.h>

#include "mt_port.h"

static uint64_t g_now;
static volatile int g_locked;

uint64_t mt_port_now_us(void)
{
    return ++g_now;
}

void mt_port_lock(void)
{
    g_locked = 1;
}

void mt_port_unlock(void)
{
    g_locked = 0;
}

void mt_port_lock_isr(void)
{
    g_locked = 1;
}

void mt_port_unlock_isr(void)
{
    g_locked = 0;
}

int32_t mt_port_suspend_s(mt_port_tref_t *ref, uint64_t timeout_us)
{
    (void)timeout_us;
    *ref = (mt_port_tref_t)0;
    return MT_PORT_TIMEOUT;
}

bool mt_port_resume_i(mt_port_tref_t *ref)
{
    bool had = (*ref != (mt_port_tref_t)0);
    *ref = (mt_port_tref_t)0;
    return had;
}

mt_status_t mt_port_thread_create(const char *name, mt_thread_fn_t fn, void *arg, void *stack,
                                  uint32_t stack_bytes, mt_prio_base_t base, int8_t offset)
{
    (void)name;
    (void)fn;
    (void)arg;
    (void)stack;
    (void)stack_bytes;
    (void)base;
    (void)offset;
    return MT_E_FULL;
}

void mt_port_halt(const char *reason)
{
    fprintf(stderr, "bench port: halt: %s\n", reason);
    abort();
}
