/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file smoke_canary.c
 * @brief Smoke-test canaries: contradictions that WP's smoke tests must find with the
 *        project's prover configuration (proofs/proofs.mk, proofs/wp/why3.conf).
 *
 * Every function named canary_* carries one seeded contradiction (in its requires, a
 * behaviour's assumes, or a branch its precondition or a callee's contract excludes): `make
 * wp-canary` fails unless at least one smoke test of each is reported failed. The control_*
 * functions are consistent: all their goals must be proved and all their smoke tests must
 * pass. The expected outcome and the kind of each function are declared once, in the table
 * EXPECT of proofs/wp/canary/check.py; a function missing there (or here) fails the canary.
 *
 * The canary is not kernel code; it shows that the smoke-test settings (time limit, provers)
 * still catch what they are there to catch. Its shapes are those of the kernel's contracts:
 * tables with quantified facts (a count and an array of values or of structs), struct fields,
 * pointer validity, non-linear arithmetic, ordered arrays, quotients and remainders, and the
 * port's ghost state through the port's own declarations (kernel/port/mt_port.h and
 * kernel/spec/mt_spec.h: the ghost lock MtLocked with MtLockHeld/MtUnlocked, the ghost clock
 * MtPortNow and the contract of mt_port_now_us()). Each new kind of contract shape gets a
 * canary and a control of the same shape.
 */
#include <stdint.h>

#include "mt_port.h"

#define CANARY_N 8u

typedef struct {
    uint32_t n;
    uint32_t a[CANARY_N];
} canary_tab_t;

/*@ predicate CanaryPos(canary_tab_t *t) =
        t->n <= CANARY_N && \forall integer i; 0 <= i < t->n ==> t->a[i] > 0;
    predicate CanarySorted(canary_tab_t *t) =
        t->n <= CANARY_N && \forall integer i, j; 0 <= i <= j < t->n ==> t->a[i] <= t->a[j];
*/

#define CANARY_TASKS 8u
#define CANARY_FAST_PRIO 3u

/* A task table: an array of structs and its count (mt_task_t, MtTableOk in mt/sched.h). */
typedef struct {
    uint32_t rate_mhz;   /* 0 for a fast task */
    uint32_t budget_us;  /* >= 1 for a normal task */
    uint8_t priority;    /* < CANARY_FAST_PRIO: fast */
} canary_task_t;

typedef struct {
    uint32_t ntasks;
    canary_task_t tasks[CANARY_TASKS];
} canary_sched_t;

/* Recorded times, never later than the port's ghost clock (sched.c: start <= MtPortNow). */
typedef struct {
    uint64_t last_sample_us;
    uint64_t task_start_us;
    uint32_t period_us;
} canary_stamps_t;

/* Function classes (STYLE.md): `_i` functions run with the kernel lock held; the others
 * (plain) take it themselves, so they are called with it free. */
#define CANARY_CLASS_I 1u

/*@ predicate CanaryTaskOk(canary_task_t *t) =
        t->priority < CANARY_FAST_PRIO ? t->rate_mhz == 0
                                       : (t->rate_mhz >= 1 && t->budget_us >= 1);
    predicate CanaryTableOk(canary_sched_t *s) =
        1 <= s->ntasks <= CANARY_TASKS &&
        \forall integer i; 0 <= i < s->ntasks ==> CanaryTaskOk(&s->tasks[i]);
    predicate CanaryStampsPast(canary_stamps_t *s) =
        s->last_sample_us <= s->task_start_us && s->task_start_us <= MtPortNow;
    predicate CanaryClassLock(integer c) = c == CANARY_CLASS_I ? MtLockHeld : MtUnlocked;
*/

/* A quantified table fact against one entry. */
/*@ requires \valid(t) && CanaryPos(t) && t->n >= 3 && t->a[2] == 0;
    assigns \nothing;
*/
uint32_t canary_quantified(const canary_tab_t *t)
{
    return t->n;
}

