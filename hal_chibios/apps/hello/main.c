/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Metronome - ChibiOS smoke application.
 *
 * Two threads hand a token back and forth through two binary semaphores
 * HANDOFFS times, sleeping 1 ms at each step. main() waits for both, prints
 * "hello ok ticks=<n>" and ends the run with success. Built with FAIL=1
 * (FW_FAIL) it calls chSysHalt() instead, which must end the run with a
 * failure status.
 */
#include "ch.h"
#include "fw_board.h"

#define HANDOFFS 100U

static binary_semaphore_t ping;   /* pinger -> ponger */
static binary_semaphore_t pong;   /* ponger -> pinger */
static volatile uint32_t ping_count;
static volatile uint32_t pong_count;

static THD_WORKING_AREA(wa_pinger, 512);
static THD_WORKING_AREA(wa_ponger, 512);

static THD_FUNCTION(pinger, arg) {
  uint32_t i;

  (void)arg;
  chRegSetThreadName("pinger");
  for (i = 0U; i < HANDOFFS; i++) {
    chThdSleepMilliseconds(1);
    ping_count++;
    chBSemSignal(&ping);
    if (chBSemWait(&pong) != MSG_OK) {
      chSysHalt("hello: pong wait failed");
    }
  }
}

static THD_FUNCTION(ponger, arg) {
  uint32_t i;

  (void)arg;
  chRegSetThreadName("ponger");
  for (i = 0U; i < HANDOFFS; i++) {
    if (chBSemWait(&ping) != MSG_OK) {
      chSysHalt("hello: ping wait failed");
    }
    pong_count++;
    chThdSleepMilliseconds(1);
    chBSemSignal(&pong);
  }
}

int main(void) {
  thread_t *tp1;
  thread_t *tp2;
  systime_t start;
  sysinterval_t elapsed;

  fw_board_init();
  chSysInit();

  chBSemObjectInit(&ping, true);
  chBSemObjectInit(&pong, true);

  start = chVTGetSystemTime();
  tp1 = chThdCreateStatic(wa_pinger, sizeof(wa_pinger), NORMALPRIO + 1,
                          pinger, NULL);
  tp2 = chThdCreateStatic(wa_ponger, sizeof(wa_ponger), NORMALPRIO + 1,
                          ponger, NULL);
  (void)chThdWait(tp1);
  (void)chThdWait(tp2);
  elapsed = chTimeDiffX(start, chVTGetSystemTime());

  if ((ping_count != HANDOFFS) || (pong_count != HANDOFFS)) {
    chSysHalt("hello: handoff count mismatch");
  }

#if defined(FW_FAIL)
  chSysHalt("hello: deliberate failure (FAIL=1)");
#endif

  fw_puts("hello ok ticks=");
  fw_put_u32((uint32_t)elapsed);
  fw_puts("\r\n");
  fw_exit(FW_EXIT_SUCCESS);
}
