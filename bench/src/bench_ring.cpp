// SPDX-License-Identifier: Apache-2.0
//
// bench_ring: SPSC rings. Metronome's object ring (elem 4), word ring (its fast path for
// 32-bit objects, compile-time capacity: MT_CFG_WRING_CAP=4096 from bench.mk) and byte ring
// against boost::lockfree::spsc_queue and the ArduPilot-style reference (ref_ap_ring.hpp), all
// compiled with the same flags into this one binary.
//
//   bench_ring cg <entry> <n>                 run one callgrind entry (see ENTRIES)
//   bench_ring tput <items> <rounds> [v,...]  two-thread throughput, interleaved rounds
//   bench_ring rtt <roundtrips> <rounds> [v,...]  ping-pong round trip, interleaved rounds
//
// Output: "RESULT key value..." lines for bench/run.py.
#include "bench_util.h"

#include <atomic>
#include <boost/lockfree/spsc_queue.hpp>
#include <string>
#include <thread>
#include <vector>

extern "C" {
#include "mt/objring.h"
#include "mt/ring.h"
#include "mt/wordring.h"
}
#include "ref_ap_ring.hpp"

namespace {

constexpr uint32_t kCap = 4096;   // objects (or bytes) every ring holds
constexpr uint32_t kBatch = 64;   // single-thread: push 64, then pop 64

// ------------------------------------------------------------------ the rings
alignas(64) uint8_t g_oring_store[MT_ORING_STORAGE_BYTES(4, kCap)];
alignas(64) mt_oring_t g_oring;
alignas(64) uint8_t g_bring_store[kCap];
alignas(64) mt_bring_t g_bring;
alignas(64) mt_wring_t g_wring;
static_assert(MT_CFG_WRING_CAP == kCap, "bench.mk builds the word ring with the peers' capacity");

using BoostQ = boost::lockfree::spsc_queue<uint32_t, boost::lockfree::capacity<kCap>>;
using BoostQrt = boost::lockfree::spsc_queue<uint32_t>;
using BoostB = boost::lockfree::spsc_queue<uint8_t, boost::lockfree::capacity<kCap>>;
using ApQ = apref::ObjectBuffer<uint32_t>;

struct Rings {
    BoostQ boost_q;
    BoostQrt boost_qrt{kCap};
    BoostB boost_b;
    ApQ ap_q{kCap};
    apref::ByteBuffer ap_b{kCap + 1u};
};
Rings *g_r;

void init_rings()
{
    mt_wring_init(&g_wring);
    if (mt_oring_init(&g_oring, g_oring_store, 4u, kCap) != MT_OK ||
        mt_bring_init(&g_bring, g_bring_store, kCap) != MT_OK) {
        std::fprintf(stderr, "bench_ring: ring init failed\n");
        std::exit(2);
    }
    g_r = new Rings();
}

// ---------------------------------------------------------- per-ring adapters
struct MtOps {
    static bool push(uint32_t v) { return mt_oring_push(&g_oring, &v) == MT_OK; }
    static bool pop(uint32_t &v) { return mt_oring_pop(&g_oring, &v) == MT_OK; }
    static void reset() { (void)mt_oring_init(&g_oring, g_oring_store, 4u, kCap); }
};
struct MtWOps {
    static bool push(uint32_t v) { return mt_wring_push(&g_wring, v) == MT_OK; }
    static bool pop(uint32_t &v) { return mt_wring_pop(&g_wring, &v) == MT_OK; }
    static void reset() { mt_wring_init(&g_wring); }
};
struct BoostOps {
    static bool push(uint32_t v) { return g_r->boost_q.push(v); }
    static bool pop(uint32_t &v) { return g_r->boost_q.pop(v); }
    static void reset() { g_r->boost_q.reset(); }
};
struct BoostRtOps {
    static bool push(uint32_t v) { return g_r->boost_qrt.push(v); }
    static bool pop(uint32_t &v) { return g_r->boost_qrt.pop(v); }
    static void reset() { g_r->boost_qrt.reset(); }
};
struct ApOps {
    static bool push(uint32_t v) { return g_r->ap_q.push(v); }
    static bool pop(uint32_t &v) { return g_r->ap_q.pop(v); }
    static void reset() { /* always drained at the end of a run */ }
};
// second set of queues for the ping-pong return direction
alignas(64) uint8_t g_oring2_store[MT_ORING_STORAGE_BYTES(4, kCap)];
alignas(64) mt_oring_t g_oring2;

// ------------------------------------------------------------- single thread
template <class Ops> uint64_t st_push_pop(uint64_t items)
{
    uint64_t sum = 0;
    for (uint64_t i = 0; i < items; i += kBatch) {
        for (uint32_t k = 0; k < kBatch; k++) {
            (void)Ops::push((uint32_t)(i + k));
        }
        for (uint32_t k = 0; k < kBatch; k++) {
            uint32_t v = 0;
            (void)Ops::pop(v);
            sum += v;
        }
    }
    return sum;
}

volatile uint64_t g_sink;
uint32_t g_plain[kBatch];

} // namespace

