/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Metronome - implementation of the kernel port contract
 * (kernel/port/mt_port.h) on ChibiOS/RT 7.
 *
 * - Time: the RT system tick (CH_CFG_ST_FREQUENCY, 16/32-bit counter)
 *   extended to 64 bits by the kernel's mt_time_extend() and converted to
 *   microseconds. Resolution is one tick (1 ms with the shipped chconf.h).
 * - Lock: chSysLock/chSysUnlock in task context (with a reschedule before
 *   unlocking, so that a thread readied by an I-class call inside the
 *   critical section runs at once), chSysLockFromISR/chSysUnlockFromISR in
 *   interrupt handlers.
 * - Suspend/resume: chThdSuspendTimeoutS()/chThdResumeI() on the kernel's
 *   waiter field. ChibiOS itself clears the reference under the lock when a
 *   timeout fires, as the contract requires. Timeouts longer than one RT
 *   interval are split by a virtual timer of this port, which only wakes the
 *   thread (and so clears the reference) at the real deadline.
 * - Threads: chThdCreateStatic() on the caller's stack, priority from an
 *   ArduPilot-like base plus a signed offset, clamped to [LOWPRIO, HIGHPRIO].
 *   Threads are not joinable; a thread whose function returns exits, and its
 *   stack may then be given to a new thread.
 * - Halt: chSysHalt().
 */
#include "ch.h"

#include "mt/time.h"
#include "mt_port.h"
#include "mt_port_chibios.h"

/* ---- Configuration. ---------------------------------------------------- */

/* Longest single RT wait, in ticks. Tests lower it to exercise the split
 * path with short timeouts. */
#if !defined(MT_PORT_CHIBIOS_MAX_CHUNK)
#define MT_PORT_CHIBIOS_MAX_CHUNK   ((uint64_t)TIME_MAX_INTERVAL)
#endif

/* Smallest usable thread stack (bytes of stack for the thread body, on top of
 * what the RT port needs for the thread structure, context and interrupts). */
#if !defined(MT_PORT_CHIBIOS_MIN_STACK)
#define MT_PORT_CHIBIOS_MIN_STACK   128U
#endif

_Static_assert((MT_PORT_CHIBIOS_MAX_CHUNK >= 1U) &&
               (MT_PORT_CHIBIOS_MAX_CHUNK <= (uint64_t)TIME_MAX_INTERVAL),
               "MT_PORT_CHIBIOS_MAX_CHUNK must be in [1, TIME_MAX_INTERVAL]");

/* The kernel keeps the waiter as an opaque pointer; ChibiOS writes and
 * clears it through a thread_reference_t pointer. Same size and
 * representation; GCC lets void * alias every pointer type. */
_Static_assert(sizeof(mt_port_tref_t) == sizeof(thread_reference_t),
               "mt_port_tref_t cannot hold a thread_reference_t");
_Static_assert(sizeof(systime_t) <= sizeof(uint32_t),
               "system time wider than the time extension input");

#define ST_COUNTER_MAX  ((uint32_t)(systime_t)~(systime_t)0)

/* ---- Time. ------------------------------------------------------------- */

static mt_time_ext_t st_ext;
static bool st_ext_started;

uint64_t mt_port_now_us(void) {
  syssts_t sts;
  uint64_t ticks;

  /* Callable from task or ISR context, with or without the lock held. */
  sts = chSysGetStatusAndLockX();
  if (!st_ext_started) {
    (void)mt_time_ext_init(&st_ext, ST_COUNTER_MAX,
                           (uint32_t)chVTGetSystemTimeX());
    st_ext_started = true;
  }
  ticks = mt_time_extend(&st_ext, (uint32_t)chVTGetSystemTimeX());
  chSysRestoreStatusX(sts);

  return mt_time_ticks_to_us(ticks, (uint32_t)CH_CFG_ST_FREQUENCY);
}

static virtual_timer_t st_keepalive;

static void st_keepalive_cb(virtual_timer_t *vtp, void *p) {
  (void)vtp;
  (void)p;
  (void)mt_port_now_us();
}

