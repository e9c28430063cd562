/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Metronome - smoke test of the ChibiOS port (hal_chibios/port) through the
 * kernel's semaphore: time, lock, suspend/resume with and without timeout
 * (single RT interval and split waits), signal from an ISR, thread creation
 * and priorities, then the firmware services of mt_port_chibios.h: sleeps
 * to absolute deadlines, the metronome, a proc thread stopped and restarted
 * on the same stack, an ISR timer. Prints "port ok ..." and exits 0, or halts
 * with a reason (exit 1). FAIL=1 ends with mt_port_halt() instead.
 * Build with EXTRA_DEFS=-DMT_PORT_CHIBIOS_MAX_CHUNK=3 to force every finite
 * wait through the split path.
 */
#include "ch.h"
#include "fw_board.h"
#include "mt/sem.h"
#include "mt_port.h"
#include "mt_port_chibios.h"

static mt_sem_t sem;
static volatile uint32_t waiter_result;
static volatile uint32_t waiter_done;
static volatile uint32_t order_log[4];
static volatile uint32_t order_n;

static uint64_t worker_stack[256];
static uint64_t hi_stack[128];

static void check(bool ok, const char *what) {
  if (!ok) {
    mt_port_halt(what);
  }
}

/* Waits forever on the semaphore; main signals it. */
static void waiter_fn(void *arg) {
  uint64_t timeout = *(const uint64_t *)arg;

  waiter_result = (uint32_t)mt_sem_wait(&sem, timeout);
  waiter_done = 1U;
}

/* High-priority thread: must run before thread_create returns. */
static void hi_fn(void *arg) {
  (void)arg;
  order_log[order_n++] = 1U;
}

static virtual_timer_t isr_vt;

static void isr_signal_cb(virtual_timer_t *vtp, void *p) {
  (void)vtp;
  (void)p;
  mt_sem_signal_isr(&sem);    /* ISR context, lock not held */
}

static mt_proc_set_t procs;
static mt_chibios_proc_thread_t proc_thread;
static volatile uint32_t proc_calls;
static volatile uint32_t isr_calls;

static void count_proc(void *arg) {
  (void)arg;
  proc_calls++;
}

static void count_isr(void *arg) {
  (void)arg;
  isr_calls++;
}

/* Firmware services beyond the port contract. */
static void services(void) {
  mt_chibios_metronome_t m;
  uint64_t t0;
  uint64_t t1;
  uint64_t prev;
  uint32_t id;
  uint32_t k;

  /* Sleep to an absolute deadline: not early, wakes on the next tick edge. */
  t0 = mt_port_now_us();
  mt_chibios_sleep_until_us(t0 + 5000U);
  t1 = mt_port_now_us();
  check((t1 >= t0 + 5000U) && (t1 < t0 + 6100U), "sleep_until: wake time");
  mt_chibios_sleep_until_us(t0);                  /* past deadline: at once */
  check(mt_port_now_us() - t1 < 1000U, "sleep_until: past deadline");

  /* Metronome: 500 Hz samples two ticks apart, none missed. */
  check(mt_chibios_metronome_init(&m, 0U) == MT_E_INVALID, "metronome: rate 0");
  check(mt_chibios_metronome_init(&m, 500U) == MT_OK, "metronome: init");
  prev = mt_chibios_metronome_wait(&m);
  for (k = 0U; k < 10U; k++) {
    t0 = mt_chibios_metronome_wait(&m);
    check(t0 == prev + 2000U, "metronome: period");
    check(mt_port_now_us() >= t0, "metronome: early");
    prev = t0;
  }
  check((m.samples == 11U) && (m.missed == 0U), "metronome: counts");

  /* Proc thread at 1 kHz, stopped, then restarted on the same stack. */
  mt_proc_set_init(&procs);
  check(mt_proc_register(&procs, count_proc, NULL) == MT_OK, "proc: register");
  for (k = 0U; k < 2U; k++) {
    proc_calls = 0U;
    check(mt_chibios_proc_thread_start(&proc_thread, "procs", &procs, 1000U,
                                       worker_stack, sizeof(worker_stack),
                                       MT_PRIO_TIMER) == MT_OK, "proc: start");
    mt_chibios_sleep_until_us(mt_port_now_us() + 10000U);
    check(mt_chibios_proc_thread_stop(&proc_thread, 5000U) == MT_OK, "proc: stop");
    /* 10 ms of 1 kHz rounds, plus the edge the sleep ends on and the one
       on which the thread sees the stop request. */
    check((proc_calls >= 10U) && (proc_calls <= 12U), "proc: rate");
    check(procs.periods_missed == 0U, "proc: missed periods");
  }

  /* ISR timer every 2 ms; nothing after the stop. */
  check(mt_chibios_isr_timer_start(&id, 2000U, count_isr, NULL) == MT_OK, "isr timer: start");
  mt_chibios_sleep_until_us(mt_port_now_us() + 20000U);
  mt_chibios_isr_timer_stop(id);
  k = isr_calls;
  check((k >= 9U) && (k <= 10U), "isr timer: rate");
  mt_chibios_sleep_until_us(mt_port_now_us() + 10000U);
  check(isr_calls == k, "isr timer: called after stop");
}

