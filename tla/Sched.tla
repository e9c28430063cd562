------------------------------- MODULE Sched -------------------------------
(***************************************************************************)
(* Tick scheduler (kernel/src/sched.c): the main-loop thread, one          *)
(* mt_sched_loop_once per tick, with nondeterministic sample latency and   *)
(* task run times. Nothing else writes the scheduler state, so the         *)
(* interleaving that matters is the one of ticks, run times and budgets.   *)
(*                                                                         *)
(* Actions and the C they abstract:                                        *)
(*  mt_sched_loop_once_tick   mt_sched_loop_once: wait(ctx) returns the    *)
(*                            sample, mt_sched_note_sample (statistics),   *)
(*                            mt_sched_tick (tick++), avail = max(0,       *)
(*                            period - (now - sample)) + extra_us          *)
(*  mt_sched_run_entry        mt_sched_run: if (run_tick == tick) return;  *)
(*                            run_tick = tick; start = now                 *)
(*  mt_sched_run_scan         one iteration of mt_sched_run's loop over    *)
(*                            task i: fast task -> run_task; normal: dt =  *)
(*                            tick - last_run, not due (dt < interval) ->  *)
(*                            continue, budget > avail -> budget_skips++,  *)
(*                            continue; else note_release(i, dt) (slips += *)
(*                            dt/iv - 1 when dt >= 2 iv; not_achieved,     *)
(*                            late_in_loop when dt >= 4 iv) and run_task   *)
(*                            (note_run: runs++, last_run = tick); then    *)
(*                            avail = time_available - (end - start)       *)
(*  mt_sched_run_again        a second mt_sched_run call in the same tick  *)
(*  mt_sched_end_loop         mt_sched_end_loop: extra_us += step when a   *)
(*                            task was late, decays after CleanLoops clean *)
(*                            loops; late_in_loop = 0                      *)
(*                                                                         *)
(* Simplifications:                                                        *)
(*  - Times are small integers (scaled microseconds); the task tables are  *)
(*    fixed below; intervals are given directly (mt_sched_init computes    *)
(*    interval = loop_rate * 1000 / rate_mhz, proved by WP).               *)
(*  - A task's run time is the wall time run_task measures, so pre-emption *)
(*    by other threads and gaps between tasks are folded into it.          *)
(*  - The adaptive extra time uses scaled constants (step 2, decay 1, cap  *)
(*    4, 2 clean loops; C: 100, 50, 5000 us, 50 loops); the slowdown       *)
(*    factor 4 is the C value.                                             *)
(*  - Statistics that decide nothing (min/max/total run time, overruns,    *)
(*    budget_skips, the spare-time window and load, loop statistics, the   *)
(*    breadcrumb `current`) are not modelled.                              *)
(*  - Ticks are bounded by MaxTick (the C tick is 64-bit and never wraps). *)
(***************************************************************************)
EXTENDS Naturals, Sequences, FiniteSets

CONSTANTS
    Table,            \* which task table (see Tables below): "fit" or "overload"
    MaxTick,          \* ticks explored
    DueOffByOne,      \* BROKEN: due only when tick - last_run > interval
    SlipsNotCounted,  \* BROKEN: note_release() does not add the slips
    NoRunTickGuard    \* BROKEN: mt_sched_run() lacks the run_tick == tick test

ASSUME /\ Table \in {"fit", "overload"} /\ MaxTick \in Nat \ {0}
       /\ DueOffByOne \in BOOLEAN /\ SlipsNotCounted \in BOOLEAN /\ NoRunTickGuard \in BOOLEAN

(* The task tables, in microsecond-like units scaled down. Fast tasks come  *)
(* first (priority < MT_SCHED_FAST_PRIO_LIMIT, rate 0, interval 1); the scan *)
(* is in table order. Exec[i] is the set of run times task i may take       *)
(* (measured wall time, so pre-emption and gaps are included).             *)
\* "fit": the budgets add up to the period minus the largest sample latency,
\* and no task overruns its budget.
\* "overload": the budgets do not fit, tasks overrun: slips, budget skips,
\* "not achieved" runs and the adaptive extra time all happen.
N == 4
Tasks == 1 .. N
Fast == IF Table = "fit" THEN <<TRUE, FALSE, FALSE, FALSE>> ELSE <<TRUE, FALSE, FALSE, FALSE>>
Interval == IF Table = "fit" THEN <<1, 1, 2, 3>> ELSE <<1, 1, 2, 3>>
Budget == IF Table = "fit" THEN <<2, 2, 3, 3>> ELSE <<0, 4, 5, 6>>
Exec == IF Table = "fit" THEN <<{1, 2}, {1, 2}, {2, 3}, {1, 3}>>
                         ELSE <<{1, 3}, {2, 5}, {3, 5}, {2, 6}>>
Period == IF Table = "fit" THEN 12 ELSE 10
Latency == IF Table = "fit" THEN {0, 2} ELSE {0, 3}   \* now - sample when run() starts

\* mt_sched.h constants, scaled (real: 4, 100, 50, 5000, 50)
Slowdown == 4
ExtraStep == 2
ExtraDecay == 1
ExtraMax == 4
CleanLoops == 2

Max(S) == CHOOSE x \in S : \A y \in S : y <= x
Sum(f, D) == LET F[E \in SUBSET D] == IF E = {} THEN 0
                                      ELSE LET x == CHOOSE y \in E : TRUE IN f[x] + F[E \ {x}]
             IN F[D]
\* The hypothesis of BoundedLateness: every task's budget fits in every tick.
FitsPeriod ==
    /\ Sum([i \in Tasks |-> IF Fast[i] /\ Budget[i] = 0 THEN Period ELSE Budget[i]], Tasks)
           + Max(Latency) <= Period
    /\ \A i \in Tasks : Max(Exec[i]) <= (IF Budget[i] = 0 THEN Period ELSE Budget[i])
LateK == 0

VARIABLES
    \* mt_sched_t
    tick, run_tick,
    last_run, runs, slips, not_achieved,  \* st[i]
    extra, clean_loops, late_in_loop,
    \* main loop locals
    pc,          \* "wait", "run", "scan", "end"
    tavail,      \* time_available_us passed to mt_sched_run
    elapsed,     \* end - start of the scan so far
    i,           \* scan index
    \* ghosts
    releases,    \* releases of each task so far
    ranThisTick  \* runs of each task in the current tick

vars == <<tick, run_tick, last_run, runs, slips, not_achieved, extra, clean_loops,
          late_in_loop, pc, tavail, elapsed, i, releases, ranThisTick>>

Init ==
    /\ tick = 0 /\ run_tick = 0
    /\ last_run = [t \in Tasks |-> 0] /\ runs = [t \in Tasks |-> 0]
    /\ slips = [t \in Tasks |-> 0] /\ not_achieved = [t \in Tasks |-> 0]
    /\ extra = 0 /\ clean_loops = 0 /\ late_in_loop = 0
    /\ pc = "wait" /\ tavail = 0 /\ elapsed = 0 /\ i = 1
    /\ releases = [t \in Tasks |-> 0] /\ ranThisTick = [t \in Tasks |-> 0]

-----------------------------------------------------------------------------
\* mt_sched_loop_once: wait for the sample, note it, mt_sched_tick(), then
\* avail = max(0, period - (now - sample)) + extra. A release of task t
\* happens every Interval[t] ticks after its last run.
mt_sched_loop_once_tick ==
    /\ pc = "wait" /\ tick < MaxTick
    /\ tick' = tick + 1
    /\ releases' = [t \in Tasks |-> IF (tick + 1 - last_run[t]) % Interval[t] = 0
                                    THEN releases[t] + 1 ELSE releases[t]]
    /\ ranThisTick' = [t \in Tasks |-> 0]
    /\ \E lat \in Latency : tavail' = (IF lat >= Period THEN 0 ELSE Period - lat) + extra
    /\ pc' = "run"
    /\ UNCHANGED <<run_tick, last_run, runs, slips, not_achieved, extra, clean_loops,
                   late_in_loop, elapsed, i>>

\* mt_sched_run: if (s->run_tick == s->tick) return avail; s->run_tick = s->tick.
mt_sched_run_entry ==
    /\ pc = "run"
    /\ IF run_tick = tick /\ ~NoRunTickGuard
       THEN pc' = "end" /\ UNCHANGED <<run_tick, elapsed, i>>
       ELSE pc' = "scan" /\ run_tick' = tick /\ elapsed' = 0 /\ i' = 1
    /\ UNCHANGED <<tick, last_run, runs, slips, not_achieved, extra, clean_loops,
                   late_in_loop, tavail, releases, ranThisTick>>

Avail == IF elapsed >= tavail THEN 0 ELSE tavail - elapsed

\* run_task() + note_run(): the task runs for e, then runs++, last_run = tick.
RunTask(e) ==
    /\ elapsed' = elapsed + e
    /\ runs' = [runs EXCEPT ![i] = @ + 1]
    /\ last_run' = [last_run EXCEPT ![i] = tick]
    /\ ranThisTick' = [ranThisTick EXCEPT ![i] = @ + 1]

\* One iteration of the scan loop over task i.
mt_sched_run_scan ==
    /\ pc = "scan" /\ i <= N
    /\ LET dt == tick - last_run[i]
           due == IF DueOffByOne THEN dt > Interval[i] ELSE dt >= Interval[i]
       IN IF Fast[i]
          THEN \* fast task: every tick, whatever is left
               /\ \E e \in Exec[i] : RunTask(e)
               /\ UNCHANGED <<slips, not_achieved, late_in_loop>>
          ELSE IF ~due \/ Budget[i] > Avail
          THEN \* not due, or due but does not fit (budget_skips++): stays due
               UNCHANGED <<elapsed, runs, last_run, ranThisTick, slips, not_achieved, late_in_loop>>
          ELSE \* note_release(s, i, dt), then run_task
               /\ slips' = [slips EXCEPT ![i] =
                              IF dt >= 2 * Interval[i] /\ ~SlipsNotCounted
                              THEN @ + (dt \div Interval[i]) - 1 ELSE @]
               /\ IF dt >= Slowdown * Interval[i]
                  THEN /\ not_achieved' = [not_achieved EXCEPT ![i] = @ + 1]
                       /\ late_in_loop' = late_in_loop + 1
                  ELSE UNCHANGED <<not_achieved, late_in_loop>>
               /\ \E e \in Exec[i] : RunTask(e)
    /\ i' = i + 1
    /\ pc' = IF i + 1 <= N THEN "scan" ELSE "end"
    /\ UNCHANGED <<tick, run_tick, extra, clean_loops, tavail, releases>>