/* An ordering fact against two entries (two instantiations and a transitive step). */
/*@ requires \valid(t) && CanarySorted(t) && t->n == 5 && t->a[1] > t->a[3];
    assigns \nothing;
*/
uint32_t canary_sorted(const canary_tab_t *t)
{
    return t->a[0];
}

/* Non-linear arithmetic. */
/*@ requires x * y == 7 && x == 2;
    assigns \nothing;
*/
uint32_t canary_nonlinear(uint32_t x, uint32_t y)
{
    return x ^ y;
}

/* Memory model: a valid null pointer. */
/*@ requires \valid(p) && p == \null;
    assigns \nothing;
*/
uint32_t canary_null(const uint32_t *p)
{
    return (p != 0) ? 1u : 0u;
}

/* Struct fields and sums. */
/*@ requires \valid(t) && CanaryPos(t) && t->n == 2 && t->a[0] + t->a[1] == 1;
    assigns \nothing;
*/
uint32_t canary_sum(const canary_tab_t *t)
{
    return t->a[0];
}

/* A defensive branch that the precondition excludes (dead code). */
/*@ requires x < 10;
    assigns \nothing;
    ensures \result == x;
*/
uint32_t canary_dead_branch(uint32_t x)
{
    uint32_t r = x;

    if (x > 20u) {
        r = 0u;
    }
    return r;
}

/* A behaviour whose assumes cannot hold. */
/*@ requires x <= 100;
    assigns \nothing;
    behavior small:
      assumes x < 50;
      ensures \result == x;
    behavior empty:
      assumes x > 60 && x < 55;
      ensures \result == 0;
    behavior big:
      assumes x >= 50;
      ensures \result == x;
*/
uint32_t canary_empty_behavior(uint32_t x)
{
    return x;
}

/* A quantified invariant over a table of structs against one entry: a normal task (priority
 * 5) with no budget. */
/*@ requires valid: \valid_read(s);
    requires table: CanaryTableOk(s);
    requires entry: s->ntasks == 4 && s->tasks[2].priority == 5 && s->tasks[2].budget_us == 0;
    assigns \nothing;
*/
uint32_t canary_task_table(const canary_sched_t *s)
{
    return s->tasks[s->ntasks - 1u].budget_us;
}

/* Modulo: a deadline on the period grid (mt_proc_period_next's `grid`) that is one past a
 * multiple of the period. */
/*@ requires period: p >= 2;
    requires grid: (d - base) % p == 0;
    requires off_grid: d == base + (integer)p * k + 1;
    assigns \nothing;
*/
uint64_t canary_grid(uint64_t d, uint64_t base, uint32_t p, uint32_t k)
{
    return d - base;
}

/* Quotient: a rounded-down quotient (mt_time_ticks_to_us) whose product exceeds the dividend. */
/*@ requires divisor: b >= 1;
    requires quotient: q == a / b;
    requires too_big: q * b > a;
    assigns \nothing;
*/
uint64_t canary_quotient(uint64_t a, uint32_t b, uint64_t q)
{
    return q;
}

/* Ghost state: a task that started one period after a sample taken at the ghost clock's
 * current value, although no recorded time is later than the ghost clock. */
/*@ requires valid: \valid_read(s);
    requires past: CanaryStampsPast(s);
    requires period: s->period_us >= 1;
    requires next: s->task_start_us == s->last_sample_us + s->period_us;
    requires now: s->last_sample_us == MtPortNow;
    assigns \nothing;
*/
uint64_t canary_ghost_stamp(const canary_stamps_t *s)
{
    return s->task_start_us;
}

/* The port's ghost lock: an `_i` function (lock held) whose class rule, through the port's
 * predicates, also says "not held". */
/*@ requires held: MtLockHeld;
    requires class: CanaryClassLock(c) && c != CANARY_CLASS_I;
    assigns MtLocked;
*/
void canary_lock_class(uint32_t c)
{
    mt_port_unlock();
    mt_port_lock();
}

