/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file main.c
 * @brief SITL: the vehicle on the host port (hal_posix) in the simulated world.
 *
 *   metronome-sitl [options] [MISSION.waypoints | MISSION.plan]
 *     --builtin          fly the firmware's built-in mission instead of a file
 *     --realtime         wall-clock time on real threads (timer thread 1 kHz, IO
 *                        thread, work-queue thread, main loop on the port's metronome)
 *     --seed N           noise and task-cost seed (default 1)
 *     --timeout S        give up after S seconds (default 600)
 *     --ticks N          stop after N scheduler ticks (schedulability runs)
 *     --log FILE         write the binary log to FILE
 *     --event T:ACTION   ground-station command at T seconds: stop, resume, land
 *     --overrun TASK:US[:START[:DURATION]]
 *                        fault injection: every run of TASK takes US us more than
 *                        its cost (from START s for DURATION s; default: always)
 *     --wind N,E         constant wind, m/s
 *     --quiet            no 1 Hz status lines
 *     --mavlink udp:ADDR:PORT
 *                        MAVLink 2 ground-station link over UDP: sends to ADDR:PORT (a ground
 *                        station listening there: QGroundControl and MAVProxy listen on 14550)
 *                        and answers whoever sends to it; the ground station arms the vehicle
 *                        and picks its mode (no arm requests of our own); only a crash or the
 *                        timeout end the run (Ctrl-C: the summary)
 *     --signing-key HEX  MAVLink 2 signing with this 32-byte key (64 hex digits; MAVProxy's
 *                        `signing setup PASSPHRASE` uses SHA-256 of the passphrase): frames sent
 *                        are signed, frames received unsigned are dropped (counted)
 *     --speedup N        simulated time paced at N x the wall clock (default with --mavlink: 1;
 *                        without: as fast as possible)
 *     --trace FILE       simulated time: one line per event for the first --ticks (or all)
 *                        ticks: "S t" sample, "R due cost" timer round, "E task cost"
 *                        task run, "K tick end runmask skipmask" end of the scan
 *                        (tests/vehicle: the Z3 encoding against the kernel's decisions)
 *     --timeline FILE    simulated time: a Chrome trace-event JSON file, one track per thread
 *                        (main loop: ticks, task runs, slips, overruns, budget skips; timer
 *                        and IO proc dispatches; work items), for Perfetto's UI or
 *                        chrome://tracing (timeline.h)
 *
 * Simulated time (default): one thread; time moves only when a task spends its
 * simulated cost (a pseudo-random time in the range of tasks.def, mostly near its low
 * end), when the timer procs run (1 kHz, pre-empting the
 * task that is running: their cost extends its wall time) or when the loop
 * waits for the next sample (idle: timer and IO procs and the work queue's pending items,
 * the battery monitor, run there). Runs are
 * deterministic and faster than real time.
 *
 * Exit status: 0 mission complete (or --ticks reached), 1 not complete
 * (rejected mission, never armed, crash, timeout), 2 usage or I/O error.
 */
#define _GNU_SOURCE
#include <arpa/inet.h>
#include <math.h>
#include <netinet/in.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <time.h>
#include <unistd.h>

#include "builtin_mission.h"
#include "mt/mt.h"
#include "mt_posix.h"
#include "report.h"
#include "simplat.h"
#include "startup.h"
#include "timeline.h"
#include "veh.h"
#include "wpl.h"

#define SIM_START_US 1000000u
#define MAX_EVENTS 16
#define SETTLE_US 1000000u /* run on after the end for the log to drain */

typedef struct {
    uint64_t t_us;
    veh_gcs_cmd_t cmd;
} sitl_event_t;

/* The platform context: the world first (simplat.h). */
typedef struct {
    simplat_t world;
    bool sim;
    FILE *log;
    uint64_t log_written;
    bool log_error;
    /* the ground-station link (--mavlink) */
    int link_fd;              /* UDP socket, -1: none (the link's bytes are discarded) */
    struct sockaddr_in gcs;   /* where the link sends: --mavlink's address, then the last sender */
    uint64_t link_rx_bytes;   /* into the vehicle's receive ring */
    uint32_t link_rx_dropped; /* datagrams that did not fit (the receive ring, or 2 KB) */
    uint32_t link_sock_dropped; /* datagrams the kernel dropped, the socket's buffer full */
    uint64_t link_tx_bytes;     /* out of the vehicle's transmit ring */
    uint32_t link_tx_errors;    /* datagrams sendto refused (nobody listening, ...) */
    double speedup;             /* simulated time at speedup x the wall clock; 0: free-running */
    bool signing;               /* --signing-key given */
    uint8_t key[32];
    /* simulated time */
    uint64_t next_sample;
    uint32_t period_us;
    uint64_t next_timer;
    uint32_t timer_period;
    uint32_t timer_cmin;
    uint32_t timer_cmax;
    uint64_t rng;
    /* real time */
    mt_posix_metronome_t met;
    /* the run (startup.h): boot time, arm requests, end rules */
    veh_run_t run;
    /* ground station events */
    sitl_event_t ev[MAX_EVENTS];
    int nev;
    int next_ev;
    /* trace */
    FILE *trace;
    /* fault injection */
    int overrun_task;
    uint32_t overrun_us;
    uint64_t overrun_from_us;
    uint64_t overrun_to_us;
    uint64_t overrun_runs;
} sitl_t;

static sitl_t g;

/* ---- console and sinks ------------------------------------------------------------------- */

static void cb_console(void *ctx, const char *s, size_t n)
{
    (void)ctx;
    (void)fwrite(s, 1u, n, stdout);
}

static void cb_log_sink(void *ctx, const uint8_t *data, uint32_t n)
{
    sitl_t *s = (sitl_t *)ctx;
    if (s->log != NULL) {
        if (fwrite(data, 1u, n, s->log) != n) {
            s->log_error = true;
        }
    }
    s->log_written += n;
}

/* ---- ground-station link: UDP <-> the vehicle's byte rings (main-loop thread) ------------- */

static volatile sig_atomic_t g_interrupted;

static void on_signal(int sig)
{
    (void)sig;
    g_interrupted = 1;
}

/* "udp:ADDR:PORT" -> a non-blocking UDP socket that sends there. */
static bool link_open(sitl_t *s, const char *spec)
{
    char addr[64];
    const char *colon;
    char *end = NULL;
    unsigned long port;
    struct sockaddr_in any;
    const int one = 1;

    if (strncmp(spec, "udp:", 4u) != 0) {
        return false;
    }
    spec += 4;
    colon = strrchr(spec, ':');
    if ((colon == NULL) || ((size_t)(colon - spec) >= sizeof(addr))) {
        return false;
    }
    memcpy(addr, spec, (size_t)(colon - spec));
    addr[colon - spec] = '\0';
    port = strtoul(colon + 1, &end, 10);
    if ((end == colon + 1) || (*end != '\0') || (port == 0u) || (port > 65535u)) {
        return false;
    }
    memset(&s->gcs, 0, sizeof(s->gcs));
    s->gcs.sin_family = AF_INET;
    s->gcs.sin_port = htons((uint16_t)port);
    if (inet_pton(AF_INET, addr, &s->gcs.sin_addr) != 1) {
        return false;
    }
    s->link_fd = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK, 0);
    memset(&any, 0, sizeof(any));
    any.sin_family = AF_INET;
    if ((s->link_fd < 0) || (bind(s->link_fd, (struct sockaddr *)&any, sizeof(any)) != 0)) {
        fprintf(stderr, "sitl: cannot open a UDP socket for --mavlink\n");
        exit(2);
    }
    /* the kernel's count of datagrams it dropped at this socket comes with each one received */
    if (setsockopt(s->link_fd, SOL_SOCKET, SO_RXQ_OVFL, &one, sizeof(one)) != 0) {
        fprintf(stderr, "sitl: cannot count the UDP socket's drops (SO_RXQ_OVFL)\n");
        exit(2);
    }
    return true;
}

/* The kernel's drop count (cumulative, SO_RXQ_OVFL) if the datagram just received carries it. */
static void note_sock_drops(sitl_t *s, struct msghdr *msg)
{
    struct cmsghdr *c;

    for (c = CMSG_FIRSTHDR(msg); c != NULL; c = CMSG_NXTHDR(msg, c)) {
        if ((c->cmsg_level == SOL_SOCKET) && (c->cmsg_type == SO_RXQ_OVFL)) {
            uint32_t d;
            memcpy(&d, CMSG_DATA(c), sizeof(d));
            if (d > s->link_sock_dropped) {
                s->link_sock_dropped = d;
            }
        }
    }
}

/* Datagrams in (whole, or dropped and counted when the ring cannot take them), the transmit
 * ring out. Without a socket the transmit ring is drained and its bytes only counted. */
static void link_pump(sitl_t *s)
{
    mt_bring_t *rx = veh_link_rx();
    mt_bring_t *tx = veh_link_tx();
    uint8_t buf[2048];
    uint32_t n;

    while (s->link_fd >= 0) {
        struct sockaddr_in from;
        struct iovec iov = {buf, sizeof(buf)};
        union {
            char b[CMSG_SPACE(sizeof(uint32_t))];
            struct cmsghdr align;
        } ctl;
        struct msghdr msg;
        memset(&msg, 0, sizeof(msg));
        msg.msg_name = &from;
        msg.msg_namelen = sizeof(from);
        msg.msg_iov = &iov;
        msg.msg_iovlen = 1;
        msg.msg_control = ctl.b;
        msg.msg_controllen = sizeof(ctl.b);
        /* MSG_TRUNC: the datagram's real length, so one larger than buf is seen (and dropped) */
        ssize_t got = recvmsg(s->link_fd, &msg, MSG_TRUNC);
        if (got <= 0) {
            break;
        }
        note_sock_drops(s, &msg);
        s->gcs = from; /* answer whoever talks to the vehicle */
        if (((size_t)got > sizeof(buf)) || (mt_bring_space(rx) < (uint32_t)got)) {
            s->link_rx_dropped++;
            continue;
        }
        (void)mt_bring_write(rx, buf, (uint32_t)got);
        s->link_rx_bytes += (uint64_t)got;
    }
    while ((n = mt_bring_read(tx, buf, (uint32_t)sizeof(buf))) > 0u) {
        if ((s->link_fd >= 0) && (sendto(s->link_fd, buf, n, 0, (struct sockaddr *)&s->gcs,
                                         sizeof(s->gcs)) != (ssize_t)n)) {
            s->link_tx_errors++;
        }
        s->link_tx_bytes += n;
    }
}

/* A 32-byte key from 64 hex digits. */
static bool parse_key(const char *hex, uint8_t key[32])
{
    size_t i;

    if (strlen(hex) != 64u) {
        return false;
    }
    for (i = 0u; i < 32u; i++) {
        unsigned v;
        if (sscanf(&hex[2u * i], "%2x", &v) != 1) {
            return false;
        }
        key[i] = (uint8_t)v;
    }
    return true;
}

/* Simulated time no faster than speedup x the wall clock since w0. */
static void pace(const sitl_t *s, double w0, double (*wall)(void))
{
    double ahead = w0 + ((double)(mt_port_now_us() - s->run.boot_us) * 1e-6 / s->speedup) - wall();

    if (ahead > 0.0) {
        struct timespec ts;
        ts.tv_sec = (time_t)ahead;
        ts.tv_nsec = (long)((ahead - (double)ts.tv_sec) * 1e9);
        (void)nanosleep(&ts, NULL);
    }
}

static veh_gcs_cmd_t cb_gcs_poll(void *ctx)
{
    sitl_t *s = (sitl_t *)ctx;
    uint64_t now = mt_port_now_us();

    if ((s->next_ev < s->nev) && (now >= s->run.boot_us + s->ev[s->next_ev].t_us)) {
        return s->ev[s->next_ev++].cmd;
    }
    /* with a ground station on MAVLink, it arms the vehicle and picks the mode */
    return s->run.gcs_session ? VEH_GCS_NONE : veh_run_arm_poll(&s->run);
}

/* ---- simulated time ------------------------------------------------------------------------- */

static uint64_t rng_next(sitl_t *s)
{
    uint64_t x = s->rng;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    s->rng = x;
    return x * 0x2545F4914F6CDD1Dull;
}

/* A simulated execution time in [lo, hi]: lo + (hi - lo) u^3, u uniform in [0, 1], so most
 * runs take about their typical time and a few come close to the worst case (tasks.def
 * gives the range measured on the target; the schedulability check covers all of it). */
static uint32_t cost(sitl_t *s, uint32_t lo, uint32_t hi)
{
    uint64_t u = rng_next(s) >> 54; /* 0 .. 1023 */
    return lo + (uint32_t)(((uint64_t)(hi - lo) * u * u * u + (1023u * 1023u * 1023u / 2u)) /
                           (1023u * 1023u * 1023u));
}

static void sim_set_at_least(uint64_t t)
{
    uint64_t now = mt_port_now_us();
    if (t > now) {
        mt_posix_sim_advance(t - now);
    }
}

/* The timer thread's round: all timer procs, then their cost. */
static void timer_round(sitl_t *s)
{
    uint64_t t0 = mt_port_now_us();
    uint32_t c;
    (void)mt_proc_dispatch(veh_timer_procs());
    c = cost(s, s->timer_cmin, s->timer_cmax);
    mt_posix_sim_advance(c);
    tl_slice(TL_TIMER, "timer procs", t0, mt_port_now_us() - t0, "procs", veh_timer_procs()->count);
    if (s->trace != NULL) {
        fprintf(s->trace, "R %llu %u\n", (unsigned long long)s->next_timer, (unsigned)c);
    }
    s->next_timer += s->timer_period;
}

/* A task spends us of simulated time; a timer round that falls due meanwhile
 * pre-empts it (its cost extends the task's wall time). */
static void sim_spend(sitl_t *s, uint64_t us)
{
    while (us > 0u) {
        uint64_t now = mt_port_now_us();
        uint64_t step;
        if (now >= s->next_timer) {
            timer_round(s);
            continue;
        }
        step = s->next_timer - now;
        if (step > us) {
            step = us;
        }
        mt_posix_sim_advance(step);
        us -= step;
    }
}

static void cb_task_work(void *ctx, uint32_t task, uint32_t cmin, uint32_t cmax)
{
    sitl_t *s = (sitl_t *)ctx;
    uint64_t us = cost(s, cmin, cmax);

    if ((int)task == s->overrun_task) {
        uint64_t t = mt_port_now_us() - s->run.boot_us;
        if ((t >= s->overrun_from_us) && (t < s->overrun_to_us)) {
            us += s->overrun_us;
            s->overrun_runs++;
        }
    }
    if (s->trace != NULL) {
        fprintf(s->trace, "E %u %llu\n", (unsigned)task, (unsigned long long)us);
    }
    tl_task_begin(veh_sched());
    sim_spend(s, us);
    tl_task_end(veh_sched(), mt_port_now_us());
}

/* The IO procs and the work queue's pending items, run in the loop's idle time. */
static void sim_idle(void)
{
    mt_wq_t *q = veh_work_queue();
    uint64_t t0 = mt_port_now_us();

    (void)mt_proc_dispatch(veh_io_procs());
    tl_slice(TL_IO, "io procs", t0, mt_port_now_us() - t0, "procs", veh_io_procs()->count);
    tl_work_begin(q);
    t0 = mt_port_now_us();
    (void)mt_wq_run_pending(q, MT_CFG_WQ_MAX_ITEMS);
    tl_work_end(q, t0, mt_port_now_us(), veh_work_item_name);
}

/* The main loop's sample wait in simulated time: the port metronome's grid (a late
 * loop skips to the next boundary); until the sample the loop is idle, so the timer
 * rounds due before it and the IO procs run there. */
static uint64_t sim_wait(void *ctx)
{
    sitl_t *s = (sitl_t *)ctx;
    uint64_t now = mt_port_now_us();
    uint64_t next;

    if (s->next_sample == 0u) {
        next = now + s->period_us;
    } else {
        next = s->next_sample + s->period_us;
        if (next < now) {
            next += ((now - next) + s->period_us - 1u) / s->period_us * s->period_us;
        }
    }
    while (s->next_timer < next) {
        sim_set_at_least(s->next_timer);
        sim_idle();
        timer_round(s);
    }
    sim_set_at_least(next);
    s->next_sample = next;
    tl_tick_begin(veh_sched(), next);
    if (s->trace != NULL) {
        fprintf(s->trace, "S %llu\n", (unsigned long long)next);
    }
    return next;
}

/* ---- trace: what the scheduler decided in each tick ------------------------------------- */

static uint64_t g_runs[MT_CFG_SCHED_MAX_TASKS];
static uint64_t g_skips[MT_CFG_SCHED_MAX_TASKS];

static void trace_tick_begin(void)
{
    const mt_sched_t *sc = veh_sched();
    uint32_t i;
    for (i = 0u; i < sc->ntasks; i++) {
        mt_task_report_t r;
        mt_sched_task_report(sc, i, &r);
        g_runs[i] = r.runs;
        g_skips[i] = r.budget_skips;
    }
}

static void trace_tick_end(uint64_t max_ticks)
{
    const mt_sched_t *sc = veh_sched();
    uint64_t run = 0u;
    uint64_t skip = 0u;
    uint32_t i;

    for (i = 0u; i < sc->ntasks; i++) {
        mt_task_report_t r;
        mt_sched_task_report(sc, i, &r);
        if (r.runs != g_runs[i]) {
            run |= 1ull << i;
        }
        if (r.budget_skips != g_skips[i]) {
            skip |= 1ull << i;
        }
    }
    fprintf(g.trace, "K %llu %llu %llx %llx\n", (unsigned long long)sc->tick,
            (unsigned long long)mt_port_now_us(), (unsigned long long)run,
            (unsigned long long)skip);
    if ((max_ticks != 0u) && (sc->tick >= max_ticks)) {
        fclose(g.trace);
        g.trace = NULL;
    }
}

/* ---- mission file ------------------------------------------------------------------------ */

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long n;

    if (f == NULL) {
        return NULL;
    }
    if ((fseek(f, 0, SEEK_END) != 0) || ((n = ftell(f)) < 0) || (fseek(f, 0, SEEK_SET) != 0) ||
        (n > (16L << 20))) {
        fclose(f);
        return NULL;
    }
    buf = malloc((size_t)n + 1u);
    if ((buf == NULL) || (fread(buf, 1u, (size_t)n, f) != (size_t)n)) {
        free(buf);
        fclose(f);
        return NULL;
    }
    fclose(f);
    buf[n] = '\0';
    *len = (size_t)n;
    return buf;
}

