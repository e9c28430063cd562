/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt_port_chibios.c
 * @brief The kernel port contract (kernel/port/mt_port.h) and the firmware
 *        services of mt_port_chibios.h on ChibiOS/RT 7. The only Metronome
 *        file that includes a ChibiOS header.
 *
 * - Time: the RT system time (16/32-bit tick counter) extended to 64 bits by
 *   the kernel's mt_time_extend() (the one wrap-around handling, proved),
 *   converted by mt_time_ticks_to_us(). With a periodic SysTick tick the
 *   microseconds inside the current tick are added from the SysTick counter;
 *   a tick edge not yet serviced (masked by the lock) counts as passed.
 *   Every sample is taken under the kernel lock; the result never decreases.
 * - Lock: chSysLock/chSysUnlock in threads (with a reschedule before
 *   unlocking, so a thread readied inside the critical section runs at
 *   once), chSysLockFromISR/chSysUnlockFromISR in interrupt handlers.
 * - Suspend/resume: chThdSuspendTimeoutS()/chThdResumeI() on the kernel's
 *   waiter field. A timeout is an absolute deadline tick. Up to one RT
 *   interval, RT's own timeout clears the reference. Longer, a virtual timer
 *   of this port re-arms itself in chunks and wakes the thread (clearing the
 *   reference under the lock) only at the deadline: the reference stays set
 *   for the whole wait, so no signal can slip between two chunks.
 * - Sleeps to absolute deadlines: under the lock, wait chunks of
 *   (deadline tick - now tick); on a periodic tick chThdSleepS(n) ends on the
 *   n-th tick edge, so the wake-up is on the deadline tick exactly.
 * - Threads: chThdCreate() on the caller's stack, priority from ArduPilot's
 *   base values plus a signed offset, clamped to [LOWPRIO, HIGHPRIO].
 * - Halt: chSysHalt() (its hook prints the reason and ends the run).
 */
#include "ch.h"

#include "mt/proc.h"
#include "mt/sem.h"
#include "mt/time.h"
#include "mt/wq.h"
#include "mt_chibios_time.h"
#include "mt_port.h"
#include "mt_port_chibios.h"

/* ---- Configuration. ---------------------------------------------------- */

#define ST_HZ           ((uint32_t)CH_CFG_ST_FREQUENCY)
#define ST_COUNTER_MAX  ((uint32_t)(systime_t)~(systime_t)0)

/* Longest single RT wait, in ticks: one RT interval, and no more than one
   counter period so that a wait never hides a wrap from the extension.
   Tests lower it to drive every wait through the split path. */
#if !defined(MT_PORT_CHIBIOS_MAX_CHUNK)
#define MT_PORT_CHIBIOS_MAX_CHUNK                                             \
  (((uint64_t)TIME_MAX_INTERVAL < (uint64_t)ST_COUNTER_MAX) ?                 \
   (uint64_t)TIME_MAX_INTERVAL : (uint64_t)ST_COUNTER_MAX)
#endif

/* Smallest usable thread stack (bytes of stack for the thread body, on top
   of what RT needs for the thread structure, context and interrupts). */
#if !defined(MT_PORT_CHIBIOS_MIN_STACK)
#define MT_PORT_CHIBIOS_MIN_STACK   128U
#endif

/* Added (modulo the counter) to every system-time reading: starts the
   extension anywhere in the counter's range, e.g. just before a wrap. */
#if !defined(MT_PORT_CHIBIOS_ST_OFFSET)
#define MT_PORT_CHIBIOS_ST_OFFSET   0U
#endif

/* Sub-tick time from SysTick: only when SysTick is the periodic RT tick. */
#if !defined(MT_PORT_CHIBIOS_SUBTICK)
#if (CH_CFG_ST_TIMEDELTA == 0) && defined(SysTick_LOAD_RELOAD_Msk) &&       \
    (CH_CFG_ST_FREQUENCY <= 1000000)
#define MT_PORT_CHIBIOS_SUBTICK     TRUE
#else
#define MT_PORT_CHIBIOS_SUBTICK     FALSE
#endif
#endif

