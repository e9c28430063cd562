/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file main.c
 * @brief The example vehicle as ChibiOS/RT firmware: the same components and
 *        task table as SITL, on the ChibiOS port, flying the built-in mission
 *        (vehicle/deploy/builtin_mission.c) in the simulated world (QEMU has
 *        no sensors). Prints the flight summary on the UART and exits 0 only
 *        when the mission completed and the checks below hold.
 *
 * Ground-station session (built with FW_GCS=1: make test-vehicle-fw): no mission
 * and no arm request of its own; a ground station on the link UART (MAVLink 2)
 * uploads the mission, arms the vehicle and picks its mode, as with the SITL's
 * --mavlink. The run ends after FW_GCS_LIMIT_S seconds of vehicle time, on a crash,
 * or when 'q' (or Ctrl-C, 0x03) arrives on the console; then the same summary and
 * checks. Exit status as the SITL's: 0 only when a mission completed (and the
 * checks hold).
 *
 * Deployment: main loop (MAIN) on the port's metronome at the table's loop
 * rate, the world stepped in its sample wait; timer thread (TIMER, 1 kHz)
 * with the barometer driver; IO thread (IO, every 2 ms) with the log writer,
 * whose sink checks every record and counts it (no file system), and the
 * console: the main loop's lines go through a byte ring to the IO thread,
 * which writes the polled UART, so a task that prints does not wait for the
 * UART. The MAVLink link: the link UART's receive interrupt fills the link's
 * receive ring (its producer), an IO proc sends the transmit ring (polled;
 * under qemu-smoke QEMU has no backend for that UART and drops what is sent).
 * Task times are real (instruction counts under QEMU -icount), not
 * simulated. Set-up, arm requests, end-of-run rules and the summary are the
 * ones SITL uses (vehicle/deploy/startup.c).
 *
 * Uses only the kernel's public API, the port's services and the board
 * console: no ChibiOS header.
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "builtin_mission.h"
#include "fw_board.h"
#include "fw_link.h"
#include "mt/mt.h"
#include "mt_port_chibios.h"
#include "simplat.h"
#include "startup.h"
#include "veh.h"

/* Seeded failure (make ... FAIL=1): the mission gets a jump to a command that does not
 * exist; the sequencer rejects it, the vehicle never arms, the run must exit non-zero. */
#if defined(FW_FAIL)
#define VEH_FW_FAIL FW_FAIL
#else
#define VEH_FW_FAIL 0
#endif

/* Ground-station session (see above) and its limit in seconds of vehicle time. */
#if defined(FW_GCS)
#define VEH_FW_GCS FW_GCS
#else
#define VEH_FW_GCS 0
#endif
#if defined(FW_GCS_LIMIT_S)
#define VEH_FW_GCS_LIMIT_S FW_GCS_LIMIT_S
#else
#define VEH_FW_GCS_LIMIT_S 1800u
#endif

#define LOOP_HZ 400u
#define LINK_BAUD 115200u
#define LINK_TX_MAX 1024u /* bytes sent per IO period at most */
#define IO_PERIOD_US 2000u
#define STOP_TIMEOUT_US 100000u
#define FLIGHT_TIMEOUT_US 240000000u
#define SETTLE_US 500000u

/* The platform context: the world first (simplat.h). */
typedef struct {
    simplat_t world;
    veh_run_t run; /* boot time, arm requests, end rules (startup.h) */
    /* log sink (IO thread): a streaming check of the record framing */
    uint64_t log_bytes;
    uint32_t log_records;
    uint32_t log_bad;
    uint32_t log_pos; /* bytes of the current record seen */
    uint8_t log_type;
    uint8_t log_len;
    uint8_t log_sum;
    uint64_t telem_bytes;
} fw_t;

static fw_t g;

/* Console: main loop -> byte ring -> IO thread -> UART. */
static uint8_t console_store[4096];
static mt_bring_t console_ring;
static uint32_t console_lost; /* main loop: bytes that did not fit */
static bool console_direct;   /* after the threads stopped: straight to the UART */
static mt_chibios_metronome_t metronome;
static mt_chibios_proc_thread_t timer_thread;
static mt_chibios_proc_thread_t io_thread;
static uint8_t timer_stack[2048] __attribute__((aligned(8)));
static uint8_t io_stack[1024] __attribute__((aligned(8)));
static mt_chibios_wq_thread_t wq_thread; /* the vehicle's work queue (battery monitor) */
static uint8_t wq_stack[1024] __attribute__((aligned(8)));

