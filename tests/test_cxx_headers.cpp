// SPDX-License-Identifier: Apache-2.0
// The kernel and host-port headers compile as C++ (C++17, -Wall -Wextra
// -Wshadow -Werror) with C linkage, and their layout promises hold there too.
// mt/mt.h and mt_posix.h are included without an extern "C" wrapper on purpose:
// the headers must provide it themselves.
#include "mt/mt.h"
#include "mt_posix.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace
{

// status enum: explicit, distinct values ending in the count sentinel
static_assert(MT_OK == 0, "MT_OK is 0");
static_assert(MT_E_INVALID == 1 && MT_E_FULL == 2 && MT_E_EMPTY == 3 && MT_E_DUPLICATE == 4, "");
static_assert(MT_E_TIMEOUT == 5 && MT_E_BUSY == 6 && MT_E_RANGE == 7, "");
static_assert(MT_E_TASK_ORDER == 8 && MT_E_TASK_RATE == 9 && MT_E_TASK_BUDGET == 10, "");
static_assert(MT_E_TASK_COUNT == 11 && MT_E_LOOP_RATE == 12 && MT_E_TASK_FN == 13, "");
static_assert(MT_W_DROPPED_OLDEST == 14 && MT_E_MISSION_CMD == 15 && MT_E_MISSION_PARAM == 16, "");
static_assert(MT_E_MISSION_LOCATION == 17 && MT_E_MISSION_FRAME == 18 && MT_E_MISSION_JUMP == 19,
              "");
static_assert(MT_E_MISSION_LOOP == 20 && MT_E_MISSION_SIZE == 21 && MT_E_MISSION_SYNTAX == 22, "");
static_assert(MT_E_STATE == 23 && MT_W_WQ_MERGED == 24, "");
static_assert(MT_E_BUS_MSG_SIZE == 25 && MT_E_BUS_QUEUE_LEN == 26, "");
static_assert(MT_E_BUS_STORAGE == 27 && MT_E_BUS_BEHIND == 28 && MT_E_BUS_TORN == 29, "");
static_assert(MT_W_BUS_MISSED == 30 && MT_STATUS_COUNT == 31, "");

// configuration defaults
static_assert(MT_CFG_VERSION == 1, "");
static_assert(MT_CFG_SCHED_MAX_TASKS == 64u && MT_CFG_PROC_MAX == 8u, "");
static_assert(MT_CFG_MISSION_MAX_CMDS == 700u, "");
static_assert(MT_CFG_WQ_MAX_ITEMS == 16u, "");

// work queues: C layout, slot indices fit the FIFO's byte arrays, distinct state values
static_assert(std::is_standard_layout<mt_wq_t>::value, "C layout");
static_assert(std::is_standard_layout<mt_work_t>::value, "C layout");
static_assert(sizeof(mt_wq_t::order[0]) == 1u && sizeof(mt_wq_t::order) == MT_CFG_WQ_MAX_ITEMS, "");
static_assert(sizeof(mt_wq_stats_t::runs) == 8u && sizeof(mt_wq_stats_t::merged) == 4u, "");
static_assert(MT_WQ_TIMER_OFF == 0u && MT_WQ_TIMER_ONCE == 1u && MT_WQ_TIMER_EVERY == 2u, "");
static_assert(MT_WQ_SHOT_NONE == 0u && MT_WQ_SHOT_ARMED == 1u && MT_WQ_SHOT_RUN == 2u &&
                  MT_WQ_SHOT_DONE == 3u,
              "");
static_assert(MT_WQ_NONE == 0xFFFFFFFFu, "");
static_assert(std::is_same<decltype(&mt_work_notify_i), void (*)(void *)>::value,
              "a publish callback shape");
static_assert(std::is_same<decltype(&mt_wq_timer_proc), mt_proc_fn_t>::value, "a proc");
static_assert(std::is_same<decltype(&mt_wq_thread_body), mt_thread_fn_t>::value, "a thread body");
static_assert(MT_CFG_BUS_MAX_MSG == 256u && MT_CFG_BUS_MAX_QUEUE == 16u, "");
static_assert(MT_CFG_BUS_MAX_NOTIFY == 4u && MT_CFG_BUS_MAX_RELIABLE == 2u, "");
static_assert(MT_CFG_BUS_COPY_TRIES == 3u, "");

// mission commands: 32 bytes, no padding
static_assert(sizeof(mt_mission_cmd_t) == 32u, "");
static_assert(std::is_standard_layout<mt_mission_t>::value, "C layout");

// rings: producer and consumer halves on separate cache lines
static_assert(std::is_standard_layout<mt_bring_t>::value, "C layout");
static_assert(std::is_standard_layout<mt_oring_t>::value, "C layout");
#if MT_CFG_CACHE_LINE > 0
static_assert(offsetof(mt_bring_t, head) == MT_CFG_CACHE_LINE, "consumer half on its own line");
static_assert(offsetof(mt_bring_t, buf) == 2u * MT_CFG_CACHE_LINE, "constants after both halves");
static_assert(offsetof(mt_oring_t, head) == MT_CFG_CACHE_LINE, "consumer half on its own line");
static_assert(offsetof(mt_oring_t, buf) == 2u * MT_CFG_CACHE_LINE, "constants after both halves");
#endif
static_assert(sizeof(mt_bring_t::tail) == 4u, "32-bit indices");
static_assert(MT_BRING_CAP_MAX == 0x40000000u && MT_ORING_BYTES_MAX == 0x40000000u, "");
static_assert(MT_ORING_STORAGE_BYTES(4, 3) == 16u, "cap + 1 slots");

// time and scheduler types: 64-bit where the kernel promises it
static_assert(sizeof(mt_time_ext_t) == 16u, "");
static_assert(sizeof(mt_time_ext_t::ticks) == 8u, "");
static_assert(sizeof(mt_sched_t::tick) == 8u, "S-4/S-12: 64-bit ticks");
static_assert(sizeof(mt_task_state_t::interval) == 4u, "S-4: 32-bit intervals");
static_assert(sizeof(mt_task_state_t::max_us) == 4u, "S-7: 32-bit run times");
static_assert(sizeof(mt_task_t::rate_mhz) == 4u, "");
static_assert(MT_HZ(50) == 50000u && MT_HZ(2000) == 2000000u, "millihertz");
static_assert(MT_SCHED_RATE_MIN == 50u && MT_SCHED_RATE_MAX == 2000u, "");
static_assert(MT_SCHED_FAST_PRIO_LIMIT == 3u, "S-2: fast class is priority < 3");
static_assert(MT_SCHED_IDLE == -1 && MT_SCHED_WAIT_SAMPLE == -3, "ArduPilot breadcrumbs");
static_assert(MT_SCHED_EXTRA_MAX_US == 5000u && MT_SCHED_EXTRA_STEP_US == 100u &&
                  MT_SCHED_EXTRA_DECAY_US == 50u && MT_SCHED_CLEAN_LOOPS == 50u,
              "");

// port
static_assert(MT_WAIT_FOREVER == UINT64_MAX, "");
static_assert(MT_PORT_RESUMED != MT_PORT_TIMEOUT, "");
static_assert(MT_PRIO_IO == 0 && MT_PRIO_TIMER == 7 && MT_PRIO_BASE_COUNT == 9, "");
static_assert(std::is_same<mt_port_tref_t, void *>::value, "");
static_assert(sizeof(mt_sem_t::token) == 4u, "");

// function types keep C signatures
static_assert(std::is_same<decltype(&mt_sched_loop_once),
                           void (*)(mt_sched_t *, mt_sample_wait_fn_t, void *)>::value,
              "");
static_assert(std::is_same<decltype(&mt_posix_metronome_wait), uint64_t (*)(void *)>::value,
              "the metronome is a sample-wait function");
static_assert(std::is_same<mt_sample_wait_fn_t, uint64_t (*)(void *)>::value, "");

TEST(CxxHeaders, CLinkageCallsWork)
{
    // a call through each header proves the symbols link with C linkage
    EXPECT_STREQ(mt_status_str(MT_E_BUSY), "MT_E_BUSY");
    mt_time_ext_t t;
    EXPECT_EQ(mt_time_ext_init(&t, 0xFFFFu, 0u), MT_OK);
    EXPECT_EQ(mt_time_ticks_to_us(1000u, 1000u), 1000000u);
    uint8_t buf[4];
    mt_bring_t r;
    EXPECT_EQ(mt_bring_init(&r, buf, 4u), MT_OK);
    mt_sem_t s;
    mt_sem_init(&s, true);
    EXPECT_EQ(s.token, 1u);
    mt_proc_set_t p;
    mt_proc_set_init(&p);
    EXPECT_EQ(p.count, 0u);
    static mt_wq_t q;
    mt_wq_init(&q, "cxx", MT_PRIO_IO, 0);
    EXPECT_EQ(q.nitems, 0u);
}

} // namespace