/* Read and validate a mission file (QGC WPL 110 or QGroundControl .plan: by the extension, else
 * by the content). Returns the number of commands (0: rejected, with the
 * reasons printed), -1 on an I/O error. */
static int load_file(const char *path, mt_mission_cmd_t *cmds, veh_home_t *home)
{
    size_t len = 0u;
    char *text = slurp(path, &len);
    mt_report_t *rep = calloc(1u, sizeof(*rep));
    mt_plan_step_t plan[1];
    mt_wpl_item_t *items = calloc(MT_CFG_MISSION_MAX_CMDS, sizeof(*items));
    mt_wpl_error_t e;
    mt_mfile_format_t fmt;
    mt_status_t st;
    size_t n = 0u;
    size_t i;
    int result = 0;

    if ((text == NULL) || (rep == NULL) || (items == NULL)) {
        fprintf(stderr, "sitl: cannot read mission file %s\n", path);
        free(text);
        free(rep);
        free(items);
        return -1;
    }
    fmt = mt_mfile_format_of_path(path);
    st = mt_report_check_as(fmt, text, len, plan, 1u, rep);
    for (i = 0u; i < rep->warnings.n; i++) {
        const mt_wpl_error_t *w = &rep->warnings.w[i];
        printf("mission file warning: %s:", path);
        if (w->line != 0u) {
            printf("%u:", (unsigned)w->line);
        }
        printf(" %s\n", w->reason);
    }
    if (st != MT_OK) {
        printf("mission file rejected: %s\n", path);
        for (i = 0u; i < rep->nerr; i++) {
            const mt_wpl_error_t *x = &rep->errors[i];
            char where[MT_WPL_WHERE_MAX];

            printf("  %s %s (%s)\n", mt_wpl_where(where, sizeof where, path, x), x->reason,
                   mt_status_str(x->st));
        }
    } else if (mt_mfile_parse(fmt, text, len, items, MT_CFG_MISSION_MAX_CMDS, &n, &e, NULL) ==
               MT_OK) {
        result = (int)n;
        for (i = 0u; i < n; i++) {
            if (mt_wpl_to_cmd(&items[i], &cmds[i], &e) != MT_OK) {
                printf("mission file rejected: %s:%u: %s\n", path, (unsigned)items[i].line,
                       e.reason);
                result = 0;
                break;
            }
        }
        if ((result > 0) && (cmds[0].x != 0 || cmds[0].y != 0)) {
            veh_run_home(home, &cmds[0]);
        }
    } else {
        printf("mission file rejected: %s:%u: %s\n", path, (unsigned)e.line, e.reason);
    }
    free(text);
    free(rep);
    free(items);
    return result;
}

