/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/mt.h
 * @brief Umbrella header of the Metronome kernel.
 */
#ifndef MT_MT_H
#define MT_MT_H

#include "mt/bus.h"
#include "mt/bus_sub.h"
#include "mt/config.h"
#include "mt/mission.h"
#include "mt/objring.h"
#include "mt/proc.h"
#include "mt/ring.h"
#include "mt/sched.h"
#include "mt/sem.h"
#include "mt/status.h"
#include "mt/time.h"
#include "mt/wordring.h"
#include "mt/wq.h"
#include "mt/wq_timer.h"
#include "mt_port.h"

#endif /* MT_MT_H */