_Static_assert((MT_PORT_CHIBIOS_MAX_CHUNK >= 1U) &&
               (MT_PORT_CHIBIOS_MAX_CHUNK <= (uint64_t)TIME_MAX_INTERVAL) &&
               (MT_PORT_CHIBIOS_MAX_CHUNK <= (uint64_t)ST_COUNTER_MAX),
               "MT_PORT_CHIBIOS_MAX_CHUNK must be in [1, min(TIME_MAX_INTERVAL, counter max)]");
_Static_assert((uint64_t)MT_PORT_CHIBIOS_ST_OFFSET <= (uint64_t)ST_COUNTER_MAX,
               "MT_PORT_CHIBIOS_ST_OFFSET beyond the system-time counter");
_Static_assert(CH_CFG_ST_TIMEDELTA == 0,
               "the port's sleeps assume a periodic RT tick (CH_CFG_ST_TIMEDELTA 0)");
/* The kernel keeps the waiter as an opaque pointer; RT writes and clears it
   through a thread_reference_t pointer: same size and representation. */
_Static_assert(sizeof(mt_port_tref_t) == sizeof(thread_reference_t),
               "mt_port_tref_t cannot hold a thread_reference_t");
_Static_assert(sizeof(systime_t) <= sizeof(uint32_t),
               "system time wider than the time extension input");

/* ---- Time. ------------------------------------------------------------- */

static mt_time_ext_t st_ext;
static bool st_started;
static uint64_t st_last_us;
static uint64_t st_edge_ticks;    /* tick of st_edge_us (one conversion per tick) */
static uint64_t st_edge_us;

/* Extended tick count. Lock held, any context. */
static uint64_t st_ticks_s(void) {
  uint32_t raw = mt_chibios_counter_shift((uint32_t)chVTGetSystemTimeX(),
                                          (uint32_t)MT_PORT_CHIBIOS_ST_OFFSET,
                                          ST_COUNTER_MAX);

  if (!st_started) {
    (void)mt_time_ext_init(&st_ext, ST_COUNTER_MAX, raw);
    st_started = true;
  }
  return mt_time_extend(&st_ext, raw);
}

/* Time of the edge that began tick `ticks`. Lock held. */
static uint64_t st_ticks_us_s(uint64_t ticks) {
  if (ticks != st_edge_ticks) {
    st_edge_us = mt_time_ticks_to_us(ticks, ST_HZ);
    st_edge_ticks = ticks;
  }
  return st_edge_us;
}

/* Time of the tick edge that began the current tick. Lock held. */
static uint64_t st_edge_us_s(void) {
  return st_ticks_us_s(st_ticks_s());
}

#if MT_PORT_CHIBIOS_SUBTICK == TRUE
#define ST_TICK_US  (1000000U / ST_HZ)

/* Microseconds into the current tick from SysTick; *edge_passed is set when
   the counter reloaded but the tick interrupt has not run yet (it is masked
   by the lock): the caller then counts that tick. Lock held. */
static uint32_t st_subtick_us_s(bool *edge_passed) {
  uint32_t reload = SysTick->LOAD & SysTick_LOAD_RELOAD_Msk;
  uint32_t pend1 = SCB->ICSR & SCB_ICSR_PENDSTSET_Msk;
  uint32_t val = SysTick->VAL & SysTick_VAL_CURRENT_Msk;
  uint32_t pend2 = SCB->ICSR & SCB_ICSR_PENDSTSET_Msk;
  const uint32_t on = SysTick_CTRL_ENABLE_Msk | SysTick_CTRL_TICKINT_Msk;

  if ((SysTick->CTRL & on) != on) {
    *edge_passed = false;           /* SysTick is not the tick: no sub-tick */
    return 0U;
  }
  *edge_passed = (pend2 != 0U);
  if ((val > reload) || ((pend1 == 0U) && (pend2 != 0U))) {
    return 0U;                      /* the edge passed between the reads */
  }
  return mt_chibios_subtick_us(reload - val, reload + 1U, ST_TICK_US);
}
#else
static uint32_t st_subtick_us_s(bool *edge_passed) {
  *edge_passed = false;
  return 0U;
}
#endif

/* Current time. Lock held, any context. */
static uint64_t st_now_us_s(void) {
  bool edge_passed;
  uint32_t sub = st_subtick_us_s(&edge_passed);
  uint64_t ticks = st_ticks_s();
  uint64_t us;

  if (edge_passed && (ticks < UINT64_MAX)) {
    ticks++;
  }
  us = mt_chibios_time_add(st_ticks_us_s(ticks), sub);
  /* Monotonic by construction, whatever the counter hardware does. */
  if (us < st_last_us) {
    us = st_last_us;
  }
  st_last_us = us;
  return us;
}