/* ---- options ----------------------------------------------------------------------------- */

static int usage(void)
{
    fprintf(stderr,
            "usage: metronome-sitl [--builtin] [--realtime] [--seed N] [--timeout S] [--ticks N]\n"
            "                      [--log FILE] [--event T:stop|resume|land]...\n"
            "                      [--overrun TASK:US[:START[:DURATION]]] [--wind N,E] [--quiet]\n"
            "                      [--trace FILE] [--timeline FILE] [--mavlink udp:ADDR:PORT]\n"
            "                      [--speedup N]\n"
            "                      [--signing-key HEX64]\n"
            "                      [MISSION.waypoints | MISSION.plan]\n");
    return 2;
}

static bool parse_event(const char *a)
{
    char *end = NULL;
    double t = strtod(a, &end);
    veh_gcs_cmd_t c;

    if ((end == a) || (*end != ':') || (t < 0.0) || (g.nev >= MAX_EVENTS)) {
        return false;
    }
    end++;
    if (strcmp(end, "stop") == 0) {
        c = VEH_GCS_STOP;
    } else if (strcmp(end, "resume") == 0) {
        c = VEH_GCS_RESUME;
    } else if (strcmp(end, "land") == 0) {
        c = VEH_GCS_LAND;
    } else {
        return false;
    }
    /* keep the list sorted by time */
    {
        int i = g.nev;
        uint64_t us = (uint64_t)(t * 1e6);
        while ((i > 0) && (g.ev[i - 1].t_us > us)) {
            g.ev[i] = g.ev[i - 1];
            i--;
        }
        g.ev[i].t_us = us;
        g.ev[i].cmd = c;
        g.nev++;
    }
    return true;
}