\* mt_sched_end_loop: adaptive extra time (the spare-time window is statistics).
\* Or, before that, a second mt_sched_run in the same tick.
mt_sched_end_loop ==
    /\ pc = "end"
    /\ IF late_in_loop > 0
       THEN /\ extra' = IF extra + ExtraStep <= ExtraMax THEN extra + ExtraStep ELSE ExtraMax
            /\ clean_loops' = 0
       ELSE IF extra > 0
       THEN IF clean_loops + 1 > CleanLoops
            THEN /\ clean_loops' = 0
                 /\ extra' = IF extra > ExtraDecay THEN extra - ExtraDecay ELSE 0
            ELSE /\ clean_loops' = clean_loops + 1 /\ UNCHANGED extra
       ELSE /\ clean_loops' = 0 /\ UNCHANGED extra
    /\ late_in_loop' = 0
    /\ pc' = "wait" /\ elapsed' = 0 /\ i' = 1 /\ tavail' = 0
    /\ UNCHANGED <<tick, run_tick, last_run, runs, slips, not_achieved, releases, ranThisTick>>

mt_sched_run_again ==
    /\ pc = "end"
    /\ pc' = "run"
    /\ UNCHANGED <<tick, run_tick, last_run, runs, slips, not_achieved, extra, clean_loops,
                   late_in_loop, tavail, elapsed, i, releases, ranThisTick>>