void mt_port_chibios_start(void) {
  /* A quarter of the counter period: at least three samples per wrap. */
  uint64_t period = ((uint64_t)ST_COUNTER_MAX + 1U) / 4U;

  if (period > (uint64_t)TIME_MAX_INTERVAL) {
    period = (uint64_t)TIME_MAX_INTERVAL;
  }
  (void)mt_port_now_us();
  chVTObjectInit(&st_keepalive);
  chVTSetContinuous(&st_keepalive, (sysinterval_t)period, st_keepalive_cb,
                    NULL);
}

/* ---- Lock. ------------------------------------------------------------- */

void mt_port_lock(void) {
  chSysLock();
}

void mt_port_unlock(void) {
  /* Run any higher-priority thread readied inside the critical section
     (RT asserts on unlocking with such a thread pending). */
  chSchRescheduleS();
  chSysUnlock();
}

void mt_port_lock_isr(void) {
  chSysLockFromISR();
}

void mt_port_unlock_isr(void) {
  /* The IRQ epilogue reschedules when the handler returns. */
  chSysUnlockFromISR();
}

/* ---- Suspend / resume. ------------------------------------------------- */

/* Microseconds to ticks, rounded up, saturating. */
static uint64_t us_to_ticks_ceil(uint64_t us) {
  const uint64_t hz = (uint64_t)CH_CFG_ST_FREQUENCY;
  uint64_t whole = us / 1000000U;
  uint64_t part = ((us % 1000000U) * hz + 999999U) / 1000000U;

  if (whole > ((UINT64_MAX - part) / hz)) {
    return UINT64_MAX;
  }
  return (whole * hz) + part;
}

/* A long wait in progress: lives in the waiting thread's frame. */
typedef struct {
  virtual_timer_t vt;
  thread_reference_t *trp;
  uint64_t left;            /* ticks still to wait after the armed chunk */
} park_t;

static sysinterval_t next_chunk(uint64_t *left) {
  uint64_t chunk = *left;

  if (chunk > MT_PORT_CHIBIOS_MAX_CHUNK) {
    chunk = MT_PORT_CHIBIOS_MAX_CHUNK;
  }
  *left -= chunk;
  return (sysinterval_t)chunk;
}

/* Virtual-timer callback: ISR context, lock not held. The park record is
 * still valid: its thread cannot run before this interrupt returns. */
static void park_chunk_cb(virtual_timer_t *vtp, void *p) {
  park_t *pk = (park_t *)p;

  (void)vtp;
  chSysLockFromISR();
  if (*pk->trp != NULL) {
    if (pk->left == 0U) {
      /* Real deadline: wake with a timeout, clearing the reference. */
      chThdResumeI(pk->trp, MSG_TIMEOUT);
    }
    else {
      chVTSetI(&pk->vt, next_chunk(&pk->left), park_chunk_cb, pk);
    }
  }
  chSysUnlockFromISR();
}

int32_t mt_port_suspend_s(mt_port_tref_t *ref, uint64_t timeout_us) {
  thread_reference_t *trp = (thread_reference_t *)ref;
  uint64_t ticks;
  msg_t msg;

  chDbgCheckClassS();
  chDbgCheck((ref != NULL) && (*ref == NULL) && (timeout_us > 0U));

  if (timeout_us == MT_WAIT_FOREVER) {
    msg = chThdSuspendTimeoutS(trp, TIME_INFINITE);
  }
  else {
    ticks = us_to_ticks_ceil(timeout_us);
#if CH_CFG_ST_TIMEDELTA == 0
    /* Periodic tick: a wait of n ticks may end up to one tick early
       (it counts tick edges), so wait one more to cover timeout_us. */
    if (ticks < UINT64_MAX) {
      ticks++;
    }
#endif
    if (ticks <= MT_PORT_CHIBIOS_MAX_CHUNK) {
      /* One RT interval: ChibiOS' own timeout clears *ref on expiry. */
      msg = chThdSuspendTimeoutS(trp, (sysinterval_t)ticks);
    }
    else {
      park_t pk;

      pk.trp = trp;
      pk.left = ticks;
      chVTObjectInit(&pk.vt);
      chVTSetI(&pk.vt, next_chunk(&pk.left), park_chunk_cb, &pk);
      msg = chThdSuspendTimeoutS(trp, TIME_INFINITE);
      /* Resumed early: the chunk timer may still be armed. */
      chVTResetI(&pk.vt);
    }
  }

  /* Both ways out leave *ref == NULL: chThdResumeI() clears it, and so does
     the RT timeout handler. */
  chDbgAssert(*ref == NULL, "waiter reference not cleared");
  return (msg == MSG_OK) ? MT_PORT_RESUMED : MT_PORT_TIMEOUT;
}