static char g_overrun_name[64];

static bool parse_overrun(const char *a)
{
    const char *colon = strchr(a, ':');
    char *end = NULL;
    double from = 0.0;
    double dur = 1e9;
    unsigned long us;

    if ((colon == NULL) || ((size_t)(colon - a) >= sizeof(g_overrun_name))) {
        return false;
    }
    memcpy(g_overrun_name, a, (size_t)(colon - a));
    g_overrun_name[colon - a] = '\0';
    us = strtoul(colon + 1, &end, 10);
    if ((end == colon + 1) || (us > 1000000ul)) {
        return false;
    }
    if (*end == ':') {
        const char *p = end + 1;
        from = strtod(p, &end);
        if (end == p) {
            return false;
        }
        if (*end == ':') {
            p = end + 1;
            dur = strtod(p, &end);
            if (end == p) {
                return false;
            }
        }
    }
    if (*end != '\0') {
        return false;
    }
    g.overrun_us = (uint32_t)us;
    g.overrun_from_us = (uint64_t)(from * 1e6);
    g.overrun_to_us = g.overrun_from_us + (uint64_t)(dur * 1e6);
    return true;
}

/* --timeout S in us: now > this exactly when now > S * 1e6 (now is whole microseconds). */
static uint64_t run_timeout_us(double s)
{
    double us = s * 1e6;

    if (isnan(us)) {
        return UINT64_MAX; /* NaN: never */
    }
    if (!(us > 0.0)) {
        return 0u;
    }
    if (us >= 1.8e19) {
        return UINT64_MAX;
    }
    return (uint64_t)us;
}

