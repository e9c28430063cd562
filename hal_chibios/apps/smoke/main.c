/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file apps/smoke/main.c
 * @brief Firmware smoke test: every kernel module on ChibiOS/RT, run under
 *        QEMU with deterministic -icount; exit status 0 only when every
 *        expected count holds.
 *
 * Uses only the kernel's public API (mt/mt.h), the port's firmware services
 * (mt_port_chibios.h) and the board console (fw_board.h): no ChibiOS header.
 *
 * What runs (priorities are the port's ArduPilot-like bases):
 * - main loop (MAIN, 180): the scheduler at LOOP_HZ on the port's metronome,
 *   for RUN_PERIODS periods; a task table of two fast tasks and rated tasks
 *   at 250/100/50/10/1 Hz with budgets. Tasks spin for a fixed time (their
 *   "work"), so the statistics show real, deterministic durations.
 * - timer thread (TIMER, 181, 1 kHz, absolute deadlines): proc obj_push
 *   pushes sequence-numbered objects to an object ring drained by the 50 Hz
 *   task obj_drain; proc byte_push writes 1..5 bytes of a known sequence per
 *   call to a byte ring (write and reserve/commit alternately).
 * - IO thread (IO, 58, 250 Hz): proc byte_pull reads the byte ring
 *   (zero-copy segments) and checks every byte; proc io_beat counts calls.
 * - ISR: a periodic virtual timer (ISR_PERIOD_US) signals isr_sem with
 *   mt_sem_signal_isr (ISR lock flavour: the kernel lock is not held there).
 * - sensor thread (SPI, 181) takes isr_sem, hands a token to the ponger
 *   thread (I2C, 176) through ping_sem and waits for it back on pong_sem.
 * - work queue `wq_smoke` (CAN, 178, its own thread): an interval item every
 *   WQ_PERIOD_US driven by the timer procs (mt_wq_timer_proc), an item the
 *   ISR schedules on every tick (mt_work_schedule_isr), and a single-shot
 *   item main waits for (mt_work_run_wait) before the loop starts.
 *
 * Checks: each task's runs within one of RUN_PERIODS / interval and no
 * slips; no missed loop, timer or IO periods; every object and byte
 * delivered in order, none lost or rejected; every semaphore signal taken
 * (none merged, no timeout); the interval item ran once per period, none
 * missed or merged; every ISR activation of the work item is a run or a
 * counted merge; the single shot returned MT_OK after its run. The loop rate, 500 Hz, is two ticks of the
 * 1 kHz RT tick, so every sample falls on a tick edge, and it divides into
 * 250/100/50/10/1 Hz exactly, so each expected run count is exact.
 *
 * Seeded failures: FW_FAIL == 1 runs a table whose budgets cannot fit:
 * three 100 Hz tasks and a 250 Hz task of 1200 us each (budget = work) in a
 * 2000 us loop. One fits per loop and the 100 Hz tasks come first, so the
 * 250 Hz task runs in one loop of five instead of one of two: its releases
 * slip and its run count falls short (about 300 of 750). FW_FAIL == 2 makes a task execute an undefined
 * instruction (fault handler, exit 1).
 */
#include <stdbool.h>
#include <stdint.h>

#include "fw_board.h"
#include "mt/mt.h"
#include "mt_port_chibios.h"

/* ---- Parameters. ------------------------------------------------------- */

#define LOOP_HZ 500u
#define RUN_S 3u
#define RUN_PERIODS (LOOP_HZ * RUN_S)
#define TIMER_PERIOD_US 1000u
#define IO_PERIOD_US 4000u
#define ISR_PERIOD_US 3000u
#define SEM_TIMEOUT_US 20000u
#define STOP_TIMEOUT_US 100000u
#define RUN_TOLERANCE 1u /* runs: one release may still be pending */
#define WQ_PERIOD_US 10000u
#define WQ_SHOT_TIMEOUT_US 100000u

#define OBJ_CAP 32u  /* 20 objects arrive per 50 Hz drain */
#define BYTE_CAP 64u /* at most 20 bytes arrive per IO period */
#define BYTE_MAX_CHUNK 5u

/* ---- Console helpers. -------------------------------------------------- */

static void put_col(uint32_t v, uint32_t width)
{
    char buf[10];
    uint32_t n = 0u;

    do {
        buf[n] = (char)('0' + (char)(v % 10u));
        n++;
        v /= 10u;
    } while (v != 0u);
    while (width > n) {
        fw_putc(' ');
        width--;
    }
    while (n > 0u) {
        n--;
        fw_putc(buf[n]);
    }
}

static void put_u(uint64_t v)
{
    fw_put_u32((v > 0xFFFFFFFFu) ? 0xFFFFFFFFu : (uint32_t)v);
}

static void put_name(const char *s, uint32_t width)
{
    uint32_t n = 0u;

    while (s[n] != '\0') {
        fw_putc(s[n]);
        n++;
    }
    while (n < width) {
        fw_putc(' ');
        n++;
    }
}

static void nl(void)
{
    fw_puts("\r\n");
}

/* ---- Checks. ----------------------------------------------------------- */

static uint32_t failures;

static void check(bool ok, const char *what)
{
    if (!ok) {
        failures++;
        fw_puts("CHECK FAILED: ");
        fw_puts(what);
        nl();
    }
}

/* ---- Work. ------------------------------------------------------------- */

/* Busy for us microseconds of (simulated) time. */
static void spin_us(uint32_t us)
{
    uint64_t end = mt_port_now_us() + us;

    while (mt_port_now_us() < end) {
    }
}

typedef struct {
    uint32_t spin_us;
    uint32_t acc;
} work_t;

static void t_work(void *arg)
{
    work_t *w = (work_t *)arg;

    w->acc = (w->acc * 1664525u) + 1013904223u;
    spin_us(w->spin_us);
}

/* ---- Object ring: timer proc -> main-loop task. ------------------------ */

typedef struct {
    uint32_t seq;
    uint32_t stamp_ms;
    uint32_t check;
} sample_obj_t;

static uint8_t obj_storage[MT_ORING_STORAGE_BYTES(sizeof(sample_obj_t), OBJ_CAP)];
static mt_oring_t obj_ring;
static uint32_t obj_pushed; /* timer thread */
static uint32_t obj_popped; /* main thread */
static uint32_t obj_bad;    /* main thread: out of order or corrupt */

static uint32_t obj_check(uint32_t seq)
{
    return (seq * 2654435761u) ^ 0xA5A5A5A5u;
}

static void p_obj_push(void *arg)
{
    sample_obj_t o;

    (void)arg;
    o.seq = obj_pushed;
    o.stamp_ms = (uint32_t)(mt_port_now_us() / 1000u);
    o.check = obj_check(o.seq);
    if (mt_oring_push(&obj_ring, &o) == MT_OK) {
        obj_pushed++;
    }
}

static void t_obj_drain(void *arg)
{
    sample_obj_t o;

    (void)arg;
    while (mt_oring_pop(&obj_ring, &o) == MT_OK) {
        if ((o.seq != obj_popped) || (o.check != obj_check(o.seq))) {
            obj_bad++;
        }
        obj_popped++;
    }
}

/* ---- Byte ring: timer proc -> IO proc. --------------------------------- */

static uint8_t byte_storage[BYTE_CAP];
static mt_bring_t byte_ring;
static uint32_t byte_calls;   /* timer thread */
static uint32_t byte_written; /* timer thread */
static uint32_t byte_short;   /* timer thread: bytes that did not fit */
static uint32_t byte_read;    /* IO thread, then main */
static uint32_t byte_bad;     /* IO thread, then main */

static uint8_t byte_at(uint32_t n)
{
    return (uint8_t)((n * 31u) + 7u);
}

static void p_byte_push(void *arg)
{
    uint8_t buf[BYTE_MAX_CHUNK];
    uint32_t len = 1u + (byte_calls % BYTE_MAX_CHUNK);
    uint32_t done = 0u;
    uint32_t i;

    (void)arg;
    if ((byte_calls & 1u) == 0u) {
        for (i = 0u; i < len; i++) {
            buf[i] = byte_at(byte_written + i);
        }
        done = mt_bring_write(&byte_ring, buf, len);
    } else {
        mt_iovec_t v[2];
        uint32_t segs = mt_bring_reserve(&byte_ring, v, len);
        uint32_t s;

        for (s = 0u; s < segs; s++) {
            for (i = 0u; i < v[s].len; i++) {
                v[s].base[i] = byte_at(byte_written + done);
                done++;
            }
        }
        (void)mt_bring_commit(&byte_ring, done);
    }
    byte_written += done;
    byte_short += len - done;
    byte_calls++;
}

static void p_byte_pull(void *arg)
{
    mt_iovec_t v[2];
    uint32_t segs = mt_bring_peek_vec(&byte_ring, v);
    uint32_t total = 0u;
    uint32_t s;
    uint32_t i;

    (void)arg;
    for (s = 0u; s < segs; s++) {
        for (i = 0u; i < v[s].len; i++) {
            if (v[s].base[i] != byte_at(byte_read + total)) {
                byte_bad++;
            }
            total++;
        }
    }
    if (mt_bring_advance(&byte_ring, total) != MT_OK) {
        byte_bad++;
    }
    byte_read += total;
}

static void p_io_beat(void *arg)
{
    (void)arg;
}

/* ---- Semaphores: ISR -> sensor thread <-> ponger thread. -------------- */

static mt_sem_t isr_sem;
static mt_sem_t ping_sem;
static mt_sem_t pong_sem;
static mt_sem_t sensor_done;
static mt_sem_t ponger_done;
static volatile uint32_t stopping;
static volatile uint32_t isr_signals;
static volatile uint32_t isr_taken;
static volatile uint32_t ping_sent;
static volatile uint32_t ping_taken;
static volatile uint32_t pong_sent;
static volatile uint32_t pong_taken;
static volatile uint32_t sem_timeouts;

/* ISR context (virtual-timer callback): kernel lock not held. */
static mt_work_t wq_isr_item;
static volatile uint32_t wq_isr_acts;

static void isr_tick(void *arg)
{
    (void)arg;
    isr_signals++;
    mt_sem_signal_isr(&isr_sem);
    (void)mt_work_schedule_isr(&wq_isr_item); /* a merge is counted by the queue */
    wq_isr_acts++;
}

static void sensor_thread(void *arg)
{
    (void)arg;
    for (;;) {
        if (mt_sem_wait(&isr_sem, SEM_TIMEOUT_US) != MT_OK) {
            if (stopping != 0u) {
                break;
            }
            sem_timeouts++;
            continue;
        }
        isr_taken++;
        ping_sent++;
        mt_sem_signal(&ping_sem);
        if (mt_sem_wait(&pong_sem, SEM_TIMEOUT_US) == MT_OK) {
            pong_taken++;
        } else {
            sem_timeouts++;
        }
    }
    mt_sem_signal(&sensor_done);
}

static void ponger_thread(void *arg)
{
    (void)arg;
    for (;;) {
        if (mt_sem_wait(&ping_sem, SEM_TIMEOUT_US) != MT_OK) {
            if (stopping != 0u) {
                break;
            }
            sem_timeouts++;
            continue;
        }
        ping_taken++;
        pong_sent++;
        mt_sem_signal(&pong_sem);
    }
    mt_sem_signal(&ponger_done);
}

/* ---- Work queue: interval item, ISR-scheduled item, single shot. ------- */

static mt_wq_t wq_smoke;
static mt_chibios_wq_thread_t wq_thread;
static mt_work_t wq_periodic;
static mt_work_t wq_shot;
static uint32_t wq_periodic_runs; /* queue thread */
static uint32_t wq_isr_runs;      /* queue thread */
static uint32_t wq_shot_runs;     /* queue thread */
static mt_status_t wq_shot_status;

static void w_periodic(void *arg)
{
    (void)arg;
    wq_periodic_runs++;
    spin_us(50u);
}

static void w_isr(void *arg)
{
    (void)arg;
    wq_isr_runs++;
}

static void w_shot(void *arg)
{
    (void)arg;
    wq_shot_runs++;
    spin_us(20u);
}

/* ---- Task table. ------------------------------------------------------- */

static work_t w_ins = {40u, 1u};
static work_t w_rate = {30u, 2u};

#if defined(FW_FAIL) && (FW_FAIL == 2)
static void t_fault(void *arg)
{
    static uint32_t calls;

    (void)arg;
    calls++;
    if (calls == 100u) {
        __builtin_trap(); /* undefined instruction: UsageFault -> HardFault */
    }
    spin_us(60u);
}
#define ATT_FN t_fault
#else
#define ATT_FN t_work
#endif

#if defined(FW_FAIL) && (FW_FAIL == 1)
#define HOG_US 1200u
static work_t w_hog[4] = {{HOG_US, 0u}, {HOG_US, 0u}, {HOG_US, 0u}, {HOG_US, 0u}};

static const mt_task_t tasks[] = {
    /* name, body, argument, rate (mHz), budget (us), priority */
    {"ins_update", t_work, &w_ins, 0u, 150u, 0u},
    {"rate_ctrl", t_work, &w_rate, 0u, 150u, 1u},
    {"obj_drain", t_obj_drain, (void *)0, MT_HZ(50), 300u, 3u},
    {"hog_1", t_work, &w_hog[0], MT_HZ(100), HOG_US, 4u},
    {"hog_2", t_work, &w_hog[1], MT_HZ(100), HOG_US, 4u},
    {"hog_3", t_work, &w_hog[2], MT_HZ(100), HOG_US, 4u},
    {"att_ctrl", t_work, &w_hog[3], MT_HZ(250), HOG_US, 5u},
};
#else
static work_t w_att = {60u, 3u};
static work_t w_nav = {120u, 4u};
static work_t w_gcs = {200u, 5u};
static work_t w_log = {400u, 6u};

static const mt_task_t tasks[] = {
    /* name, body, argument, rate (mHz), budget (us), priority */
    {"ins_update", t_work, &w_ins, 0u, 150u, 0u},
    {"rate_ctrl", t_work, &w_rate, 0u, 150u, 1u},
    {"att_ctrl", ATT_FN, &w_att, MT_HZ(250), 200u, 3u},
    {"nav", t_work, &w_nav, MT_HZ(100), 300u, 4u},
    {"obj_drain", t_obj_drain, (void *)0, MT_HZ(50), 300u, 5u},
    {"gcs_send", t_work, &w_gcs, MT_HZ(10), 500u, 6u},
    {"log_1hz", t_work, &w_log, MT_HZ(1), 600u, 7u},
};
#endif

#define NTASKS ((uint32_t)(sizeof(tasks) / sizeof(tasks[0])))

/* ---- Threads, proc sets, scheduler. ------------------------------------ */

static uint64_t timer_stack[128];
static uint64_t io_stack[128];
static uint64_t sensor_stack[96];
static uint64_t ponger_stack[96];
static uint64_t wq_stack[128];

static mt_proc_set_t timer_procs;
static mt_proc_set_t io_procs;
static mt_chibios_proc_thread_t timer_thread;
static mt_chibios_proc_thread_t io_thread;
static mt_chibios_metronome_t metronome;
static mt_sched_t sched;

static void setup(void)
{
    uint32_t bad_index = 0u;
    mt_status_t st;

    check(mt_oring_init(&obj_ring, obj_storage, (uint32_t)sizeof(sample_obj_t), OBJ_CAP) == MT_OK,
          "object ring init");
    check(mt_bring_init(&byte_ring, byte_storage, BYTE_CAP) == MT_OK, "byte ring init");
    mt_sem_init(&isr_sem, false);
    mt_sem_init(&ping_sem, false);
    mt_sem_init(&pong_sem, false);
    mt_sem_init(&sensor_done, false);
    mt_sem_init(&ponger_done, false);

    mt_proc_set_init(&timer_procs);
    mt_proc_set_init(&io_procs);
    check(mt_proc_register(&timer_procs, p_obj_push, (void *)0) == MT_OK, "register obj_push");
    check(mt_proc_register(&timer_procs, p_byte_push, (void *)0) == MT_OK, "register byte_push");
    check(mt_proc_register(&io_procs, p_byte_pull, (void *)0) == MT_OK, "register byte_pull");
    check(mt_proc_register(&io_procs, p_io_beat, (void *)0) == MT_OK, "register io_beat");
    check(mt_proc_register(&io_procs, p_io_beat, (void *)0) == MT_E_DUPLICATE,
          "duplicate proc refused");

    mt_wq_init(&wq_smoke, "wq_smoke", MT_PRIO_CAN, 0);
    mt_work_init(&wq_periodic, w_periodic, (void *)0);
    mt_work_init(&wq_isr_item, w_isr, (void *)0);
    mt_work_init(&wq_shot, w_shot, (void *)0);
    check(mt_wq_attach(&wq_smoke, &wq_periodic) == MT_OK, "attach wq_periodic");
    check(mt_wq_attach(&wq_smoke, &wq_isr_item) == MT_OK, "attach wq_isr");
    check(mt_wq_attach(&wq_smoke, &wq_shot) == MT_OK, "attach wq_shot");
    check(mt_wq_attach(&wq_smoke, &wq_shot) == MT_E_DUPLICATE, "second attach refused");
    check(mt_proc_register(&timer_procs, mt_wq_timer_proc, &wq_smoke) == MT_OK,
          "register wq timer proc");
    check(mt_chibios_wq_start(&wq_thread, &wq_smoke, wq_stack, (uint32_t)sizeof(wq_stack)) ==
              MT_OK,
          "start wq thread");
    wq_shot_status = mt_work_run_wait(&wq_shot, WQ_SHOT_TIMEOUT_US);
    check((wq_shot_status == MT_OK) && (wq_shot_runs == 1u), "wq single shot");

    st = mt_sched_init(&sched, tasks, NTASKS, LOOP_HZ, &bad_index);
    if (st != MT_OK) {
        fw_puts("task table rejected: ");
        fw_puts(mt_status_str(st));
        fw_puts(" at entry ");
        fw_put_u32(bad_index);
        nl();
        fw_exit(FW_EXIT_FAILURE);
    }

    check(mt_port_thread_create("sensor", sensor_thread, (void *)0, sensor_stack,
                                (uint32_t)sizeof(sensor_stack), MT_PRIO_SPI, 0) == MT_OK,
          "create sensor thread");
    check(mt_port_thread_create("ponger", ponger_thread, (void *)0, ponger_stack,
                                (uint32_t)sizeof(ponger_stack), MT_PRIO_I2C, 0) == MT_OK,
          "create ponger thread");
    check(mt_chibios_proc_thread_start(&timer_thread, "timer", &timer_procs, TIMER_PERIOD_US,
                                       timer_stack, (uint32_t)sizeof(timer_stack),
                                       MT_PRIO_TIMER) == MT_OK,
          "start timer thread");
    check(mt_chibios_proc_thread_start(&io_thread, "io", &io_procs, IO_PERIOD_US, io_stack,
                                       (uint32_t)sizeof(io_stack), MT_PRIO_IO) == MT_OK,
          "start io thread");
}

static uint32_t isr_timer_id;

static void run(void)
{
    check(mt_chibios_isr_timer_start(&isr_timer_id, ISR_PERIOD_US, isr_tick, (void *)0) == MT_OK,
          "start ISR timer");
    check(mt_work_schedule_interval(&wq_periodic, WQ_PERIOD_US, 0u) == MT_OK, "wq interval");
    check(mt_chibios_metronome_init(&metronome, LOOP_HZ) == MT_OK, "metronome init");
    while ((metronome.samples + metronome.missed) < RUN_PERIODS) {
        mt_sched_loop_once(&sched, mt_chibios_metronome_wait, &metronome);
    }
}

/* Stop every producer before its consumer, then drain what is left. */
static void shutdown(void)
{
    mt_chibios_isr_timer_stop(isr_timer_id);
    stopping = 1u;
    check(mt_sem_wait(&sensor_done, STOP_TIMEOUT_US) == MT_OK, "sensor thread stopped");
    check(mt_sem_wait(&ponger_done, STOP_TIMEOUT_US) == MT_OK, "ponger thread stopped");
    check(mt_chibios_proc_thread_stop(&timer_thread, STOP_TIMEOUT_US) == MT_OK,
          "timer thread stopped");
    check(mt_chibios_proc_thread_stop(&io_thread, STOP_TIMEOUT_US) == MT_OK, "io thread stopped");
    /* No activation is left to come: stop the queue thread, then run what is queued. */
    check(mt_work_cancel(&wq_periodic) == MT_OK, "wq cancel");
    check(mt_chibios_wq_stop(&wq_thread, STOP_TIMEOUT_US) == MT_OK, "wq thread stopped");
    (void)mt_wq_run_pending(&wq_smoke, 10u);
    /* Both threads have exited: main is now the only consumer. */
    t_obj_drain((void *)0);
    p_byte_pull((void *)0);
}

/* ---- Report. ----------------------------------------------------------- */

static void report_tasks(void)
{
    uint32_t i;
    mt_task_report_t r;

    fw_puts("task        rate_hz   runs expect min_us max_us mean_us overrun slips skips");
    nl();
    for (i = 0u; i < NTASKS; i++) {
        uint64_t expect;
        uint64_t lo;

        mt_sched_task_report(&sched, i, &r);
        expect = (uint64_t)RUN_PERIODS / r.interval;
        lo = (expect > RUN_TOLERANCE) ? (expect - RUN_TOLERANCE) : 0u;
        put_name(r.name, 12u);
        if (tasks[i].rate_mhz == 0u) {
            fw_puts("   fast");
        } else {
            put_col(tasks[i].rate_mhz / 1000u, 7u);
        }
        put_col((uint32_t)r.runs, 7u);
        put_col((uint32_t)expect, 7u);
        put_col(r.min_us, 7u);
        put_col(r.max_us, 7u);
        put_col(r.mean_us, 8u);
        put_col(r.overruns, 8u);
        put_col((uint32_t)r.slips, 6u);
        put_col((uint32_t)r.budget_skips, 6u);
        nl();
        if ((r.runs < lo) || (r.runs > (expect + RUN_TOLERANCE)) || (r.slips != 0u)) {
            check(false, r.name);
        }
    }
}

static void report_loop(void)
{
    mt_loop_report_t l;

    mt_sched_loop_report(&sched, &l);
    fw_puts("loop: ");
    put_u(metronome.samples);
    fw_puts(" samples of ");
    fw_put_u32(metronome.period_us);
    fw_puts(" us, missed ");
    fw_put_u32(metronome.missed);
    fw_puts(", loop min/mean/max ");
    fw_put_u32(l.min_us);
    fw_putc('/');
    fw_put_u32(l.mean_us);
    fw_putc('/');
    fw_put_u32(l.max_us);
    fw_puts(" us, long ");
    fw_put_u32(l.long_loops);
    fw_puts(", extra ");
    fw_put_u32(l.extra_us);
    fw_puts(" us");
    nl();
    fw_puts("load average: ");
    fw_put_u32(l.load_permille / 10u);
    fw_putc('.');
    fw_put_u32(l.load_permille % 10u);
    fw_puts("% (");
    fw_put_u32(l.load_permille);
    fw_puts(" permille), filtered loop ");
    fw_put_u32(l.filtered_us);
    fw_puts(" us");
    nl();
    check(metronome.samples == RUN_PERIODS, "loop: samples");
    check(metronome.missed == 0u, "loop: missed samples");
}

static void report_procs(const char *name, const mt_chibios_proc_thread_t *pt,
                         const char *const *proc_names)
{
    const mt_proc_set_t *p = pt->set;
    uint32_t i;

    fw_puts(name);
    fw_puts(" thread: ");
    fw_put_u32(1000000u / pt->period_us);
    fw_puts(" Hz, rounds ");
    put_u(p->dispatches);
    fw_puts(", missed ");
    fw_put_u32(p->periods_missed);
    fw_puts(", longest round ");
    fw_put_u32(p->max_round_us);
    fw_puts(" us");
    nl();
    for (i = 0u; i < p->count; i++) {
        fw_puts("  proc ");
        put_name(proc_names[i], 10u);
        fw_puts(" calls ");
        fw_put_u32(p->procs[i].calls);
        fw_puts(", max ");
        fw_put_u32(p->procs[i].max_us);
        fw_puts(" us, mean ");
        put_u((p->procs[i].calls == 0u) ? 0u : (p->procs[i].total_us / p->procs[i].calls));
        fw_puts(" us");
        nl();
        check(p->procs[i].calls == p->dispatches, proc_names[i]);
    }
    check(p->periods_missed == 0u, name);
    check(p->refused == 0u, "proc dispatch refused");
}

static void report_rings(void)
{
    fw_puts("objring: pushed ");
    fw_put_u32(obj_pushed);
    fw_puts(" popped ");
    fw_put_u32(obj_popped);
    fw_puts(" lost ");
    fw_put_u32(obj_ring.lost);
    fw_puts(" rejected ");
    fw_put_u32(obj_ring.rejected);
    fw_puts(" bad ");
    fw_put_u32(obj_bad);
    nl();
    fw_puts("bytering: written ");
    fw_put_u32(byte_written);
    fw_puts(" read ");
    fw_put_u32(byte_read);
    fw_puts(" short ");
    fw_put_u32(byte_short);
    fw_puts(" bad ");
    fw_put_u32(byte_bad);
    nl();
    check((obj_pushed == timer_procs.procs[0].calls) && (obj_popped == obj_pushed),
          "objring: every object delivered");
    check((obj_ring.lost == 0u) && (obj_ring.rejected == 0u) && (obj_bad == 0u),
          "objring: none lost, rejected or out of order");
    check((byte_written == byte_read) && (byte_short == 0u) && (byte_bad == 0u),
          "bytering: every byte delivered in order");
}

static void report_sems(void)
{
    fw_puts("sem isr->sensor: signals ");
    fw_put_u32(isr_signals);
    fw_puts(" taken ");
    fw_put_u32(isr_taken);
    fw_puts(" merged ");
    fw_put_u32(isr_sem.merged);
    nl();
    fw_puts("sem sensor->ponger: signals ");
    fw_put_u32(ping_sent);
    fw_puts(" taken ");
    fw_put_u32(ping_taken);
    fw_puts(" merged ");
    fw_put_u32(ping_sem.merged);
    nl();
    fw_puts("sem ponger->sensor: signals ");
    fw_put_u32(pong_sent);
    fw_puts(" taken ");
    fw_put_u32(pong_taken);
    fw_puts(" merged ");
    fw_put_u32(pong_sem.merged);
    fw_puts(", timeouts ");
    fw_put_u32(sem_timeouts);
    nl();
    check((isr_signals == isr_taken) && (isr_sem.merged == 0u) && (isr_signals > 0u),
          "sem: every ISR signal taken");
    check((ping_sent == ping_taken) && (pong_sent == pong_taken) && (pong_taken == isr_taken) &&
              (ping_sem.merged == 0u) && (pong_sem.merged == 0u),
          "sem: every hand-off taken");
    check(sem_timeouts == 0u, "sem: no timeout");
}

static void report_wq(void)
{
    mt_wq_report_t q;
    mt_work_report_t p;
    mt_work_report_t i;
    /* the timer proc ran `calls` times, 1 ms apart; the first call activated the item */
    uint32_t calls = timer_procs.procs[2].calls;
    uint32_t expect = (calls == 0u) ? 0u : ((((calls - 1u) * TIMER_PERIOD_US) / WQ_PERIOD_US) + 1u);

    mt_wq_report(&wq_smoke, &q);
    mt_work_report(&wq_periodic, &p);
    mt_work_report(&wq_isr_item, &i);
    fw_puts("wq ");
    fw_puts(q.name);
    fw_puts(": runs ");
    put_u(q.runs);
    fw_puts(" merged ");
    fw_put_u32(q.merged);
    fw_puts(" missed ");
    fw_put_u32(q.missed);
    fw_puts(" max depth ");
    fw_put_u32(q.max_depth);
    fw_puts(" max latency ");
    fw_put_u32(q.max_latency_us);
    fw_puts(" us");
    nl();
    fw_puts("  periodic: runs ");
    put_u(p.runs);
    fw_puts(" expect ");
    fw_put_u32(expect);
    fw_puts(", interval min/mean/max ");
    fw_put_u32(p.min_interval_us);
    fw_putc('/');
    fw_put_u32(p.mean_interval_us);
    fw_putc('/');
    fw_put_u32(p.max_interval_us);
    fw_puts(" us, run max ");
    fw_put_u32(p.max_run_us);
    fw_puts(" us, rate ");
    fw_put_u32(p.rate_mhz);
    fw_puts(" mHz, missed ");
    fw_put_u32(p.missed);
    fw_puts(" merged ");
    fw_put_u32(p.merged);
    nl();
    fw_puts("  isr: activations ");
    fw_put_u32(wq_isr_acts);
    fw_puts(" runs ");
    put_u(i.runs);
    fw_puts(" merged ");
    fw_put_u32(i.merged);
    fw_puts("; single shot ");
    fw_puts(mt_status_str(wq_shot_status));
    nl();
    check((p.runs + RUN_TOLERANCE >= expect) && (p.runs <= expect + RUN_TOLERANCE) &&
              (p.missed == 0u) && (p.merged == 0u),
          "wq: interval item once per period");
    check((i.runs + i.merged == wq_isr_acts) && (i.runs == wq_isr_runs) && (wq_isr_acts > 0u),
          "wq: every ISR activation run or merged");
    check((q.depth == 0u) && (wq_periodic_runs == (uint32_t)p.runs), "wq: drained");
}

static const char *const timer_proc_names[] = {"obj_push", "byte_push", "wq_timer"};
static const char *const io_proc_names[] = {"byte_pull", "io_beat"};

int main(void)
{
    uint32_t sim_ms;

    fw_board_init();
    mt_chibios_init();
    mt_chibios_set_priority(MT_PRIO_MAIN, 0);

    fw_puts("metronome smoke: ");
    fw_put_u32(NTASKS);
    fw_puts(" tasks, loop ");
    fw_put_u32(LOOP_HZ);
    fw_puts(" Hz for ");
    fw_put_u32(RUN_PERIODS);
    fw_puts(" periods");
#if defined(FW_FAIL)
    fw_puts(" (seeded failure ");
    fw_put_u32(FW_FAIL);
    fw_putc(')');
#endif
    nl();

    setup();
    run();
    shutdown();

    report_tasks();
    report_loop();
    report_procs("timer", &timer_thread, timer_proc_names);
    report_procs("io", &io_thread, io_proc_names);
    report_rings();
    report_sems();
    report_wq();
    sim_ms = (uint32_t)(mt_port_now_us() / 1000u);
    fw_puts("sim time ");
    fw_put_u32(sim_ms);
    fw_puts(" ms");
    nl();
    /* The loop ran RUN_S seconds; the shutdown adds one semaphore timeout. */
    check((sim_ms >= (RUN_S * 1000u)) && (sim_ms <= ((RUN_S * 1000u) + 100u)), "sim time");

    if (failures != 0u) {
        fw_puts("RESULT: FAIL (");
        fw_put_u32(failures);
        fw_puts(" checks)");
        nl();
        fw_exit(FW_EXIT_FAILURE);
    }
    fw_puts("RESULT: PASS");
    nl();
    fw_exit(FW_EXIT_SUCCESS);
}