\* After MaxTick ticks the exploration stops (stuttering, not a deadlock).
Done == pc = "wait" /\ tick = MaxTick /\ UNCHANGED vars

Next ==
    \/ mt_sched_loop_once_tick \/ mt_sched_run_entry \/ mt_sched_run_scan
    \/ mt_sched_end_loop \/ mt_sched_run_again \/ Done

Spec == Init /\ [][Next]_vars

-----------------------------------------------------------------------------
(* Invariants                                                              *)

TypeOK ==
    /\ tick \in 0 .. MaxTick /\ run_tick \in 0 .. tick
    /\ pc \in {"wait", "run", "scan", "end"} /\ i \in 1 .. N + 1
    /\ extra \in 0 .. ExtraMax /\ clean_loops \in 0 .. CleanLoops

\* MtSchedInv (the part about the run state).
SchedInv ==
    \A t \in Tasks : last_run[t] <= run_tick /\ runs[t] <= run_tick

\* No task runs twice in one tick (whatever calls mt_sched_run).
OncePerTick == \A t \in Tasks : ranThisTick[t] <= 1

\* Once the scan of a tick is over, every fast task has run in it.
FastEveryTick ==
    (pc \in {"end", "wait"} /\ tick > 0) => \A t \in Tasks : Fast[t] => ranThisTick[t] = 1

\* Every release is a run, a counted slip, or still pending (the report's
\* floor((tick - last_run) / interval)).
SlipAccountingExact ==
    \A t \in Tasks :
        releases[t] = runs[t] + slips[t] + (tick - last_run[t]) \div Interval[t]

\* When all budgets fit the period and nobody overruns, a task runs within
\* LateK ticks of being due: tick - last_run never exceeds interval + LateK.
BoundedLateness ==
    FitsPeriod => \A t \in Tasks : tick - last_run[t] <= Interval[t] + LateK

ExtraBounded == extra <= ExtraMax

Safety ==
    /\ TypeOK /\ SchedInv /\ OncePerTick /\ FastEveryTick /\ SlipAccountingExact
    /\ BoundedLateness /\ ExtraBounded

=============================================================================
