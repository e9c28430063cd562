/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file mt/status.h
 * @brief The one status enum of the kernel.
 *
 * Every value is distinct and explicit; the list ends with a count sentinel.
 * A status reports bad input or a full/empty/busy condition to the caller.
 * Caller bugs (NULL pointers, wrong lock state) are contract violations, not
 * statuses: they halt through the port in checked builds.
 */
#ifndef MT_STATUS_H
#define MT_STATUS_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    MT_OK = 0,               /**< Done. */
    MT_E_INVALID = 1,        /**< An argument value is outside its documented range. */
    MT_E_FULL = 2,           /**< No room: a ring, a proc set or a table is full. */
    MT_E_EMPTY = 3,          /**< Nothing to read. */
    MT_E_DUPLICATE = 4,      /**< The same entry is already registered. */
    MT_E_TIMEOUT = 5,        /**< A wait ended without the event. */
    MT_E_BUSY = 6,           /**< The object is in use (second waiter, re-entrant dispatch). */
    MT_E_RANGE = 7,          /**< A count exceeds what the object holds (advance, commit). */
    MT_E_TASK_ORDER = 8,     /**< Task table: priorities are not non-decreasing. */
    MT_E_TASK_RATE = 9,      /**< Task table: rate zero for a normal task, non-zero for a fast
                                  one, or above the loop rate. */
    MT_E_TASK_BUDGET = 10,   /**< Task table: zero budget on a normal task, or a budget longer
                                  than the loop period. */
    MT_E_TASK_COUNT = 11,    /**< Task table: no tasks, or more than MT_CFG_SCHED_MAX_TASKS. */
    MT_E_LOOP_RATE = 12,     /**< Scheduler: loop rate outside [MT_SCHED_RATE_MIN, MAX]. */
    MT_E_TASK_FN = 13,       /**< Task table: an entry has no function. */
    MT_W_DROPPED_OLDEST = 14, /**< Pushed into the spare slot of a ring that was full when the
                                   push looked: the consumer discards the oldest object unless
                                   it consumed it meanwhile; its `lost` counts actual drops. */
    MT_E_MISSION_CMD = 15,   /**< Mission: unknown or reserved command id, or index 0 (home) is
                                  not a waypoint. */
    MT_E_MISSION_PARAM = 16, /**< Mission: a parameter is outside its range, not an integer
                                  where one is needed, or NaN where NaN is not allowed. */
    MT_E_MISSION_LOCATION = 17, /**< Mission: latitude or longitude out of range. */
    MT_E_MISSION_FRAME = 18, /**< Mission: coordinate frame not supported for the command. */
    MT_E_MISSION_JUMP = 19,  /**< Mission: jump target outside [1, count), unknown jump tag,
                                  or repeat count outside {-1} and [0, 32767]. */
    MT_E_MISSION_LOOP = 20,  /**< Mission: a loop that contains no nav command (the do-only
                                  repeat lockup); reported at the first index on the loop
                                  or leading into it. */
    MT_E_MISSION_SIZE = 21,  /**< Mission: no home entry, or more than MT_CFG_MISSION_MAX_CMDS
                                  commands. */
    MT_E_MISSION_SYNTAX = 22, /**< Mission file: malformed line or field (file layer). */
    MT_E_STATE = 23,         /**< The operation is not allowed in the object's current state
                                  (mission running, stopped, complete). */
    MT_W_WQ_MERGED = 24,     /**< Work queue: the item was already queued; this activation
                                  merged into its pending run (counted in the item's and the
                                  queue's `merged`). */
    MT_E_BUS_MSG_SIZE = 25,  /**< Topic bus: message size 0 or above MT_CFG_BUS_MAX_MSG at init,
                                  or a publish/copy size that is not the topic's. */
    MT_E_BUS_QUEUE_LEN = 26, /**< Topic bus: queue length 0 or above MT_CFG_BUS_MAX_QUEUE. */
    MT_E_BUS_STORAGE = 27,   /**< Topic bus: storage NULL or smaller than
                                  MT_BUS_STORAGE_BYTES(msg_size, queue_len). */
    MT_E_BUS_BEHIND = 28,    /**< Topic bus: a reliable subscriber has not consumed the oldest
                                  queued message; nothing published (counted in `rejected`). */
    MT_E_BUS_TORN = 29,      /**< Topic bus: every copy attempt was overwritten by a publisher
                                  while it copied; nothing delivered (counted in `torn`). */
    MT_W_BUS_MISSED = 30,    /**< Topic bus: copied, but messages had left the queue before the
                                  subscriber reached them (counted in `missed`). */
    MT_STATUS_COUNT = 31     /**< Number of statuses (sentinel, not a status). */
} mt_status_t;

/** The status names, indexed by status ("MT_E_FULL" at MT_E_FULL); the entry at
 *  MT_STATUS_COUNT is "MT_STATUS_?", the name of every value that is not a status. */
extern const char *const mt_status_names[(int)MT_STATUS_COUNT + 1];

/** Short stable name of a status: its entry of mt_status_names. */
/*@ assigns \nothing;
    ensures named: \result == mt_status_names[0 <= st < MT_STATUS_COUNT ? st : MT_STATUS_COUNT];
*/
const char *mt_status_str(mt_status_t st);

#ifdef __cplusplus
}
#endif

#endif /* MT_STATUS_H */
