/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/config.h
 * @brief Metronome build-time configuration: size options with defaults and checks.
 *
 * Every option may be overridden with -D on the compiler command line (or by a
 * header given as MT_CFG_USER_HEADER). Out-of-range values stop the build.
 * The configurations that are proved are listed in README.md ("Assurance").
 */
#ifndef MT_CONFIG_H
#define MT_CONFIG_H

#if defined(MT_CFG_USER_HEADER)
#include MT_CFG_USER_HEADER
#endif

/** Version stamp of the configuration interface. */
#define MT_CFG_VERSION 1

/** Maximum number of tasks in one scheduler table (the scheduler keeps one
 *  state record per task). */
#if !defined(MT_CFG_SCHED_MAX_TASKS)
#define MT_CFG_SCHED_MAX_TASKS 64u
#endif

/** Capacity of one timer or IO proc set (ArduPilot: 8). */
#if !defined(MT_CFG_PROC_MAX)
#define MT_CFG_PROC_MAX 8u
#endif

/** Size in bytes of the cache line that separates the producer and consumer
 *  halves of a ring. 0 packs the fields (parts without a data cache). */
#if !defined(MT_CFG_CACHE_LINE)
#define MT_CFG_CACHE_LINE 64u
#endif

/** Capacity in words of every word ring (mt/wordring.h): compile-time, so its index
 *  arithmetic folds to constants. Each ring keeps MT_CFG_WRING_CAP + 1 words. */
#if !defined(MT_CFG_WRING_CAP)
#define MT_CFG_WRING_CAP 256u
#endif

/** Capacity of the mission command list, home (index 0) included (ArduPilot:
 *  storage-dependent, 724 on a 16 KiB FRAM). Indices are 16-bit; the mission
 *  module keeps 39 bytes of RAM per command (see mt/mission.h). */
#if !defined(MT_CFG_MISSION_MAX_CMDS)
#define MT_CFG_MISSION_MAX_CMDS 700u
#endif

/** Commands the mission's nav advance may visit beyond the command count before it gives
 *  up and completes the mission: room for nav starts refused inside a loop (ArduPilot's
 *  advance gives up after 255 commands in all). */
#if !defined(MT_CFG_MISSION_ADVANCE_EXTRA)
#define MT_CFG_MISSION_ADVANCE_EXTRA 255u
#endif

/** Items one work queue holds (mt/wq.h): the FIFO, the timers and the
 *  statistics are one slot record per item (112 bytes on Cortex-M4). */
#if !defined(MT_CFG_WQ_MAX_ITEMS)
#define MT_CFG_WQ_MAX_ITEMS 16u
#endif

/** Topic bus: largest message in bytes (uORB's largest messages are a few hundred
 *  bytes). A copy of one message is the longest stretch a subscriber spends in its
 *  lock-free copy loop. */
#if !defined(MT_CFG_BUS_MAX_MSG)
#define MT_CFG_BUS_MAX_MSG 256u
#endif

/** Topic bus: longest message queue of one topic (uORB's command topics use 8). Each
 *  topic keeps one 32-bit stamp per possible slot. */
#if !defined(MT_CFG_BUS_MAX_QUEUE)
#define MT_CFG_BUS_MAX_QUEUE 16u
#endif

/** Topic bus: notifiers per topic (poll wake-ups and gated callbacks such as the work
 *  queue's subscription callback). */
#if !defined(MT_CFG_BUS_MAX_NOTIFY)
#define MT_CFG_BUS_MAX_NOTIFY 4u
#endif

/** Topic bus: reliable subscribers per reliable topic (a publish that would overwrite a
 *  message one of them has not consumed is refused). */
#if !defined(MT_CFG_BUS_MAX_RELIABLE)
#define MT_CFG_BUS_MAX_RELIABLE 2u
#endif

/** Topic bus: attempts of one lock-free copy before it gives up with MT_E_BUS_TORN (each
 *  failed attempt saw the slot overwritten by a publisher while it copied). */
#if !defined(MT_CFG_BUS_COPY_TRIES)
#define MT_CFG_BUS_COPY_TRIES 3u
#endif

#if (MT_CFG_SCHED_MAX_TASKS < 1u) || (MT_CFG_SCHED_MAX_TASKS > 255u)
#error "MT_CFG_SCHED_MAX_TASKS must be in [1, 255]"
#endif
#if (MT_CFG_PROC_MAX < 1u) || (MT_CFG_PROC_MAX > 64u)
#error "MT_CFG_PROC_MAX must be in [1, 64]"
#endif
#if (MT_CFG_CACHE_LINE != 0u) && (MT_CFG_CACHE_LINE != 32u) && (MT_CFG_CACHE_LINE != 64u) && \
    (MT_CFG_CACHE_LINE != 128u)
#error "MT_CFG_CACHE_LINE must be 0, 32, 64 or 128"
#endif
#if (MT_CFG_WRING_CAP < 1u) || (MT_CFG_WRING_CAP > 0x1000000u)
#error "MT_CFG_WRING_CAP must be in [1, 2^24]"
#endif

#if (MT_CFG_MISSION_MAX_CMDS < 2u) || (MT_CFG_MISSION_MAX_CMDS > 32766u)
#error "MT_CFG_MISSION_MAX_CMDS must be in [2, 32766]"
#endif
#if (MT_CFG_MISSION_ADVANCE_EXTRA < 1u) || (MT_CFG_MISSION_ADVANCE_EXTRA > 65535u)
#error "MT_CFG_MISSION_ADVANCE_EXTRA must be in [1, 65535]"
#endif

#if (MT_CFG_WQ_MAX_ITEMS < 1u) || (MT_CFG_WQ_MAX_ITEMS > 64u)
#error "MT_CFG_WQ_MAX_ITEMS must be in [1, 64]"
#endif
#if (MT_CFG_BUS_MAX_MSG < 1u) || (MT_CFG_BUS_MAX_MSG > 65536u)
#error "MT_CFG_BUS_MAX_MSG must be in [1, 65536]"
#endif
#if (MT_CFG_BUS_MAX_QUEUE < 1u) || (MT_CFG_BUS_MAX_QUEUE > 1024u)
#error "MT_CFG_BUS_MAX_QUEUE must be in [1, 1024]"
#endif
#if (MT_CFG_BUS_MAX_NOTIFY < 1u) || (MT_CFG_BUS_MAX_NOTIFY > 64u)
#error "MT_CFG_BUS_MAX_NOTIFY must be in [1, 64]"
#endif
#if (MT_CFG_BUS_MAX_RELIABLE < 1u) || (MT_CFG_BUS_MAX_RELIABLE > 64u)
#error "MT_CFG_BUS_MAX_RELIABLE must be in [1, 64]"
#endif
#if (MT_CFG_BUS_COPY_TRIES < 1u) || (MT_CFG_BUS_COPY_TRIES > 64u)
#error "MT_CFG_BUS_COPY_TRIES must be in [1, 64]"
#endif

#endif /* MT_CONFIG_H */
