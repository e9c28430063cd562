/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Metronome - board-neutral firmware services used by the apps and, later,
 * by the kernel port. Each board in hal_chibios/boards/ implements the
 * fw_board_* / fw_putc / fw_exit part; fw_common.c implements the rest.
 */
#ifndef FW_BOARD_H
#define FW_BOARD_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Exit statuses for fw_exit(). */
#define FW_EXIT_SUCCESS 0
#define FW_EXIT_FAILURE 1

/*
 * Board bring-up, called from main() before chSysInit() with interrupts
 * still disabled: console, system tick source, HAL where there is one.
 */
void fw_board_init(void);

/* Polled console output; usable from any context, including faults. */
void fw_putc(char c);

/*
 * End the run. On the QEMU board this is a semihosting SYS_EXIT, so QEMU
 * exits 0 for FW_EXIT_SUCCESS and non-zero otherwise. On real boards it
 * uses semihosting only when a debugger is attached, and otherwise stops
 * with interrupts disabled.
 */
__attribute__((noreturn)) void fw_exit(int status);

/* Helpers from fw_common.c. */
void fw_puts(const char *s);
void fw_put_u32(uint32_t v);
void fw_put_hex32(uint32_t v);

/* Semihosting SYS_EXIT with an ADP_Stopped_* reason code. */
__attribute__((noreturn)) void fw_semihost_exit(int status);

/* RT halt hook (see CH_CFG_SYSTEM_HALT_HOOK in cfg/chconf.h). */
void fw_halt_hook(const char *reason);

#ifdef __cplusplus
}
#endif

#endif /* FW_BOARD_H */
