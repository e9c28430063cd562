/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_port.h
 * @brief The port contract: everything the kernel needs from an OS or a board.
 *
 * A port (hal_posix/, hal_chibios/) implements exactly these functions. The
 * kernel proofs assume the ACSL contracts below; each one is listed in the
 * proof report as an assumption. Semantics every port must keep:
 *
 * - Time is monotonic, 64-bit microseconds since an arbitrary epoch. The port
 *   extends its hardware counter with mt_time_extend() (kernel/src/time.c, the
 *   one place where counter wrap-around is handled, proved once). A 64-bit
 *   microsecond count does not wrap for 584,000 years, so no kernel comparison
 *   ever wraps.
 * - The kernel lock is a non-nesting critical section (ChibiOS chSysLock, or a
 *   global mutex on the host). mt_port_lock/unlock are for task context,
 *   mt_port_lock_isr/unlock_isr for interrupt context.
 * - Suspend/resume implement one-waiter blocking for the kernel's semaphore.
 *   The kernel's own (proved) logic decides who gets a token; the port only
 *   parks and un-parks a thread:
 *     mt_port_suspend_s(ref, t) is called with the lock held; it stores a
 *     reference to the calling thread in *ref, releases the lock, sleeps until
 *     mt_port_resume_i(ref) is called or t microseconds pass, and re-takes the
 *     lock before returning. On timeout the port clears *ref itself while
 *     holding the lock, so a later resume finds *ref == NULL and returns false.
 *     t == MT_WAIT_FOREVER never times out; any other t, however long, works
 *     (the port splits it into the chunks its timer can handle).
 * - Threads are created statically (caller-provided stack) at a priority given
 *   as an ArduPilot-like base plus a signed offset.
 */
#ifndef MT_PORT_H
#define MT_PORT_H

#include <stdbool.h>
#include <stdint.h>

#include "mt/status.h"
#include "mt_spec.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Timeout value that never expires. */
#define MT_WAIT_FOREVER UINT64_MAX

/** Results of mt_port_suspend_s(). */
#define MT_PORT_RESUMED 0
#define MT_PORT_TIMEOUT 1

/** Opaque reference to a suspended thread (NULL when none). */
typedef void *mt_port_tref_t;

/** Thread body. */
typedef void (*mt_thread_fn_t)(void *arg);

/** Priority bases, lowest first; ports map them to OS priorities keeping this
 *  order (the ChibiOS port keeps ArduPilot's relative values). */
typedef enum {
    MT_PRIO_IO = 0,       /**< IO procs, logging (low). */
    MT_PRIO_STORAGE = 1,  /**< Storage writes. */
    MT_PRIO_UART = 2,     /**< Serial drivers. */
    MT_PRIO_I2C = 3,      /**< I2C bus threads. */
    MT_PRIO_CAN = 4,      /**< CAN bus threads. */
    MT_PRIO_MAIN = 5,     /**< The main loop (scheduler). */
    MT_PRIO_SPI = 6,      /**< SPI bus threads. */
    MT_PRIO_TIMER = 7,    /**< The 1 kHz timer procs. */
    MT_PRIO_BOOST = 8,    /**< Main loop while boosted. */
    MT_PRIO_BASE_COUNT = 9
} mt_prio_base_t;

/** Monotonic time in microseconds. */
/*@ assigns MtPortNow;
    ensures monotonic: \result >= \old(MtPortNow);
    ensures recorded: MtPortNow == \result;
*/
uint64_t mt_port_now_us(void);

/** Enter the kernel critical section from task context (does not nest). */
/*@ requires not_held: MtLocked == 0;
    assigns MtLocked;
    ensures held: MtLocked == 1;
*/
void mt_port_lock(void);

/** Leave the kernel critical section from task context. */
/*@ requires held: MtLocked == 1;
    assigns MtLocked;
    ensures released: MtLocked == 0;
*/
void mt_port_unlock(void);

/** Enter the kernel critical section from an interrupt handler. */
/*@ requires not_held: MtLocked == 0;
    assigns MtLocked;
    ensures held: MtLocked == 1;
*/
void mt_port_lock_isr(void);

/** Leave the kernel critical section from an interrupt handler. */
/*@ requires held: MtLocked == 1;
    assigns MtLocked;
    ensures released: MtLocked == 0;
*/
void mt_port_unlock_isr(void);

/** Park the calling thread (see the file comment). S-class: lock held. */
/*@ requires held: MtLocked == 1;
    requires valid_ref: \valid(ref);
    requires no_waiter: *ref == \null;
    requires positive: timeout_us > 0;
    assigns *ref, MtPortNow, MtPortHandoffs;
    ensures held: MtLocked == 1;
    ensures cleared: *ref == \null;
    ensures result: \result == MT_PORT_RESUMED || \result == MT_PORT_TIMEOUT;
    ensures handed: \result == MT_PORT_RESUMED <==> MtPortHandoffs != \old(MtPortHandoffs);
*/
int32_t mt_port_suspend_s(mt_port_tref_t *ref, uint64_t timeout_us);

/** Un-park the thread referenced by *ref, if any. I-class: lock held. */
/*@ requires held: MtLocked == 1;
    requires valid_ref: \valid(ref);
    assigns *ref, MtPortWakes;
    ensures cleared: *ref == \null;
    behavior waiter:
      assumes *ref != \null;
      ensures woke: \result == \true;
      ensures delivered: MtPortWakes != \old(MtPortWakes);
    behavior nobody:
      assumes *ref == \null;
      ensures none: \result == \false;
      ensures none_delivered: MtPortWakes == \old(MtPortWakes);
    complete behaviors;
    disjoint behaviors;
*/
bool mt_port_resume_i(mt_port_tref_t *ref);

/** Create a thread. @retval MT_OK, MT_E_INVALID (bad base, NULL fn, stack too
 *  small for the port), MT_E_FULL (the port has no thread slot left). */
mt_status_t mt_port_thread_create(const char *name, mt_thread_fn_t fn, void *arg, void *stack,
                                  uint32_t stack_bytes, mt_prio_base_t base, int8_t offset);

/** Stop the system after a contract violation; never returns. */
/*@ assigns \nothing;
    ensures never: \false;
*/
void mt_port_halt(const char *reason);

#ifdef __cplusplus
}
#endif

#endif /* MT_PORT_H */