bool mt_port_resume_i(mt_port_tref_t *ref) {
  thread_reference_t *trp = (thread_reference_t *)ref;

  chDbgCheckClassI();
  chDbgCheck(ref != NULL);

  if (*trp == NULL) {
    return false;
  }
  chThdResumeI(trp, MSG_OK);
  return true;
}

/* ---- Threads. ---------------------------------------------------------- */

/* ArduPilot's ChibiOS priorities (AP_HAL_ChibiOS/Scheduler.h), indexed by
 * mt_prio_base_t. SPI and TIMER share 181 there, and so here. */
static const tprio_t prio_base_map[MT_PRIO_BASE_COUNT] = {
  [MT_PRIO_IO]      = 58,
  [MT_PRIO_STORAGE] = 59,
  [MT_PRIO_UART]    = 60,
  [MT_PRIO_I2C]     = 176,
  [MT_PRIO_CAN]     = 178,
  [MT_PRIO_MAIN]    = 180,
  [MT_PRIO_SPI]     = 181,
  [MT_PRIO_TIMER]   = 181,
  [MT_PRIO_BOOST]   = 182
};

mt_status_t mt_port_thread_create(const char *name, mt_thread_fn_t fn,
                                  void *arg, void *stack,
                                  uint32_t stack_bytes, mt_prio_base_t base,
                                  int8_t offset) {
  uintptr_t lo;
  uintptr_t hi;
  int32_t prio;
  thread_t *tp;

  if ((fn == NULL) || (stack == NULL) || ((uint32_t)base >= MT_PRIO_BASE_COUNT)) {
    return MT_E_INVALID;
  }

  /* Trim the caller's area to the alignment RT requires. */
  lo = (uintptr_t)stack;
  hi = lo + (uintptr_t)stack_bytes;
  if (hi < lo) {
    return MT_E_INVALID;
  }
  lo = (lo + (PORT_WORKING_AREA_ALIGN - 1U)) &
       ~(uintptr_t)(PORT_WORKING_AREA_ALIGN - 1U);
  hi &= ~(uintptr_t)(PORT_STACK_ALIGN - 1U);
  if ((hi <= lo) ||
      ((hi - lo) < (uintptr_t)THD_WORKING_AREA_SIZE(MT_PORT_CHIBIOS_MIN_STACK))) {
    return MT_E_INVALID;
  }

  prio = (int32_t)prio_base_map[base] + (int32_t)offset;
  if (prio < (int32_t)LOWPRIO) {
    prio = (int32_t)LOWPRIO;
  }
  if (prio > (int32_t)HIGHPRIO) {
    prio = (int32_t)HIGHPRIO;
  }

  tp = chThdCreateStatic((void *)lo, (size_t)(hi - lo), (tprio_t)prio,
                         (tfunc_t)fn, arg);
#if CH_CFG_USE_REGISTRY == TRUE
  /* Debug name only; the thread may already be running (our reference
     keeps its record valid until the release below). */
  chRegSetThreadNameX(tp, (name != NULL) ? name : "mt");
  /* Nobody joins Metronome threads: drop the creation reference so that an
     exited thread leaves the registry and its stack may be reused. */
  chThdRelease(tp);
#else
  (void)tp;
  (void)name;
#endif
  return MT_OK;
}

/* ---- Halt. ------------------------------------------------------------- */

void mt_port_halt(const char *reason) {
  chSysHalt(reason);
  for (;;) {
  }
}
