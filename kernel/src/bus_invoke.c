/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file bus_invoke.c
 * @brief Topic bus notifier calls (assumption A1, see mt_bus_invoke.h). Not analysed by WP.
 */
#include "mt_bus_invoke.h"

#include "mt/sem.h"

/* The slot only names the call for the proofs (the ghost MtCalls). */
void mt_bus_invoke_notify(mt_bus_notify_fn_t fn, void *arg, uint32_t slot)
{
    (void)slot;
    fn(arg);
}

void mt_bus_invoke_wake(void *sem)
{
    mt_sem_signal_i((mt_sem_t *)sem);
}

void *mt_bus_invoke_wake_arg(mt_sem_t *sem)
{
    return (void *)sem;
}
