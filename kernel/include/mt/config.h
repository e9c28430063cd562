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

/** Capacity of the mission command list, home (index 0) included (ArduPilot:
 *  storage-dependent, 724 on a 16 KiB FRAM). Indices are 16-bit; the mission
 *  module keeps 39 bytes of RAM per command (see mt/mission.h). */
#if !defined(MT_CFG_MISSION_MAX_CMDS)
#define MT_CFG_MISSION_MAX_CMDS 700u
#endif

/** Items one work queue holds (mt/wq.h): the FIFO, the timers and the
 *  statistics are one slot record per item (112 bytes on Cortex-M4). */
#if !defined(MT_CFG_WQ_MAX_ITEMS)
#define MT_CFG_WQ_MAX_ITEMS 16u
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

#if (MT_CFG_MISSION_MAX_CMDS < 2u) || (MT_CFG_MISSION_MAX_CMDS > 32766u)
#error "MT_CFG_MISSION_MAX_CMDS must be in [2, 32766]"
#endif

#if (MT_CFG_WQ_MAX_ITEMS < 1u) || (MT_CFG_WQ_MAX_ITEMS > 64u)
#error "MT_CFG_WQ_MAX_ITEMS must be in [1, 64]"
#endif

#endif /* MT_CONFIG_H */