/* The port's clock (task context): a second reading earlier than the first, although
 * mt_port_now_us() is monotonic by its contract (a defensive branch the contract excludes). */
/*@ requires not_held: MtUnlocked;
    assigns MtPortNow;
*/
uint64_t canary_clock_backwards(void)
{
    uint64_t t0 = mt_port_now_us();
    uint64_t t1 = mt_port_now_us();

    if (t1 < t0) {
        return 0u;
    }
    return t1 - t0;
}

/* Controls: consistent contracts over the same shapes; every goal and smoke test must pass.
 * Each kind of contract shape seeded above has one (checked by EXPECT in check.py). */
/*@ requires \valid(t) && CanaryPos(t) && t->n >= 1;
    assigns \nothing;
    ensures \result > 0;
*/
uint32_t control_positive(const canary_tab_t *t)
{
    return t->a[0];
}

/*@ requires \valid(t) && CanarySorted(t) && t->n == 5;
    assigns \nothing;
    ensures \result <= t->a[4];
*/
uint32_t control_sorted(const canary_tab_t *t)
{
    return t->a[1];
}

/*@ requires \valid(t) && CanaryPos(t);
    assigns \nothing;
    ensures \result <= t->n;
*/
uint32_t control_loop(const canary_tab_t *t)
{
    uint32_t i;
    uint32_t k = 0u;

    /*@ loop invariant 0 <= i <= t->n && k <= i;
        loop assigns i, k;
        loop variant t->n - i;
    */
    for (i = 0u; i < t->n; i++) {
        if (t->a[i] > 1u) {
            k++;
        }
    }
    return k;
}

/* The task table without the bad entry: a normal task's budget is positive. */
/*@ requires valid: \valid_read(s);
    requires table: CanaryTableOk(s);
    requires normal: s->tasks[s->ntasks - 1].priority >= CANARY_FAST_PRIO;
    assigns \nothing;
    ensures budget: \result >= 1;
*/
uint32_t control_task_table(const canary_sched_t *s)
{
    return s->tasks[s->ntasks - 1u].budget_us;
}

/* A deadline on the period grid. */
/*@ requires period: p >= 2;
    requires grid: (d - base) % p == 0;
    requires on_grid: d == base + (integer)p * k;
    assigns \nothing;
    ensures grid: \result % p == 0;
*/
uint64_t control_grid(uint64_t d, uint64_t base, uint32_t p, uint32_t k)
{
    return d - base;
}

/* A rounded-down quotient. */
/*@ requires divisor: b >= 1;
    requires quotient: q == a / b;
    requires below: q * b <= a;
    assigns \nothing;
    ensures quotient: \result == q;
*/
uint64_t control_quotient(uint64_t a, uint32_t b, uint64_t q)
{
    return a / b;
}

/* Recorded times at or before the ghost clock. */
/*@ requires valid: \valid_read(s);
    requires past: CanaryStampsPast(s);
    requires period: s->period_us >= 1;
    requires next: s->task_start_us == s->last_sample_us + s->period_us;
    assigns \nothing;
    ensures age: \result <= MtPortNow - s->last_sample_us;
*/
uint64_t control_ghost_stamp(const canary_stamps_t *s)
{
    return s->task_start_us - s->last_sample_us;
}

/* An `_i` function that drops the lock for a moment (the port's contracts on both calls). */
/*@ requires held: MtLockHeld;
    requires class: CanaryClassLock(c) && c == CANARY_CLASS_I;
    assigns MtLocked;
    ensures held: MtLockHeld;
*/
void control_lock_class(uint32_t c)
{
    mt_port_unlock();
    mt_port_lock();
}

/* Two readings of the port's clock (task context): the elapsed time needs no saturation. */
/*@ requires not_held: MtUnlocked;
    assigns MtPortNow;
    ensures elapsed: \result <= MtPortNow - \old(MtPortNow);
*/
uint64_t control_clock_elapsed(void)
{
    uint64_t t0 = mt_port_now_us();
    uint64_t t1 = mt_port_now_us();

    return t1 - t0;
}