static void wait_done(void) {
  while (waiter_done == 0U) {
    chThdSleepMilliseconds(1);
  }
}

int main(void) {
  uint64_t t0;
  uint64_t t1;
  uint64_t dt_timeout;
  static uint64_t forever = MT_WAIT_FOREVER;
  static uint64_t long_timeout = 50000U;   /* 50 ms */
  mt_status_t st;

  fw_board_init();
  mt_chibios_init();

  /* Time: monotonic, follows the tick. */
  t0 = mt_port_now_us();
  chThdSleepMilliseconds(10);
  t1 = mt_port_now_us();
  check((t1 >= t0 + 9000U) && (t1 <= t0 + 11000U), "time: 10 ms sleep");

  /* Timeout without a signal: at least the requested time. */
  mt_sem_init(&sem, false);
  t0 = mt_port_now_us();
  st = mt_sem_wait(&sem, 5000U);
  t1 = mt_port_now_us();
  dt_timeout = t1 - t0;
  check(st == MT_E_TIMEOUT, "sem: timeout status");
  check((dt_timeout >= 5000U) && (dt_timeout <= 7000U), "sem: timeout length");
  check(sem.waiter == NULL, "sem: waiter left after timeout");

  /* Non-blocking and token paths. */
  check(mt_sem_wait(&sem, 0U) == MT_E_TIMEOUT, "sem: poll empty");
  mt_sem_signal(&sem);
  check(mt_sem_wait(&sem, 0U) == MT_OK, "sem: poll token");

  /* Resume from task context, waiter parked forever (higher priority
     than main: it parks before create returns). */
  waiter_done = 0U;
  check(mt_port_thread_create("waiter", waiter_fn, &forever, worker_stack,
                              sizeof(worker_stack), MT_PRIO_MAIN, 0) == MT_OK,
        "create: waiter");
  check(sem.waiter != NULL, "sem: waiter not parked");
  chThdSleepMilliseconds(3);
  check(waiter_done == 0U, "sem: forever wait returned early");
  mt_sem_signal(&sem);          /* unlock reschedules: runs at once */
  check(waiter_done == 1U, "sem: resume did not preempt");
  check(waiter_result == (uint32_t)MT_OK, "sem: resume status");
  check(sem.token == 0U, "sem: token handed over");

  /* Resume from an ISR (virtual-timer callback) during a long finite wait
     (split path when MT_PORT_CHIBIOS_MAX_CHUNK is small). */
  waiter_done = 0U;
  check(mt_port_thread_create("waiter2", waiter_fn, &long_timeout,
                              worker_stack, sizeof(worker_stack),
                              MT_PRIO_MAIN, 0) == MT_OK,
        "create: waiter2");
  chVTObjectInit(&isr_vt);
  chVTSet(&isr_vt, TIME_MS2I(20), isr_signal_cb, NULL);
  t0 = mt_port_now_us();
  wait_done();
  t1 = mt_port_now_us();
  check(waiter_result == (uint32_t)MT_OK, "sem: isr resume status");
  check((t1 - t0) <= 30000U, "sem: isr resume late");

  /* Long finite wait that times out. */
  waiter_done = 0U;
  t0 = mt_port_now_us();
  check(mt_port_thread_create("waiter3", waiter_fn, &long_timeout,
                              worker_stack, sizeof(worker_stack),
                              MT_PRIO_MAIN, 0) == MT_OK,
        "create: waiter3");
  wait_done();
  t1 = mt_port_now_us();
  check(waiter_result == (uint32_t)MT_E_TIMEOUT, "sem: long timeout status");
  check((t1 - t0) >= 50000U, "sem: long timeout early");
  check(sem.waiter == NULL, "sem: waiter left after long timeout");

  /* Thread creation: priority order and argument checks. */
  order_n = 0U;
  check(mt_port_thread_create("hi", hi_fn, NULL, hi_stack, sizeof(hi_stack),
                              MT_PRIO_TIMER, 1) == MT_OK, "create: hi");
  order_log[order_n++] = 2U;
  check((order_n == 2U) && (order_log[0] == 1U) && (order_log[1] == 2U),
        "create: priority order");
  check(mt_port_thread_create("bad", hi_fn, NULL, hi_stack, sizeof(hi_stack),
                              MT_PRIO_BASE_COUNT, 0) == MT_E_INVALID,
        "create: bad base accepted");
  check(mt_port_thread_create("bad", NULL, NULL, hi_stack, sizeof(hi_stack),
                              MT_PRIO_IO, 0) == MT_E_INVALID,
        "create: NULL fn accepted");
  check(mt_port_thread_create("bad", hi_fn, NULL, hi_stack, 64U,
                              MT_PRIO_IO, 0) == MT_E_INVALID,
        "create: tiny stack accepted");

  services();

#if defined(FW_FAIL)
  mt_port_halt("port_smoke: deliberate failure (FAIL=1)");
#endif

  fw_puts("port ok timeout_us=");
  fw_put_u32((uint32_t)dt_timeout);
  fw_puts(" now_ms=");
  fw_put_u32((uint32_t)(mt_port_now_us() / 1000U));
  fw_puts("\r\n");
  fw_exit(FW_EXIT_SUCCESS);
}
