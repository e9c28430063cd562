/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file tools/trace/ring_trace.c
 * @brief Trace generator for trace validation of tla/Ring.tla.
 *
 * Runs the real kernel/src/ring.c or objring.c with one producer and one
 * consumer coroutine (ucontext) under a seeded random interleaving. The
 * coroutines switch at every shared-index access: tools/trace/shim/mt_atomic.h
 * routes mt_load_acquire_u32 / mt_store_release_u32 here, and the scheduler
 * picks the side that performs the next access. Everything between two index
 * accesses (the slot copies, the cached-index arithmetic) runs without a
 * switch, which is one of the interleavings the model allows.
 *
 * The log is written as a TLA+ module (RingTraceData.tla, operator Trace):
 *   [s, k = "call", op, n]   an API call starts (n: len)
 *   [s, k = "load", f, v]    acquire load of index f, value v
 *   [s, k = "store", f, v]   release store of index f, value v
 *   [s, k = "ret", n, d]     the call returns: n items, d the items read
 *                            (object pushes also carry the status, st)
 *   [k = "end", ...]         the final ring fields and slot contents
 * Items are numbered 1, 2, ...; a byte ring byte or an object (4 bytes) holds
 * its item number. tla/RingTrace.tla checks that the model can take
 * exactly these steps.
 *
 * usage: ring_trace byte|obj CAP MAX_MSG MAX_LEN DROP(0|1) SEED OUT_DIR
 */
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <ucontext.h>

#include "mt/objring.h"
#include "mt/ring.h"
#include "trace_rng.h"

#define MAX_CAP 64u
#define STACK_BYTES (256u * 1024u)

enum { PROD = 0, CONS = 1 };

static int g_byte;               /* 1: byte ring, 0: object ring */
static uint32_t g_cap, g_max_msg, g_max_len;
static int g_drop;
static uint64_t g_rng;

static mt_bring_t g_br;
static uint8_t g_bstore[MAX_CAP];
static mt_oring_t g_or;
static uint32_t g_ostore[MAX_CAP + 1u];

static ucontext_t g_sched, g_side[2];
static int g_cur;
static int g_done[2];

static FILE *g_out;
static int g_first = 1;

static uint32_t rnd(uint32_t n)
{
    return trace_rnd(&g_rng, n);
}

static void sep(void)
{
    fputs(g_first ? "    " : ",\n    ", g_out);
    g_first = 0;
}

static const char *side(void)
{
    return g_cur == PROD ? "P" : "C";
}

static const char *field(const uint32_t *p)
{
    if (g_byte) {
        return p == &g_br.head ? "head" : p == &g_br.tail ? "tail" : "?";
    }
    return p == &g_or.head ? "head" : p == &g_or.tail ? "tail" : "?";
}

/* Give the scheduler the choice of who performs the next shared access. */
static void yield(void)
{
    if (swapcontext(&g_side[g_cur], &g_sched) != 0) {
        perror("swapcontext");
        exit(2);
    }
}

uint32_t mt_trace_load_acquire(const uint32_t *p)
{
    uint32_t v;

    yield();
    v = __atomic_load_n(p, __ATOMIC_ACQUIRE);
    sep();
    fprintf(g_out, "[s |-> \"%s\", k |-> \"load\", f |-> \"%s\", v |-> %u]", side(), field(p), v);
    return v;
}

void mt_trace_store_release(uint32_t *p, uint32_t v)
{
    yield();
    __atomic_store_n(p, v, __ATOMIC_RELEASE);
    sep();
    fprintf(g_out, "[s |-> \"%s\", k |-> \"store\", f |-> \"%s\", v |-> %u]", side(), field(p), v);
}

static void log_call(const char *op, uint32_t n)
{
    sep();
    fprintf(g_out, "[s |-> \"%s\", k |-> \"call\", op |-> \"%s\", n |-> %u]", side(), op, n);
}

static void log_ret(uint32_t n, const uint32_t *d, uint32_t nd)
{
    uint32_t k;

    sep();
    fprintf(g_out, "[s |-> \"%s\", k |-> \"ret\", n |-> %u, d |-> <<", side(), n);
    for (k = 0; k < nd; k++) {
        fprintf(g_out, "%s%u", k ? ", " : "", d[k]);
    }
    fputs(">>]", g_out);
}

static void producer(void)
{
    uint32_t nxt = 1;

    while (nxt <= g_max_msg) {
        if (g_byte) {
            uint8_t src[MAX_CAP];
            uint32_t room = g_max_msg - nxt + 1u;
            uint32_t len = 1u + rnd(room < g_max_len ? room : g_max_len);
            uint32_t k, n;
            for (k = 0; k < len; k++) {
                src[k] = (uint8_t)(nxt + k);
            }
            log_call("write", len);
            n = mt_bring_write(&g_br, src, len);
            log_ret(n, NULL, 0);
            nxt += n;
        } else {
            uint32_t obj = nxt;
            mt_status_t st;
            log_call(g_drop ? "push_drop_oldest" : "push", 1);
            st = g_drop ? mt_oring_push_drop_oldest(&g_or, &obj) : mt_oring_push(&g_or, &obj);
            /* with the status: run_traces.py compares the MT_W_DROPPED_OLDEST
             * returns with the consumer's lost count */
            sep();
            fprintf(g_out, "[s |-> \"P\", k |-> \"ret\", n |-> %u, d |-> <<>>, st |-> \"%s\"]",
                    st == MT_E_FULL ? 0u : 1u, mt_status_str(st));
            nxt++; /* stored, or rejected and counted: the item is given up */
        }
    }
    g_done[PROD] = 1;
}

