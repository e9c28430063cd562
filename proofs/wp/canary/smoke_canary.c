/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file smoke_canary.c
 * @brief Smoke-test canaries: contradictions that WP's smoke tests must find with the
 *        project's prover configuration (proofs/proofs.mk, proofs/wp/why3.conf).
 *
 * Every function named canary_* carries one contradiction (in its requires, a behaviour's
 * assumes, or a branch its precondition excludes): `make wp-canary` fails unless at least one
 * smoke test of each is reported failed. The control_* functions are consistent: all their
 * goals must be proved and all their smoke tests must pass. The canary is not kernel code; it
 * shows that the smoke-test settings (time limit, provers) still catch what they are there to
 * catch. Its types mirror the shapes the kernel's invariants use (tables with quantified
 * facts, struct fields, pointer validity, non-linear arithmetic, ordered arrays).
 */
#include <stdint.h>

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

/* Controls: consistent contracts over the same shapes; every goal and smoke test must pass. */
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