static void uart_write(const uint8_t *s, uint32_t n)
{
    uint32_t i;
    for (i = 0u; i < n; i++) {
        if (s[i] == (uint8_t)'\n') {
            fw_putc('\r');
        }
        fw_putc((char)s[i]);
    }
}

static void cb_console(void *ctx, const char *s, size_t n)
{
    (void)ctx;
    if (console_direct) {
        uart_write((const uint8_t *)s, (uint32_t)n);
    } else {
        /* zero-copy: reserve, copy into the ring's segments, commit */
        mt_iovec_t vec[2];
        uint32_t segs = mt_bring_reserve(&console_ring, vec, (uint32_t)n);
        uint32_t off = 0u;
        uint32_t i;
        for (i = 0u; i < segs; i++) {
            memcpy(vec[i].base, &s[off], vec[i].len);
            off += vec[i].len;
        }
        (void)mt_bring_commit(&console_ring, off);
        console_lost += (uint32_t)n - off;
    }
}

/* IO proc: the console ring to the UART. */
static void console_drain(void *arg)
{
    mt_iovec_t vec[2];
    uint32_t segs = mt_bring_peek_vec(&console_ring, vec);
    uint32_t n = 0u;
    uint32_t i;

    (void)arg;
    for (i = 0u; i < segs; i++) {
        uart_write(vec[i].base, vec[i].len);
        n += vec[i].len;
    }
    if (n > 0u) {
        (void)mt_bring_advance(&console_ring, n);
    }
}

/* Record: 'M' 'T' type len payload[len] sum (vehicle/src/logger.c). */
static void cb_log_sink(void *ctx, const uint8_t *data, uint32_t n)
{
    fw_t *f = (fw_t *)ctx;
    uint32_t i;

    for (i = 0u; i < n; i++) {
        uint8_t b = data[i];
        if (f->log_pos == 0u) {
            if (b != 0x4Du) {
                f->log_bad++;
                continue;
            }
        } else if (f->log_pos == 1u) {
            if (b != 0x54u) {
                f->log_bad++;
                f->log_pos = 0u;
                continue;
            }
        } else if (f->log_pos == 2u) {
            f->log_type = b;
            f->log_sum = b;
        } else if (f->log_pos == 3u) {
            f->log_len = b;
            f->log_sum = (uint8_t)(f->log_sum + b);
        } else if (f->log_pos < (4u + (uint32_t)f->log_len)) {
            f->log_sum = (uint8_t)(f->log_sum + b);
        } else {
            if (b == f->log_sum) {
                f->log_records++;
            } else {
                f->log_bad++;
            }
            f->log_pos = 0u;
            continue;
        }
        f->log_pos++;
    }
    f->log_bytes += n;
}

/* The MAVLink link's transmit ring to the link UART (IO thread, the ring's only consumer);
 * the bytes sent are counted and checked against what the vehicle sent. */
static void link_drain(void *arg)
{
    (void)arg;
    g.telem_bytes += fw_link_send(veh_link_tx(), LINK_TX_MAX);
}

static veh_gcs_cmd_t cb_gcs_poll(void *ctx)
{
    fw_t *f = (fw_t *)ctx;

    /* with a ground station on the link, it arms the vehicle and picks the mode */
    return f->run.gcs_session ? VEH_GCS_NONE : veh_run_arm_poll(&f->run);
}

/* The console asks the session to end: 'q' or Ctrl-C (main loop, polled). */
static bool console_stop(void)
{
    int ch;

    while ((ch = fw_console_getc()) >= 0) {
        if ((ch == (int)'q') || (ch == 0x03)) {
            return true;
        }
    }
    return false;
}

/* Every task kept within its budget and met every release (the costs and budgets of
 * tasks.def are measured here: this holds them to it). */
static bool no_overrun_no_slip(void)
{
    const mt_sched_t *sc = veh_sched();
    uint32_t i;
    bool ok = true;

    for (i = 0u; i < sc->ntasks; i++) {
        mt_task_report_t r;
        mt_sched_task_report(sc, i, &r);
        if ((r.overruns != 0u) || (r.slips != 0u)) {
            ok = false;
        }
    }
    return ok;
}

static uint32_t failures;
static mt_mission_cmd_t bad_mission[16];

static void check(bool ok, const char *what)
{
    if (!ok) {
        failures++;
        veh_printf("CHECK FAILED: %s\n", what);
    }
}

