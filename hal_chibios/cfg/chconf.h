/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Metronome - ChibiOS/RT 7.0 kernel configuration shared by all firmware
 * boards in hal_chibios/.
 *
 * RT 7 refuses to build unless every option below is defined, so nothing is
 * left to defaults. The smart build of rt.mk greps this file for
 * "#define CH_CFG_USE_xxx TRUE": keep each option on one "#define" line.
 */
#ifndef CHCONF_H
#define CHCONF_H

#define _CHIBIOS_RT_CONF_
#define _CHIBIOS_RT_CONF_VER_7_0_

/* ---- System timer: periodic 1 kHz tick (tickless did not wake sleepers
 *      under QEMU 7.2). ------------------------------------------------- */
#define CH_CFG_SMP_MODE                     FALSE
/* Counter width: 32 bits; the wrap test builds 16 (-D both options). */
#if !defined(CH_CFG_ST_RESOLUTION)
#define CH_CFG_ST_RESOLUTION                32
#endif
/* Tick rate: 1 kHz; an app may raise it with -D (both C and assembler, see
 * mk/firmware.mk): the vehicle uses 2 kHz so that its 400 Hz samples fall on
 * tick edges. */
#if !defined(CH_CFG_ST_FREQUENCY)
#define CH_CFG_ST_FREQUENCY                 1000
#endif
#if !defined(CH_CFG_INTERVALS_SIZE)
#define CH_CFG_INTERVALS_SIZE               32
#endif
#define CH_CFG_TIME_TYPES_SIZE              32
#define CH_CFG_ST_TIMEDELTA                 0

/* ---- Scheduler. ----------------------------------------------------- */
/* No round robin: equal-priority threads only switch when one blocks. */
#define CH_CFG_TIME_QUANTUM                 0
#define CH_CFG_NO_IDLE_THREAD               FALSE
#define CH_CFG_OPTIMIZE_SPEED               TRUE

/* ---- RT subsystems. ------------------------------------------------- */
#define CH_CFG_USE_TM                       FALSE
#define CH_CFG_USE_TIMESTAMP                FALSE
#define CH_CFG_USE_REGISTRY                 TRUE
#define CH_CFG_USE_WAITEXIT                 TRUE
#define CH_CFG_USE_SEMAPHORES               TRUE
#define CH_CFG_USE_SEMAPHORES_PRIORITY      FALSE
#define CH_CFG_USE_MUTEXES                  TRUE
#define CH_CFG_USE_MUTEXES_RECURSIVE        FALSE
#define CH_CFG_USE_CONDVARS                 TRUE
#define CH_CFG_USE_CONDVARS_TIMEOUT         TRUE
#define CH_CFG_USE_EVENTS                   TRUE
#define CH_CFG_USE_EVENTS_TIMEOUT           TRUE
#define CH_CFG_USE_MESSAGES                 FALSE
#define CH_CFG_USE_MESSAGES_PRIORITY        FALSE
#define CH_CFG_USE_DYNAMIC                  FALSE

/* ---- OSLIB: only the core allocator is kept (small, and available to
 *      the port later); no heap, pools, FIFOs, pipes, jobs or factory. -- */
#define CH_CFG_USE_MAILBOXES                FALSE
#define CH_CFG_USE_MEMCORE                  TRUE
#define CH_CFG_MEMCORE_SIZE                 0
#define CH_CFG_USE_HEAP                     FALSE
#define CH_CFG_USE_MEMPOOLS                 FALSE
#define CH_CFG_USE_OBJ_FIFOS                FALSE
#define CH_CFG_USE_PIPES                    FALSE
#define CH_CFG_USE_OBJ_CACHES               FALSE
#define CH_CFG_USE_DELEGATES                FALSE
#define CH_CFG_USE_JOBS                     FALSE
#define CH_CFG_USE_FACTORY                  FALSE
#define CH_CFG_FACTORY_MAX_NAMES_LENGTH     8
#define CH_CFG_FACTORY_OBJECTS_REGISTRY     FALSE
#define CH_CFG_FACTORY_GENERIC_BUFFERS      FALSE
#define CH_CFG_FACTORY_SEMAPHORES           FALSE
#define CH_CFG_FACTORY_MAILBOXES            FALSE
#define CH_CFG_FACTORY_OBJ_FIFOS            FALSE
#define CH_CFG_FACTORY_PIPES                FALSE

/* ---- Debug. Checks and asserts are on: the smoke tests are meant to
 *      catch misuse of the RT API by the port. They can be turned off from
 *      the command line (UDEFS/UADEFS) for size measurements. ----------- */
#define CH_DBG_STATISTICS                   FALSE
#if !defined(CH_DBG_SYSTEM_STATE_CHECK)
#define CH_DBG_SYSTEM_STATE_CHECK           TRUE
#endif
#if !defined(CH_DBG_ENABLE_CHECKS)
#define CH_DBG_ENABLE_CHECKS                TRUE
#endif
#if !defined(CH_DBG_ENABLE_ASSERTS)
#define CH_DBG_ENABLE_ASSERTS               TRUE
#endif
#define CH_DBG_TRACE_MASK                   CH_DBG_TRACE_MASK_DISABLED
#define CH_DBG_TRACE_BUFFER_SIZE            128
#if !defined(CH_DBG_ENABLE_STACK_CHECK)
#define CH_DBG_ENABLE_STACK_CHECK           TRUE
#endif
#define CH_DBG_FILL_THREADS                 TRUE
#define CH_DBG_THREADS_PROFILING            FALSE

/* ---- Hooks. --------------------------------------------------------- */
#define CH_CFG_SYSTEM_EXTRA_FIELDS          /* none */
#define CH_CFG_SYSTEM_INIT_HOOK()           do { } while (0)
#define CH_CFG_OS_INSTANCE_EXTRA_FIELDS     /* none */
#define CH_CFG_OS_INSTANCE_INIT_HOOK(oip)   do { (void)(oip); } while (0)
#define CH_CFG_THREAD_EXTRA_FIELDS          /* none */
#define CH_CFG_THREAD_INIT_HOOK(tp)         do { (void)(tp); } while (0)
#define CH_CFG_THREAD_EXIT_HOOK(tp)         do { (void)(tp); } while (0)
#define CH_CFG_CONTEXT_SWITCH_HOOK(ntp, otp) do { (void)(ntp); (void)(otp); } while (0)
#define CH_CFG_IRQ_PROLOGUE_HOOK()          do { } while (0)
#define CH_CFG_IRQ_EPILOGUE_HOOK()          do { } while (0)
#define CH_CFG_IDLE_ENTER_HOOK()            do { } while (0)
#define CH_CFG_IDLE_LEAVE_HOOK()            do { } while (0)
#define CH_CFG_IDLE_LOOP_HOOK()             do { } while (0)
#define CH_CFG_SYSTEM_TICK_HOOK()           do { } while (0)
/* A halt (chSysHalt, failed assert or check) prints its reason on the
 * console and ends the run with a failure status (fw_common.c). */
#define CH_CFG_SYSTEM_HALT_HOOK(reason)     fw_halt_hook(reason)
#define CH_CFG_TRACE_HOOK(tep)              do { (void)(tep); } while (0)
#define CH_CFG_RUNTIME_FAULTS_HOOK(mask)    do { (void)(mask); } while (0)

#if !defined(_FROM_ASM_)
#ifdef __cplusplus
extern "C" {
#endif
void fw_halt_hook(const char *reason);
#ifdef __cplusplus
}
#endif
#endif /* !_FROM_ASM_ */

#endif /* CHCONF_H */