// Callgrind entries: same loop shape, the ring operations differ.
BENCH_EXTERN_C NOINL uint64_t bench_ring_base(uint64_t items)
{
    uint64_t sum = 0;
    for (uint64_t i = 0; i < items; i += kBatch) {
        for (uint32_t k = 0; k < kBatch; k++) {
            uint32_t v = (uint32_t)(i + k);
            BENCH_OPAQUE(v);
            g_plain[k] = v;
        }
        BENCH_CLOBBER();
        for (uint32_t k = 0; k < kBatch; k++) {
            uint32_t v = g_plain[k];
            BENCH_OPAQUE(v);
            sum += v;
        }
    }
    return sum;
}
BENCH_EXTERN_C NOINL uint64_t bench_ring_mt(uint64_t items) { return st_push_pop<MtOps>(items); }
BENCH_EXTERN_C NOINL uint64_t bench_ring_mtw(uint64_t items) { return st_push_pop<MtWOps>(items); }
BENCH_EXTERN_C NOINL uint64_t bench_ring_boost(uint64_t items) { return st_push_pop<BoostOps>(items); }
BENCH_EXTERN_C NOINL uint64_t bench_ring_boostrt(uint64_t items) { return st_push_pop<BoostRtOps>(items); }
BENCH_EXTERN_C NOINL uint64_t bench_ring_ap(uint64_t items) { return st_push_pop<ApOps>(items); }

// Byte ring: write n bytes then read n bytes, `iters` times.
namespace {
uint8_t g_src[64], g_dst[64];
}
#define BYTE_ENTRIES(N)                                                                   \
    BENCH_EXTERN_C NOINL uint64_t bench_bytes_mt_##N(uint64_t iters)                     \
    {                                                                                     \
        uint64_t s = 0;                                                                   \
        for (uint64_t i = 0; i < iters; i++) {                                            \
            s += mt_bring_write(&g_bring, g_src, N);                                      \
            s += mt_bring_read(&g_bring, g_dst, N);                                       \
        }                                                                                 \
        return s;                                                                         \
    }                                                                                     \
    BENCH_EXTERN_C NOINL uint64_t bench_bytes_boost_##N(uint64_t iters)                  \
    {                                                                                     \
        uint64_t s = 0;                                                                   \
        for (uint64_t i = 0; i < iters; i++) {                                            \
            s += g_r->boost_b.push(g_src, N);                                             \
            s += g_r->boost_b.pop(g_dst, N);                                              \
        }                                                                                 \
        return s;                                                                         \
    }                                                                                     \
    BENCH_EXTERN_C NOINL uint64_t bench_bytes_ap_##N(uint64_t iters)                     \
    {                                                                                     \
        uint64_t s = 0;                                                                   \
        for (uint64_t i = 0; i < iters; i++) {                                            \
            s += g_r->ap_b.write(g_src, N);                                               \
            s += g_r->ap_b.read(g_dst, N);                                                \
        }                                                                                 \
        return s;                                                                         \
    }