int main(void)
{
    veh_platform_t plat = {0};
    veh_home_t home;
    uint32_t bad = 0u;
    uint32_t period_us;
    uint32_t cmin;
    uint32_t cmax;
    mt_status_t st;
    const veh_counters_t *c;
    fw_link_counters_t lc;

    fw_board_init();
    mt_chibios_init();
    mt_chibios_set_priority(MT_PRIO_MAIN, 0);
    (void)mt_bring_init(&console_ring, console_store, (uint32_t)sizeof(console_store));

    veh_run_home(&home, &veh_builtin_mission[0]);
    if (mt_chibios_metronome_init(&metronome, LOOP_HZ) != MT_OK) {
        fw_puts("metronome init failed\r\n");
        fw_exit(FW_EXIT_FAILURE);
    }
    simplat_init(&g.world, &home, 1u, mt_chibios_metronome_wait, &metronome);
    /* veh_run_start adds the world's callbacks (plat.ctx: the world, first member of g) */
    plat.console = cb_console;
    plat.log_sink = cb_log_sink;
    plat.gcs_poll = cb_gcs_poll;
    plat.task_work = NULL;                 /* real execution time */
    plat.status_lines = (VEH_FW_GCS == 0); /* a session: as the SITL's tests run it (--quiet) */
    g.run.timeout_us = FLIGHT_TIMEOUT_US;
    g.run.settle_us = SETTLE_US;
    g.run.max_ticks = 0u;

    if (VEH_FW_GCS != 0) {
        g.run.timeout_us = (uint64_t)VEH_FW_GCS_LIMIT_S * 1000000u;
        g.run.gcs_session = true;
        st = veh_run_start(&g.run, &plat, &g.world, &home, veh_builtin_mission, 0u, &bad);
    } else if (VEH_FW_FAIL == 1) {
        uint16_t i;
        for (i = 0u; (i < veh_builtin_mission_len) && (i < 15u); i++) {
            bad_mission[i] = veh_builtin_mission[i];
        }
        bad_mission[i].id = MT_MAV_CMD_DO_JUMP; /* to command 99 of at most 16 */
        bad_mission[i].frame = 2u;
        bad_mission[i].options = 1u;
        bad_mission[i].param[0] = 99 * MT_MISSION_MILLI;
        bad_mission[i].param[1] = 1 * MT_MISSION_MILLI;
        st = veh_run_start(&g.run, &plat, &g.world, &home, bad_mission, (uint16_t)(i + 1u), &bad);
    } else {
        st = veh_run_start(&g.run, &plat, &g.world, &home, veh_builtin_mission,
                           veh_builtin_mission_len, &bad);
    }
    if (VEH_FW_GCS != 0) {
        veh_printf(
            "metronome firmware: ChibiOS/RT, loop %u Hz, %u tasks, ground-station session: "
            "MAVLink 2 on the link UART, no mission, up to %u s (q on the console ends it)\n",
            (unsigned)veh_sched()->loop_rate_hz, (unsigned)veh_sched()->ntasks,
            (unsigned)VEH_FW_GCS_LIMIT_S);
    } else {
        veh_printf("metronome firmware: ChibiOS/RT, loop %u Hz, %u tasks, built-in mission of %u "
                   "items\n",
                   (unsigned)veh_sched()->loop_rate_hz, (unsigned)veh_sched()->ntasks,
                   (unsigned)veh_builtin_mission_len);
    }
    if ((st != MT_OK) && (veh_sched()->ntasks == 0u)) {
        veh_printf("task table rejected: %s at entry %u\n", mt_status_str(st), (unsigned)bad);
        fw_exit(FW_EXIT_FAILURE);
    }
    (void)veh_run_rejected(st, bad);
    veh_timer_spec(&period_us, &cmin, &cmax);
    /* the link's rings exist now (veh_init): the receive interrupt may fill one */
    fw_link_start(veh_link_rx(), LINK_BAUD);
    if (VEH_FW_GCS != 0) {
        fw_console_rx_start();
    }
    if ((mt_proc_register(veh_io_procs(), console_drain, NULL) != MT_OK) ||
        (mt_proc_register(veh_io_procs(), link_drain, NULL) != MT_OK) ||
        (mt_chibios_proc_thread_start(&timer_thread, "timer", veh_timer_procs(), period_us,
                                      timer_stack, (uint32_t)sizeof(timer_stack),
                                      MT_PRIO_TIMER) != MT_OK) ||
        (mt_chibios_proc_thread_start(&io_thread, "io", veh_io_procs(), IO_PERIOD_US, io_stack,
                                      (uint32_t)sizeof(io_stack), MT_PRIO_IO) != MT_OK) ||
        (mt_chibios_wq_start(&wq_thread, veh_work_queue(), wq_stack, (uint32_t)sizeof(wq_stack)) !=
         MT_OK)) {
        veh_printf("proc and work-queue threads could not start\n");
        fw_exit(FW_EXIT_FAILURE);
    }

    do {
        veh_loop_once(simplat_wait, &g.world);
        if ((VEH_FW_GCS != 0) && console_stop()) {
            g.run.reason = "interrupted (console)";
            break;
        }
    } while (veh_run_after_tick(&g.run, &g.world));
    fw_link_stop(); /* no more bytes in: the counts below are final */
    check(mt_chibios_proc_thread_stop(&timer_thread, STOP_TIMEOUT_US) == MT_OK,
          "timer thread stopped");
    check(mt_chibios_proc_thread_stop(&io_thread, STOP_TIMEOUT_US) == MT_OK, "io thread stopped");
    check(mt_chibios_wq_stop(&wq_thread, STOP_TIMEOUT_US) == MT_OK, "work-queue thread stopped");
    /* the threads have exited: main is now the only consumer of the log and the console */
    veh_run_drain();
    console_direct = true;

    veh_run_summary(&g.run, &g.world);
    c = veh_counters();
    fw_link_counters(&lc);
    veh_printf("link UART: %llu bytes received, %u dropped (receive ring full), %u overruns, %u "
               "interrupts; %llu bytes sent, %u sends stopped at a full transmitter\n",
               (unsigned long long)lc.rx_bytes, (unsigned)lc.rx_dropped, (unsigned)lc.rx_overruns,
               (unsigned)lc.rx_irqs, (unsigned long long)lc.tx_bytes, (unsigned)lc.tx_busy);
    veh_printf("log sink: %llu bytes, %u records checked, %u bad; metronome: %llu samples, %u "
               "missed; timer round max %u us; console: %u bytes lost\n",
               (unsigned long long)g.log_bytes, (unsigned)g.log_records, (unsigned)g.log_bad,
               (unsigned long long)metronome.samples, (unsigned)metronome.missed,
               (unsigned)veh_timer_procs()->max_round_us, (unsigned)console_lost);
    if (VEH_FW_GCS == 0) {
        check(veh_phase() == VEH_PHASE_DONE, "mission complete");
    }
    if (VEH_FW_GCS == 0) {
        check(no_overrun_no_slip(), "no task overran its budget or slipped (tasks.def is honest)");
    } else if (!no_overrun_no_slip()) {
        /* tasks.def's costs were measured without a ground station: the link UART's receive
         * interrupt (one per byte) can fall into a task on top of a timer round */
        veh_printf("note: overruns or slips in a session, not checked: the link's receive "
                   "interrupts (%u) are not in tasks.def's costs\n",
                   (unsigned)lc.rx_irqs);
    }
    check(g.world.collisions == 0u, "no bus collision");
    check((g.log_bad == 0u) && (g.log_records == c->log_records) && (c->log_dropped == 0u),
          "every log record reached the sink intact");
    check(g.log_bytes == c->log_bytes, "log bytes");
    check(c->baro_bus_fail == 0u, "barometer reads");
    check(console_lost == 0u, "console");
    check((g.telem_bytes == c->telem_bytes) && (c->telem_full == 0u),
          "every MAVLink byte left the link's ring");
    check((lc.tx_bytes == g.telem_bytes) && (lc.rx_dropped == 0u) && (lc.rx_overruns == 0u) &&
              (lc.rx_bytes == c->link_rx_bytes + mt_bring_available(veh_link_rx())),
          "every byte received reached the vehicle, every byte sent the link UART");
    if (failures != 0u) {
        veh_printf("RESULT: FAIL (%u checks)\n", (unsigned)failures);
        fw_exit(FW_EXIT_FAILURE);
    }
    if ((VEH_FW_GCS != 0) && (veh_phase() != VEH_PHASE_DONE)) {
        veh_printf("RESULT: no mission completed (the checks held)\n");
        fw_exit(FW_EXIT_FAILURE);
    }
    veh_printf("RESULT: PASS\n");
    fw_exit(FW_EXIT_SUCCESS);
}