uint64_t mt_port_now_us(void) {
  /* Task or ISR context, with or without the lock held. */
  syssts_t sts = chSysGetStatusAndLockX();
  uint64_t us = st_now_us_s();

  chSysRestoreStatusX(sts);
  return us;
}

static virtual_timer_t st_keeper;

static void st_keeper_cb(virtual_timer_t *vtp, void *p) {
  (void)vtp;
  (void)p;
  chSysLockFromISR();
  (void)st_ticks_s();
  chSysUnlockFromISR();
}

void mt_chibios_init(void) {
  /* A quarter of the counter period: several samples per wrap. */
  uint64_t period = ((uint64_t)ST_COUNTER_MAX + 1U) / 4U;

  if (period > MT_PORT_CHIBIOS_MAX_CHUNK) {
    period = MT_PORT_CHIBIOS_MAX_CHUNK;
  }
  chSysInit();
  chSysLock();
  (void)st_ticks_s();
  chVTObjectInit(&st_keeper);
  chVTSetContinuousI(&st_keeper, (sysinterval_t)period, st_keeper_cb, NULL);
  chSysUnlock();
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

/* A wait longer than one chunk: lives in the waiting thread's frame. */
typedef struct {
  virtual_timer_t vt;
  thread_reference_t *trp;
  uint64_t target;          /* deadline tick */
} park_t;

/* Virtual-timer callback: ISR context, lock not held. The park record is
   still valid: its thread resets this timer before leaving the wait, and
   cannot run before this interrupt returns. */
static void park_chunk_cb(virtual_timer_t *vtp, void *p) {
  park_t *pk = (park_t *)p;
  uint64_t n;

  (void)vtp;
  chSysLockFromISR();
  if (*pk->trp != NULL) {
    n = mt_chibios_wait_chunk(pk->target, st_ticks_s(), MT_PORT_CHIBIOS_MAX_CHUNK);
    if (n == 0U) {
      /* The deadline: wake with a timeout, clearing the reference. */
      chThdResumeI(pk->trp, MSG_TIMEOUT);
    }
    else {
      chVTSetI(&pk->vt, (sysinterval_t)n, park_chunk_cb, pk);
    }
  }
  chSysUnlockFromISR();
}

int32_t mt_port_suspend_s(mt_port_tref_t *ref, uint64_t timeout_us) {
  thread_reference_t *trp = (thread_reference_t *)ref;
  uint64_t now;
  uint64_t target;
  uint64_t n;
  msg_t msg;

  chDbgCheckClassS();
  chDbgCheck((ref != NULL) && (*ref == NULL) && (timeout_us > 0U));

  if (timeout_us == MT_WAIT_FOREVER) {
    msg = chThdSuspendTimeoutS(trp, TIME_INFINITE);
  }
  else {
    now = st_ticks_s();
    target = mt_chibios_timeout_deadline(now, timeout_us, ST_HZ);
    n = mt_chibios_wait_chunk(target, now, MT_PORT_CHIBIOS_MAX_CHUNK);
    if (n == 0U) {
      msg = MSG_TIMEOUT;            /* the end of time */
    }
    else if ((target - now) <= MT_PORT_CHIBIOS_MAX_CHUNK) {
      /* One RT interval: RT's own timeout clears *ref on expiry. */
      msg = chThdSuspendTimeoutS(trp, (sysinterval_t)n);
    }
    else {
      park_t pk;

      pk.trp = trp;
      pk.target = target;
      chVTObjectInit(&pk.vt);
      chVTSetI(&pk.vt, (sysinterval_t)n, park_chunk_cb, &pk);
      msg = chThdSuspendTimeoutS(trp, TIME_INFINITE);
      /* Resumed before the deadline: the chunk timer may still be armed. */
      chVTResetI(&pk.vt);
    }
  }

  /* Every way out leaves *ref == NULL: chThdResumeI() clears it, and so
     does RT's timeout handler. */
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

/* ---- Sleeps. ----------------------------------------------------------- */

void mt_chibios_sleep_until_us(uint64_t deadline_us) {
  const uint64_t target = mt_chibios_us_to_ticks_ceil(deadline_us, ST_HZ);
  uint64_t n;

  chSysLock();
  for (;;) {
    n = mt_chibios_wait_chunk(target, st_ticks_s(), MT_PORT_CHIBIOS_MAX_CHUNK);
    if (n == 0U) {
      break;
    }
    chThdSleepS((sysinterval_t)n);
  }
  chSysUnlock();
}

/* ---- Threads. ---------------------------------------------------------- */

/* ArduPilot's ChibiOS priorities (AP_HAL_ChibiOS/Scheduler.h), indexed by
   mt_prio_base_t. SPI and TIMER share 181 there, and so here. */
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

static tprio_t prio_of(mt_prio_base_t base, int8_t offset) {
  int32_t prio = (int32_t)prio_base_map[base] + (int32_t)offset;

  if (prio < (int32_t)LOWPRIO) {
    prio = (int32_t)LOWPRIO;
  }
  if (prio > (int32_t)HIGHPRIO) {
    prio = (int32_t)HIGHPRIO;
  }
  return (tprio_t)prio;
}

mt_status_t mt_port_thread_create(const char *name, mt_thread_fn_t fn,
                                  void *arg, void *stack,
                                  uint32_t stack_bytes, mt_prio_base_t base,
                                  int8_t offset) {
  uintptr_t lo;
  uintptr_t hi;
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

  {
    const thread_descriptor_t td = THD_DESCRIPTOR(
        (name != NULL) ? name : "mt", (stkalign_t *)lo, (stkalign_t *)hi,
        prio_of(base, offset), (tfunc_t)fn, arg);

    tp = chThdCreate(&td);
  }
#if CH_CFG_USE_REGISTRY == TRUE
  /* Nobody joins Metronome threads: drop the creation reference so that an
     exited thread leaves the registry and its stack may be reused. */
  chThdRelease(tp);
#else
  (void)tp;
#endif
  return MT_OK;
}

void mt_chibios_set_priority(mt_prio_base_t base, int8_t offset) {
  if ((uint32_t)base >= MT_PRIO_BASE_COUNT) {
    mt_port_halt("mt_chibios_set_priority: bad base");
  }
  (void)chThdSetPriority(prio_of(base, offset));
}

/* ---- Main-loop metronome. ---------------------------------------------- */

mt_status_t mt_chibios_metronome_init(mt_chibios_metronome_t *m, uint32_t rate_hz) {
  if ((rate_hz == 0U) || (rate_hz > ST_HZ)) {
    return MT_E_INVALID;
  }
  m->period_us = 1000000U / rate_hz;
  m->missed = 0U;
  m->samples = 0U;
  chSysLock();
  m->deadline_us = st_edge_us_s();
  chSysUnlock();
  return MT_OK;
}

uint64_t mt_chibios_metronome_wait(void *ctx) {
  mt_chibios_metronome_t *m = (mt_chibios_metronome_t *)ctx;
  uint32_t missed = mt_proc_period_next(&m->deadline_us, mt_port_now_us(), m->period_us);

  m->missed = ((UINT32_MAX - m->missed) < missed) ? UINT32_MAX : (m->missed + missed);
  mt_chibios_sleep_until_us(m->deadline_us);
  m->samples++;
  return m->deadline_us;
}

/* ---- Proc threads. ----------------------------------------------------- */

static bool proc_thread_stopping(mt_chibios_proc_thread_t *pt) {
  bool stop;

  chSysLock();
  stop = (pt->stop != 0U);
  chSysUnlock();
  return stop;
}

static void proc_thread_fn(void *arg) {
  mt_chibios_proc_thread_t *pt = (mt_chibios_proc_thread_t *)arg;
  uint32_t missed;

  do {
    mt_chibios_sleep_until_us(pt->deadline_us);
    (void)mt_proc_dispatch(pt->set);    /* MT_E_BUSY only when re-entered */
    pt->rounds++;
    missed = mt_proc_period_next(&pt->deadline_us, mt_port_now_us(), pt->period_us);
    mt_proc_note_missed(pt->set, missed);
  } while (!proc_thread_stopping(pt));
  /* Signal and exit in one critical section: whoever takes `done` finds
     the thread terminated (out of the registry, its stack free). */
  chSysLock();
  mt_sem_signal_i(&pt->done);
  chThdExitS(MSG_OK);
}

mt_status_t mt_chibios_proc_thread_start(mt_chibios_proc_thread_t *pt, const char *name,
                                         mt_proc_set_t *set, uint32_t period_us, void *stack,
                                         uint32_t stack_bytes, mt_prio_base_t base) {
  if ((pt == NULL) || (set == NULL) || (period_us == 0U)) {
    return MT_E_INVALID;
  }
  pt->set = set;
  pt->period_us = period_us;
  pt->stop = 0U;
  pt->rounds = 0U;
  mt_sem_init(&pt->done, false);
  chSysLock();
  pt->deadline_us = st_edge_us_s() + period_us;
  chSysUnlock();
  return mt_port_thread_create(name, proc_thread_fn, pt, stack, stack_bytes, base, 0);
}

mt_status_t mt_chibios_proc_thread_stop(mt_chibios_proc_thread_t *pt, uint64_t timeout_us) {
  chSysLock();
  pt->stop = 1U;
  chSysUnlock();
  return mt_sem_wait(&pt->done, timeout_us);
}

/* ---- Work-queue threads. ---------------------------------------------- */

static void wq_thread_fn(void *arg) {
  mt_chibios_wq_thread_t *wt = (mt_chibios_wq_thread_t *)arg;

  mt_wq_thread_body(wt->wq);
  /* Signal and exit in one critical section, as the proc threads do. */
  chSysLock();
  mt_sem_signal_i(&wt->done);
  chThdExitS(MSG_OK);
}

mt_status_t mt_chibios_wq_start(mt_chibios_wq_thread_t *wt, mt_wq_t *q, void *stack,
                                uint32_t stack_bytes) {
  if ((wt == NULL) || (q == NULL)) {
    return MT_E_INVALID;
  }
  wt->wq = q;
  mt_sem_init(&wt->done, false);
  return mt_port_thread_create(q->name, wq_thread_fn, wt, stack, stack_bytes, q->prio_base,
                               q->prio_offset);
}

mt_status_t mt_chibios_wq_stop(mt_chibios_wq_thread_t *wt, uint64_t timeout_us) {
  mt_wq_request_stop(wt->wq);
  return mt_sem_wait(&wt->done, timeout_us);
}

/* ---- ISR timers. ------------------------------------------------------- */

typedef struct {
  virtual_timer_t vt;
  mt_chibios_isr_fn_t fn;
  void *arg;
} isr_timer_t;

static isr_timer_t isr_timers[MT_CHIBIOS_ISR_TIMERS];
static uint32_t isr_timers_used;

static void isr_timer_cb(virtual_timer_t *vtp, void *p) {
  isr_timer_t *it = (isr_timer_t *)p;

  (void)vtp;
  it->fn(it->arg);          /* ISR context, lock not held */
}

mt_status_t mt_chibios_isr_timer_start(uint32_t *id, uint32_t period_us, mt_chibios_isr_fn_t fn,
                                       void *arg) {
  uint64_t ticks = mt_chibios_us_to_ticks_ceil(period_us, ST_HZ);
  isr_timer_t *it;

  if ((id == NULL) || (fn == NULL) || (ticks == 0U) || (ticks > MT_PORT_CHIBIOS_MAX_CHUNK)) {
    return MT_E_INVALID;
  }
  chSysLock();
  if (isr_timers_used >= MT_CHIBIOS_ISR_TIMERS) {
    chSysUnlock();
    return MT_E_FULL;
  }
  *id = isr_timers_used;
  it = &isr_timers[isr_timers_used];
  isr_timers_used++;
  it->fn = fn;
  it->arg = arg;
  chVTObjectInit(&it->vt);
  chVTSetContinuousI(&it->vt, (sysinterval_t)ticks, isr_timer_cb, it);
  chSysUnlock();
  return MT_OK;
}

void mt_chibios_isr_timer_stop(uint32_t id) {
  if (id >= MT_CHIBIOS_ISR_TIMERS) {
    mt_port_halt("mt_chibios_isr_timer_stop: bad id");
  }
  chVTReset(&isr_timers[id].vt);
}

/* ---- Halt. ------------------------------------------------------------- */

void mt_port_halt(const char *reason) {
  chSysHalt(reason);
  for (;;) {
  }
}