BYTE_ENTRIES(1)
BYTE_ENTRIES(64)

namespace {

struct Entry {
    const char *name;
    uint64_t (*fn)(uint64_t);
    uint64_t per_call; // operations per unit of n (for checking)
};

const Entry kEntries[] = {
    {"bench_ring_base", bench_ring_base, 1},       {"bench_ring_mt", bench_ring_mt, 1},
    {"bench_ring_mtw", bench_ring_mtw, 1},         {"bench_ring_boost", bench_ring_boost, 1},     {"bench_ring_boostrt", bench_ring_boostrt, 1},
    {"bench_ring_ap", bench_ring_ap, 1},           {"bench_bytes_mt_1", bench_bytes_mt_1, 1},
    {"bench_bytes_boost_1", bench_bytes_boost_1, 1}, {"bench_bytes_ap_1", bench_bytes_ap_1, 1},
    {"bench_bytes_mt_64", bench_bytes_mt_64, 1},   {"bench_bytes_boost_64", bench_bytes_boost_64, 1},
    {"bench_bytes_ap_64", bench_bytes_ap_64, 1},
};

int run_cg(const std::string &name, uint64_t n)
{
    for (const Entry &e : kEntries) {
        if (name == e.name) {
            // warm-up outside the toggled entry is not needed for Ir; check the
            // result so a broken ring cannot pass silently
            uint64_t s = e.fn(n);
            g_sink = s;
            uint64_t want_sum = (n - 1) * n / 2; // push/pop entries return sum of 0..n-1
            bool is_ring = name.rfind("bench_ring_", 0) == 0;
            bool is_bytes = name.rfind("bench_bytes_", 0) == 0;
            uint64_t nbytes = (name.size() >= 3 && name.compare(name.size() - 3, 3, "_64") == 0) ? 64 : 1;
            if ((is_ring && s != want_sum) || (is_bytes && s != 2 * nbytes * n)) {
                std::fprintf(stderr, "bench_ring: %s: wrong result %llu\n", e.name, (unsigned long long)s);
                return 3;
            }
            BENCH_RESULT(e.name, "%llu", (unsigned long long)n);
            return 0;
        }
    }
    std::fprintf(stderr, "bench_ring: unknown entry %s\n", name.c_str());
    return 2;
}

// ------------------------------------------------------------- two threads
struct Sync {
    alignas(64) std::atomic<int> ready{0};
    alignas(64) std::atomic<int> go{0};
    double t0 = 0, t1 = 0;
    uint64_t sum = 0;
    int pinned = 1;
    std::vector<double> stamps; // time at the end of each chunk (steady-state estimate)
};

constexpr uint64_t kTputChunk = 1u << 16; // items per steady-state chunk (~1 ms)
constexpr uint64_t kRttChunk = 1u << 8;   // round trips per steady-state chunk

// One measurement: the round's value (items / elapsed, or elapsed / round
// trips) and the steady-state value (median over short equal chunks of the
// run, insensitive to the moments one of the two threads was preempted by
// another process on a shared machine).
struct Meas {
    double value;
    double steady;
};

double chunk_median(const Sync &s, double per_chunk, bool as_rate)
{
    std::vector<double> v;
    double prev = s.t0;
    for (double t : s.stamps) {
        double dt = t - prev;
        prev = t;
        if (dt > 0) {
            v.push_back(as_rate ? per_chunk / dt : dt * 1e9 / per_chunk);
        }
    }
    return v.empty() ? 0.0 : bench_median(v.data(), (int)v.size());
}

// Spin until the peer is ready, then start the clock and release it.
void start_as_leader(Sync &s)
{
    while (s.ready.load(std::memory_order_acquire) == 0) {
    }
    s.t0 = bench_now_s();
    s.go.store(1, std::memory_order_release);
}
void start_as_follower(Sync &s)
{
    s.ready.store(1, std::memory_order_release);
    while (s.go.load(std::memory_order_acquire) == 0) {
    }
}

// chunk_items: kTputChunk, divided by the item divisor for the slow peer so
// that every variant's chunks last about as long
template <class Ops> Meas tput_once(uint64_t items, uint64_t chunk_items, int *pinned)
{
    Sync s;
    const uint64_t chunk = items < chunk_items ? items : (chunk_items ? chunk_items : 1);
    s.stamps.reserve(items / chunk + 1);
    Ops::reset();
    std::thread cons([&] {
        s.pinned &= bench_pin(1);
        start_as_follower(s);
        uint64_t sum = 0;
        uint64_t next = chunk;
        for (uint64_t i = 0; i < items; i++) {
            uint32_t v;
            while (!Ops::pop(v)) {
            }
            sum += v;
            if (i + 1 == next) {
                s.stamps.push_back(bench_now_s());
                next += chunk;
            }
        }
        s.t1 = bench_now_s();
        s.sum = sum;
    });
    std::thread prod([&] {
        s.pinned &= bench_pin(0);
        start_as_leader(s);
        for (uint64_t i = 0; i < items; i++) {
            while (!Ops::push((uint32_t)i)) {
            }
        }
    });
    prod.join();
    cons.join();
    uint64_t want = 0;
    for (uint64_t i = 0; i < items; i++) {
        want += (uint32_t)i;
    }
    if (s.sum != want) {
        std::fprintf(stderr, "bench_ring: throughput checksum mismatch\n");
        std::exit(3);
    }
    *pinned &= s.pinned;
    return Meas{(double)items / (s.t1 - s.t0), chunk ? chunk_median(s, (double)chunk, true) : 0.0};
}

// Round trip over two rings A (ping -> pong) and B (pong -> ping).
template <class PushA, class PopA, class PushB, class PopB> Meas rtt_once(uint64_t n, int *pinned)
{
    Sync s;
    const uint64_t chunk = n < kRttChunk ? n : kRttChunk;
    s.stamps.reserve(n / chunk + 1);
    std::thread pong([&] {
        s.pinned &= bench_pin(1);
        start_as_follower(s);
        for (uint64_t i = 0; i < n; i++) {
            uint32_t v;
            while (!PopA::f(v)) {
            }
            while (!PushB::f(v)) {
            }
        }
    });
    std::thread ping([&] {
        s.pinned &= bench_pin(0);
        start_as_leader(s);
        uint64_t bad = 0;
        uint64_t next = chunk;
        for (uint64_t i = 0; i < n; i++) {
            uint32_t v;
            while (!PushA::f((uint32_t)i)) {
            }
            while (!PopB::f(v)) {
            }
            bad += (v != (uint32_t)i);
            if (i + 1 == next) {
                s.stamps.push_back(bench_now_s());
                next += chunk;
            }
        }
        s.t1 = bench_now_s();
        s.sum = bad;
    });
    ping.join();
    pong.join();
    if (s.sum != 0) {
        std::fprintf(stderr, "bench_ring: ping-pong mismatch\n");
        std::exit(3);
    }
    *pinned &= s.pinned;
    return Meas{(s.t1 - s.t0) * 1e9 / (double)n, chunk ? chunk_median(s, (double)chunk, false) : 0.0};
}

// round-trip adapters
struct MtPushA { static bool f(uint32_t v) { return mt_oring_push(&g_oring, &v) == MT_OK; } };
struct MtPopA { static bool f(uint32_t &v) { return mt_oring_pop(&g_oring, &v) == MT_OK; } };
struct MtPushB { static bool f(uint32_t v) { return mt_oring_push(&g_oring2, &v) == MT_OK; } };
struct MtPopB { static bool f(uint32_t &v) { return mt_oring_pop(&g_oring2, &v) == MT_OK; } };
BoostQ *g_boost2;
ApQ *g_ap2;
struct BoPushA { static bool f(uint32_t v) { return g_r->boost_q.push(v); } };
struct BoPopA { static bool f(uint32_t &v) { return g_r->boost_q.pop(v); } };
struct BoPushB { static bool f(uint32_t v) { return g_boost2->push(v); } };
struct BoPopB { static bool f(uint32_t &v) { return g_boost2->pop(v); } };
struct ApPushA { static bool f(uint32_t v) { return g_r->ap_q.push(v); } };
struct ApPopA { static bool f(uint32_t &v) { return g_r->ap_q.pop(v); } };
struct ApPushB { static bool f(uint32_t v) { return g_ap2->push(v); } };
struct ApPopB { static bool f(uint32_t &v) { return g_ap2->pop(v); } };

// bare cache-line ping-pong: two atomics on separate lines
struct alignas(64) Line {
    std::atomic<uint32_t> v{0};
};
Line g_ping, g_pong;
Meas bare_once(uint64_t n, int *pinned)
{
    Sync s;
    const uint64_t chunk = n < kRttChunk ? n : kRttChunk;
    s.stamps.reserve(n / chunk + 1);
    g_ping.v.store(0);
    g_pong.v.store(0);
    std::thread pong([&] {
        s.pinned &= bench_pin(1);
        start_as_follower(s);
        for (uint32_t i = 1; i <= n; i++) {
            while (g_ping.v.load(std::memory_order_acquire) != i) {
            }
            g_pong.v.store(i, std::memory_order_release);
        }
    });
    std::thread ping([&] {
        s.pinned &= bench_pin(0);
        start_as_leader(s);
        uint64_t next = chunk;
        for (uint32_t i = 1; i <= n; i++) {
            g_ping.v.store(i, std::memory_order_release);
            while (g_pong.v.load(std::memory_order_acquire) != i) {
            }
            if (i == next) {
                s.stamps.push_back(bench_now_s());
                next += chunk;
            }
        }
        s.t1 = bench_now_s();
    });
    ping.join();
    pong.join();
    *pinned &= s.pinned;
    return Meas{(s.t1 - s.t0) * 1e9 / (double)n, chunk ? chunk_median(s, (double)chunk, false) : 0.0};
}

std::vector<std::string> split(const std::string &s)
{
    std::vector<std::string> out;
    size_t p = 0;
    while (p <= s.size()) {
        size_t q = s.find(',', p);
        if (q == std::string::npos) {
            q = s.size();
        }
        if (q > p) {
            out.push_back(s.substr(p, q - p));
        }
        p = q + 1;
    }
    return out;
}

void print_series(const char *kind, const std::string &v, std::vector<double> &xs)
{
    std::string key = std::string(kind) + "." + v;
    std::string all;
    for (double x : xs) {
        char b[32];
        std::snprintf(b, sizeof b, "%s%.6g", all.empty() ? "" : ",", x);
        all += b;
    }
    std::vector<double> tmp = xs;
    double med = bench_median(tmp.data(), (int)tmp.size());
    BENCH_RESULT(key.c_str(), "%.6g %.6g %.6g %s", med, tmp.front(), tmp.back(), all.c_str());
}

// Rounds are interleaved: round r runs the variants starting at index r % V.
// Time guard: the whole loop should finish within budget_s. After each round
// the work per round (n, shared by every variant of the round so the ratios
// stay like for like) is scaled so that the remaining rounds fit the budget;
// it never grows above the requested n nor shrinks below min_n.
template <class Fn>
int rounds_loop(const char *kind, std::vector<std::string> vars, int rounds, uint64_t n, uint64_t min_n,
                double budget_s, Fn run_one)
{
    std::vector<std::vector<double>> res(vars.size()), steady(vars.size());
    int pinned = 1;
    uint64_t cur = n, lo = n, hi = 0;
    double start = bench_now_s();
    for (int r = 0; r < rounds; r++) {
        double t_round = bench_now_s();
        lo = cur < lo ? cur : lo;
        hi = cur > hi ? cur : hi;
        for (size_t k = 0; k < vars.size(); k++) {
            size_t idx = (r + k) % vars.size();
            Meas x = run_one(vars[idx], cur, &pinned);
            if (x.value < 0) {
                std::fprintf(stderr, "bench_ring: unknown variant %s\n", vars[idx].c_str());
                return 2;
            }
            res[idx].push_back(x.value);
            steady[idx].push_back(x.steady);
        }
        double now = bench_now_s();
        int left = rounds - r - 1;
        if (left > 0) {
            double per_round = (budget_s - (now - start)) / left;
            double took = now - t_round;
            double want = (took > 0 && per_round > 0) ? (double)cur * per_round / took : (double)min_n;
            uint64_t next = want >= (double)n ? n : (uint64_t)want;
            cur = next < min_n ? min_n : next;
        }
    }
    for (size_t k = 0; k < vars.size(); k++) {
        print_series(kind, vars[k], res[k]);
        print_series((std::string(kind) + "_steady").c_str(), vars[k], steady[k]);
    }
    BENCH_RESULT((std::string(kind) + ".pinned").c_str(), "%d", pinned);
    BENCH_RESULT((std::string(kind) + ".n").c_str(), "%llu %llu %llu %.1f", (unsigned long long)n,
                 (unsigned long long)lo, (unsigned long long)hi, bench_now_s() - start);
    return 0;
}

} // namespace