static void consumer(void)
{
    uint32_t idle = 0, calls = 0;

    /* Drain until the producer is done and two calls in a row found nothing. */
    while (idle < 2u && calls < 8u * g_max_msg) {
        uint32_t got;
        calls++;
        if (g_byte) {
            uint8_t dst[MAX_CAP];
            uint32_t d[MAX_CAP];
            uint32_t len = 1u + rnd(g_max_len);
            uint32_t k;
            log_call("read", len);
            got = mt_bring_read(&g_br, dst, len);
            for (k = 0; k < got; k++) {
                d[k] = dst[k];
            }
            log_ret(got, d, got);
        } else {
            uint32_t out = 0;
            mt_status_t st;
            log_call("pop", 1);
            st = mt_oring_pop(&g_or, &out);
            got = st == MT_OK ? 1u : 0u;
            log_ret(got, &out, got);
        }
        idle = (got == 0u && g_done[PROD]) ? idle + 1u : 0u;
    }
    g_done[CONS] = 1;
}

static void log_end(void)
{
    uint32_t k, slots = g_byte ? g_cap : g_cap + 1u;

    sep();
    if (g_byte) {
        fprintf(g_out,
                "[k |-> \"end\", tail |-> %u, head |-> %u, hc |-> %u, tc |-> %u, lost |-> 0, "
                "rej |-> 0, buf |-> <<",
                g_br.tail, g_br.head, g_br.head_cache, g_br.tail_cache);
    } else {
        fprintf(g_out,
                "[k |-> \"end\", tail |-> %u, head |-> %u, hc |-> %u, tc |-> %u, lost |-> %u, "
                "rej |-> %u, buf |-> <<",
                g_or.tail, g_or.head, g_or.head_cache, g_or.tail_cache, g_or.lost, g_or.rejected);
    }
    for (k = 0; k < slots; k++) {
        fprintf(g_out, "%s%u", k ? ", " : "", g_byte ? (uint32_t)g_bstore[k] : g_ostore[k]);
    }
    fputs(">>]", g_out);
}

int main(int argc, char **argv)
{
    static uint8_t stacks[2][STACK_BYTES];
    char path[4096];
    uint32_t bias;
    int s;

    if (argc != 8) {
        fprintf(stderr, "usage: %s byte|obj CAP MAX_MSG MAX_LEN DROP SEED OUT_DIR\n", argv[0]);
        return 2;
    }
    g_byte = strcmp(argv[1], "byte") == 0;
    g_cap = (uint32_t)strtoul(argv[2], NULL, 0);
    g_max_msg = (uint32_t)strtoul(argv[3], NULL, 0);
    g_max_len = (uint32_t)strtoul(argv[4], NULL, 0);
    g_drop = atoi(argv[5]);
    g_rng = strtoull(argv[6], NULL, 0) * 0x9E3779B97F4A7C15ull + 1u;
    if (g_cap < 1u || g_cap > MAX_CAP - 1u || g_max_len < 1u || g_max_len > g_cap ||
        g_max_msg < 1u || g_max_msg > 255u || (g_byte && g_drop)) {
        fprintf(stderr, "ring_trace: bad parameters\n");
        return 2;
    }
    if (g_byte) {
        if (mt_bring_init(&g_br, g_bstore, g_cap) != MT_OK) {
            return 2;
        }
    } else if (mt_oring_init(&g_or, g_ostore, sizeof(uint32_t), g_cap) != MT_OK) {
        return 2;
    }

    snprintf(path, sizeof path, "%s/RingTraceData.tla", argv[7]);
    g_out = fopen(path, "w");
    if (g_out == NULL) {
        fprintf(stderr, "ring_trace: %s: %s\n", path, strerror(errno));
        return 2;
    }
    fprintf(g_out, "---- MODULE RingTraceData ----\n"
                   "\\* Generated by tools/trace/ring_trace %s %s %s %s %s %s\n"
                   "Trace == <<\n",
            argv[1], argv[2], argv[3], argv[4], argv[5], argv[6]);

    for (s = 0; s < 2; s++) {
        if (getcontext(&g_side[s]) != 0) {
            return 2;
        }
        g_side[s].uc_stack.ss_sp = stacks[s];
        g_side[s].uc_stack.ss_size = STACK_BYTES;
        g_side[s].uc_link = &g_sched;
        makecontext(&g_side[s], s == PROD ? producer : consumer, 0);
    }
    /* Before every shared access, the producer goes next with probability
     * bias % (40, 50 or 60 by seed), else the consumer. */
    bias = 40u + 10u * (uint32_t)(strtoull(argv[6], NULL, 0) % 3u);
    while (!g_done[PROD] || !g_done[CONS]) {
        g_cur = rnd(100u) < bias ? PROD : CONS;
        if (g_done[g_cur]) {
            g_cur = 1 - g_cur;
        }
        if (swapcontext(&g_sched, &g_side[g_cur]) != 0) {
            perror("swapcontext");
            return 2;
        }
    }
    log_end();
    fputs("\n>>\n====\n", g_out);
    fclose(g_out);
    return 0;
}