static double wall_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ((double)ts.tv_nsec * 1e-9);
}

int main(int argc, char **argv)
{
    static mt_mission_cmd_t cmds[MT_CFG_MISSION_MAX_CMDS];
    const char *mission_path = NULL;
    const char *log_path = NULL;
    const char *trace_path = NULL;
    const char *timeline_path = NULL;
    bool builtin = false;
    bool quiet = false;
    uint64_t seed = 1u;
    double timeout_s = 600.0;
    uint64_t max_ticks = 0u;
    double wind_n = 0.0;
    double wind_e = 0.0;
    veh_home_t home = {465197000, 65657000, 40000};
    veh_platform_t plat;
    int ncmds = 0;
    uint32_t bad = 0u;
    mt_status_t st;
    mt_posix_proc_thread_t timer_thr;
    mt_posix_proc_thread_t io_thr;
    mt_posix_wq_thread_t wq_thr;
    double w0;
    int rc;
    int i;

    memset(&g, 0, sizeof(g));
    g.sim = true;
    g.overrun_task = -1;
    g.link_fd = -1;
    g.speedup = -1.0; /* not given */
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *val = (i + 1 < argc) ? argv[i + 1] : NULL;
        if (strcmp(a, "--builtin") == 0) {
            builtin = true;
        } else if (strcmp(a, "--realtime") == 0) {
            g.sim = false;
        } else if (strcmp(a, "--quiet") == 0) {
            quiet = true;
        } else if ((strcmp(a, "--seed") == 0) && (val != NULL)) {
            seed = strtoull(val, NULL, 10);
            i++;
        } else if ((strcmp(a, "--timeout") == 0) && (val != NULL)) {
            timeout_s = strtod(val, NULL);
            i++;
        } else if ((strcmp(a, "--ticks") == 0) && (val != NULL)) {
            max_ticks = strtoull(val, NULL, 10);
            i++;
        } else if ((strcmp(a, "--trace") == 0) && (val != NULL)) {
            trace_path = val;
            i++;
        } else if ((strcmp(a, "--timeline") == 0) && (val != NULL)) {
            timeline_path = val;
            i++;
        } else if ((strcmp(a, "--log") == 0) && (val != NULL)) {
            log_path = val;
            i++;
        } else if ((strcmp(a, "--event") == 0) && (val != NULL)) {
            if (!parse_event(val)) {
                return usage();
            }
            i++;
        } else if ((strcmp(a, "--overrun") == 0) && (val != NULL)) {
            if (!parse_overrun(val)) {
                return usage();
            }
            i++;
        } else if ((strcmp(a, "--mavlink") == 0) && (val != NULL)) {
            if ((g.link_fd >= 0) || !link_open(&g, val)) {
                return usage();
            }
            i++;
        } else if ((strcmp(a, "--signing-key") == 0) && (val != NULL)) {
            if (!parse_key(val, g.key)) {
                return usage();
            }
            g.signing = true;
            i++;
        } else if ((strcmp(a, "--speedup") == 0) && (val != NULL)) {
            g.speedup = strtod(val, NULL);
            if (!(g.speedup > 0.0) || !(g.speedup <= 1000.0)) {
                return usage();
            }
            i++;
        } else if ((strcmp(a, "--wind") == 0) && (val != NULL)) {
            if (sscanf(val, "%lf,%lf", &wind_n, &wind_e) != 2) {
                return usage();
            }
            i++;
        } else if ((a[0] != '-') && (mission_path == NULL)) {
            mission_path = a;
        } else {
            return usage();
        }
    }
    if ((mission_path != NULL) && builtin) {
        fprintf(stderr, "sitl: give a mission file or --builtin (not both)\n");
        return usage();
    }
    if ((mission_path == NULL) && !builtin && (g.link_fd < 0)) {
        fprintf(stderr, "sitl: give a mission file or --builtin (or --mavlink: start with none)\n");
        return usage();
    }
    if ((g.speedup > 0.0) && !g.sim) {
        fprintf(stderr,
                "sitl: --speedup paces simulated time; --realtime runs on the wall clock\n");
        return usage();
    }
    if (g.speedup < 0.0) {
        g.speedup = (g.link_fd >= 0) ? 1.0 : 0.0;
    }
    if (log_path != NULL) {
        g.log = fopen(log_path, "wb");
        if (g.log == NULL) {
            fprintf(stderr, "sitl: cannot write %s\n", log_path);
            return 2;
        }
    }

    if (trace_path != NULL) {
        g.trace = g.sim ? fopen(trace_path, "w") : NULL;
        if (g.trace == NULL) {
            fprintf(stderr, "sitl: --trace needs simulated time and a writable file\n");
            return 2;
        }
    }
    if ((timeline_path != NULL) && !g.sim) {
        fprintf(stderr, "sitl: --timeline needs simulated time\n");
        return usage();
    }
    if (g.sim) {
        mt_posix_sim_enable(SIM_START_US);
    }
    g.rng = (seed * 0x9E3779B97F4A7C15ull) | 1u;
    if (builtin) {
        ncmds = (int)veh_builtin_mission_len;
        memcpy(cmds, veh_builtin_mission, (size_t)ncmds * sizeof(cmds[0]));
        veh_run_home(&home, &cmds[0]);
    } else if (mission_path != NULL) {
        ncmds = load_file(mission_path, cmds, &home);
        if (ncmds < 0) {
            return 2;
        }
    }

    simplat_init(&g.world, &home, seed, g.sim ? sim_wait : mt_posix_metronome_wait,
                 g.sim ? (void *)&g : (void *)&g.met);
    simplat_set_wind(&g.world, (float)wind_n, (float)wind_e);
    memset(&plat, 0, sizeof(plat));
    plat.console = cb_console;
    plat.log_sink = cb_log_sink;
    plat.gcs_poll = cb_gcs_poll;
    plat.task_work = g.sim ? cb_task_work : NULL;
    plat.status_lines = !quiet;
    g.run.timeout_us = run_timeout_us(timeout_s);
    g.run.settle_us = SETTLE_US;
    g.run.max_ticks = max_ticks;
    g.run.gcs_session = g.link_fd >= 0;

    /* plat.ctx: the world, the first member of g */
    st = veh_run_start(&g.run, &plat, &g.world, &home, cmds, (uint16_t)ncmds, &bad);
    veh_timer_spec(&g.timer_period, &g.timer_cmin, &g.timer_cmax);
    g.period_us = veh_sched()->period_us;
    g.next_timer = g.run.boot_us + g.timer_period;
    if ((st != MT_OK) && (veh_sched()->ntasks == 0u)) {
        fprintf(stderr, "sitl: task table rejected: %s at entry %u\n", mt_status_str(st), bad);
        return 2;
    }
    if (g_overrun_name[0] != '\0') {
        const mt_sched_t *sc = veh_sched();
        uint32_t k;
        for (k = 0u; k < sc->ntasks; k++) {
            if (strcmp(sc->tasks[k].name, g_overrun_name) == 0) {
                g.overrun_task = (int)k;
            }
        }
        if (g.overrun_task < 0) {
            fprintf(stderr, "sitl: --overrun: no task named %s\n", g_overrun_name);
            return 2;
        }
    }
    veh_printf("metronome SITL: %s time, loop %u Hz, %u tasks, seed %llu\n",
               g.sim ? "simulated" : "real", (unsigned)veh_sched()->loop_rate_hz,
               (unsigned)veh_sched()->ntasks, (unsigned long long)seed);
    if (!veh_run_rejected(st, bad)) {
        if (ncmds == 0) {
            veh_printf("no mission loaded; the vehicle stays disarmed\n");
        } else {
            veh_printf("mission: %d items (%s)\n", ncmds, builtin ? "built-in" : mission_path);
        }
    }
    if (g.overrun_task >= 0) {
        veh_printf("fault injection: %s takes %u us more per run\n", g_overrun_name,
                   (unsigned)g.overrun_us);
    }
    if (g.signing) {
        struct timespec now;
        /* the signature clock: MAVLink's 10 us units since 2015-01-01, from the host's clock */
        clock_gettime(CLOCK_REALTIME, &now);
        veh_link_signing(g.key, ((uint64_t)now.tv_sec - 1420070400u) * 100000u +
                                    (uint64_t)now.tv_nsec / 10000u);
        veh_printf("MAVLink signing on: frames sent are signed, unsigned ones received dropped\n");
    }
    if (g.link_fd >= 0) {
        char ip[INET_ADDRSTRLEN];
        veh_printf("MAVLink: udp to %s:%u, %s\n",
                   inet_ntop(AF_INET, &g.gcs.sin_addr, ip, sizeof(ip)),
                   (unsigned)ntohs(g.gcs.sin_port),
                   g.sim ? "simulated time paced to the wall clock" : "real time");
        (void)signal(SIGINT, on_signal);
        (void)signal(SIGTERM, on_signal);
    }

    if (!g.sim) {
        mt_posix_metronome_init(&g.met, g.period_us);
        if ((mt_posix_proc_thread_start(&timer_thr, veh_timer_procs(), g.timer_period,
                                        MT_PRIO_TIMER) != MT_OK) ||
            (mt_posix_proc_thread_start(&io_thr, veh_io_procs(), 1000u, MT_PRIO_IO) != MT_OK) ||
            (mt_posix_wq_start(&wq_thr, veh_work_queue()) != MT_OK)) {
            fprintf(stderr, "sitl: cannot start the proc and work-queue threads\n");
            return 2;
        }
    }

    if ((timeline_path != NULL) && !tl_open(timeline_path, veh_work_queue())) {
        fprintf(stderr, "sitl: cannot write %s\n", timeline_path);
        return 2;
    }
    w0 = wall_s();
    for (;;) {
        if (g.trace != NULL) {
            trace_tick_begin();
        }
        veh_loop_once(simplat_wait, &g.world);
        tl_tick_end(veh_sched(), mt_port_now_us());
        if (g.trace != NULL) {
            trace_tick_end(max_ticks);
        }
        link_pump(&g);
        if (g.sim && (g.speedup > 0.0)) {
            pace(&g, w0, wall_s);
        }
        if (g_interrupted != 0) {
            g.run.reason = "interrupted (signal)";
            break;
        }
        if (!veh_run_after_tick(&g.run, &g.world)) {
            break;
        }
    }
    if (!g.sim) {
        mt_posix_proc_thread_stop(&timer_thr);
        mt_posix_proc_thread_stop(&io_thr);
        mt_posix_wq_stop(&wq_thr);
    }
    /* drain what is left of the log (the IO thread is stopped: this is its consumer now) */
    {
        uint64_t d0 = veh_io_procs()->dispatches;
        uint64_t t0 = mt_port_now_us();
        veh_run_drain();
        for (; d0 < veh_io_procs()->dispatches; d0++) {
            tl_slice(TL_IO, "io procs", t0, mt_port_now_us() - t0, "procs", veh_io_procs()->count);
        }
    }
    veh_run_summary(&g.run, &g.world);
    if (g.overrun_task >= 0) {
        veh_printf("fault injection: %llu runs of %s overran by %u us\n",
                   (unsigned long long)g.overrun_runs, g_overrun_name, (unsigned)g.overrun_us);
    }
    if (g.link_fd >= 0) {
        veh_printf("MAVLink udp: %llu bytes received, %u datagrams dropped (%u: receive ring full "
                   "or over 2 KB; %u: the socket's buffer full), "
                   "%llu bytes sent, %u datagrams refused\n",
                   (unsigned long long)g.link_rx_bytes,
                   (unsigned)(g.link_rx_dropped + g.link_sock_dropped), (unsigned)g.link_rx_dropped,
                   (unsigned)g.link_sock_dropped, (unsigned long long)g.link_tx_bytes,
                   (unsigned)g.link_tx_errors);
        (void)close(g.link_fd);
    }
    if (g.trace != NULL) {
        fclose(g.trace);
        g.trace = NULL;
    }
    if (timeline_path != NULL) {
        if (!tl_close()) {
            fprintf(stderr, "sitl: error writing %s\n", timeline_path);
            return 2;
        }
        veh_printf("timeline file: %s (Perfetto UI or chrome://tracing)\n", timeline_path);
    }
    if (g.log != NULL) {
        if ((fclose(g.log) != 0) || g.log_error) {
            fprintf(stderr, "sitl: error writing %s\n", log_path);
            return 2;
        }
        veh_printf("log file: %s (%llu bytes)\n", log_path, (unsigned long long)g.log_written);
    }
    fflush(stdout);
    {
        double w = wall_s() - w0;
        double simulated = (double)(mt_port_now_us() - g.run.boot_us) * 1e-6;
        fprintf(stderr, "sitl: %.1f s %s in %.2f s of wall time (%.0fx real time)\n", simulated,
                g.sim ? "simulated" : "flown", w, (w > 0.0) ? simulated / w : 0.0);
    }
    rc =
        ((veh_phase() == VEH_PHASE_DONE) || ((max_ticks != 0u) && (veh_sched()->tick >= max_ticks)))
            ? 0
            : 1;
    return rc;
}