int main(int argc, char **argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s cg ENTRY N | tput ITEMS ROUNDS [variants] | rtt N ROUNDS [variants]\n",
                     argv[0]);
        return 2;
    }
    init_rings();
    std::memset(g_src, 0x5a, sizeof g_src);
    std::string mode = argv[1];
    if (mode == "cg") {
        return run_cg(argv[2], argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 1000000ull);
    }
    if (mode == "tput") {
        uint64_t items = std::strtoull(argv[2], nullptr, 10);
        int rounds = argc > 3 ? std::atoi(argv[3]) : 21;
        std::vector<std::string> vars = split(argc > 4 ? argv[4] : "mt,boost,ap");
        // the ArduPilot-style reference is ~20x slower: it moves items / AP_DIV
        // items per round (a rate is a rate; see bench/README.md)
        uint64_t ap_div = (uint64_t)bench_env_long("BENCH_AP_DIV", 10, 1);
        double budget = (double)bench_env_long("BENCH_TPUT_BUDGET_S", 1000000, 1);
        return rounds_loop("tput", vars, rounds, items, 4 * kTputChunk * ap_div, budget,
                           [&](const std::string &v, uint64_t n, int *pinned) -> Meas {
            if (v == "mt") return tput_once<MtOps>(n, kTputChunk, pinned);
            if (v == "mtw") return tput_once<MtWOps>(n, kTputChunk, pinned);
            if (v == "boost") return tput_once<BoostOps>(n, kTputChunk, pinned);
            if (v == "boostrt") return tput_once<BoostRtOps>(n, kTputChunk, pinned);
            if (v == "ap") return tput_once<ApOps>(n / ap_div, kTputChunk / ap_div, pinned);
            return Meas{-1.0, 0.0};
        });
    }
    if (mode == "rtt") {
        uint64_t n = std::strtoull(argv[2], nullptr, 10);
        int rounds = argc > 3 ? std::atoi(argv[3]) : 21;
        std::vector<std::string> vars = split(argc > 4 ? argv[4] : "bare,mt,boost,ap");
        (void)mt_oring_init(&g_oring2, g_oring2_store, 4u, kCap);
        g_boost2 = new BoostQ();
        g_ap2 = new ApQ(kCap);
        double budget = (double)bench_env_long("BENCH_RTT_BUDGET_S", 1000000, 1);
        return rounds_loop("rtt", vars, rounds, n, 16 * kRttChunk, budget,
                           [&](const std::string &v, uint64_t m, int *pinned) -> Meas {
            if (v == "bare") return bare_once(m, pinned);
            if (v == "mt") return rtt_once<MtPushA, MtPopA, MtPushB, MtPopB>(m, pinned);
            if (v == "boost") return rtt_once<BoPushA, BoPopA, BoPushB, BoPopB>(m, pinned);
            if (v == "ap") return rtt_once<ApPushA, ApPopA, ApPushB, ApPopB>(m, pinned);
            return Meas{-1.0, 0.0};
        });
    }
    std::fprintf(stderr, "bench_ring: unknown mode %s\n", mode.c_str());
    return 2;
}
