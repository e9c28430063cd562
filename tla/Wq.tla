--------------------------------- MODULE Wq ----------------------------------
(***************************************************************************)
(* Work queue (kernel/src/wq*.c): schedulers in task context and in an ISR, *)
(* the timer (mt_wq_timer_tick_i from the 1 kHz timer procs, here the      *)
(* timer interrupt), a single-shot caller (mt_work_run_wait), the queue's   *)
(* thread (mt_wq_thread_body) and optionally a second runner (a task       *)
(* calling mt_wq_run_once) race on one queue.                              *)
(*                                                                         *)
(* Granularity. Every field of mt_wq_t is read and written only under the  *)
(* kernel lock, and no critical section of wq*.c contains a point where    *)
(* another context can run (the lock is a non-nesting critical section;    *)
(* ISRs take it too), so each critical section is one step here, and the   *)
(* steps outside the lock are separate: the run of an item, the wait of    *)
(* the thread on `wake`, the park of a single-shot caller. The broken      *)
(* variant MergeOutsideLock adds the one unlocked read a "fast path" would *)
(* make.                                                                   *)
(*                                                                         *)
(* Actions and the C they abstract:                                        *)
(*  ScheduleI(i)        schedule_slot_i(): merged++ if queued, else        *)
(*                      fifo_push + mt_sem_signal_i(&wake)                 *)
(*  mt_work_schedule(s, i)  a task: lock; mt_work_schedule_i; unlock        *)
(*  mt_work_schedule_isr(i) an ISR: the same, one step                     *)
(*  mt_wq_timer_tick_i  the timer at time `now`: every due interval item   *)
(*                      activated in slot order, its deadline moved on its *)
(*                      grid (mt_proc_period_next), skipped periods missed *)
(*  start_i(r)          mt_wq_run_once: lock; start_i (busy -> refused,     *)
(*                      empty, or pop + running = i + shot ARMED -> RUN);  *)
(*                      read fn/arg; unlock                                *)
(*  RunEnd(r)           the item's run ends (mt_invoke returns); it takes  *)
(*                      Cost[i] ticks of time                              *)
(*  finish_i(r)         relock_after_run; finish_i (statistics, shot RUN   *)
(*                      -> DONE + signal done, running = NONE, wake if     *)
(*                      items are left); unlock                            *)
(*  WaitWake            mt_wq_serve_once's mt_sem_wait(&wake, FOREVER)     *)
(*                      after EMPTY or BUSY, abstracted: proceeds once the *)
(*                      token is set and takes it (Sem.tla checks the      *)
(*                      semaphore itself)                                  *)
(*  ShotArm / ShotWake / ShotTimeout / ShotReturn                          *)
(*                      mt_work_run_wait: lock; schedule_slot_i; shot =    *)
(*                      ARMED, token 0; wait_s parks (lock released); it   *)
(*                      is resumed by finish_i's signal or times out; with *)
(*                      the lock: OK iff shot == DONE; shot = NONE         *)
(*  Tick                time moves by one tick                             *)
(*                                                                         *)
(* Time (configurations with MaxTime > 0): one tick is one period of the   *)
(* timer procs. The queue's thread has the highest priority of the tasks   *)
(* and its zero-time steps come first: time does not move while it can     *)
(* start, finish or wake (only while an item's run still takes time or     *)
(* while it waits with nothing to do). The timer processes each tick       *)
(* before time moves on, unless TimerLag > 0: then it may fall up to       *)
(* TimerLag ticks behind (a starved timer thread) and catches up in one    *)
(* call, counting the periods it skipped.                                  *)
(*                                                                         *)
(* Simplifications: counters do not saturate (bounded runs); statistics    *)
(* other than merged/missed are not modelled; the stop request is not      *)
(* modelled; delayed (ONCE) timers are not modelled (one activation of     *)
(* the same ScheduleI).                                                    *)
(***************************************************************************)
EXTENDS Naturals, Sequences, FiniteSets

CONSTANTS
    NItems,            \* items 1..NItems, attached to the queue
    Schedulers,        \* task-context scheduler threads (model values)
    MaxActs,           \* activations by schedulers and the ISR in a behaviour
    TwoRunners,        \* a second runner (a task calling mt_wq_run_once) races the thread
    Period,            \* Period[i]: interval of item i in ticks (0: no timer)
    Cost,              \* Cost[i]: ticks one run of item i takes
    MaxTime,           \* ticks in a behaviour (0: time is not modelled)
    TimerLag,          \* ticks the timer may fall behind
    ShotItem,          \* the item a single-shot caller waits for (0: no caller)
    MaxShots,          \* single-shot calls in a behaviour
    \* broken variants (each must violate its named property)
    MergeOutsideLock,  \* a scheduler tests "queued" before taking the lock
    NoRunnerGuard,     \* start_i does not refuse a second runner
    RelativeDeadline,  \* the interval item is re-armed period ticks after its run ends (drift)
    SignalAnyRun,      \* finish_i completes the single shot for a run started before it armed
    MissedNotCounted,  \* the timer skips periods without counting them
    NoWakeAtFinish     \* finish_i does not signal `wake` when items are left

Items == 1 .. NItems
NONE == 0
THR == "thread"
AUX == "runner2"
Runners == IF TwoRunners THEN {THR, AUX} ELSE {THR}

ASSUME /\ NItems \in Nat \ {0} /\ MaxActs \in Nat /\ MaxTime \in Nat /\ TimerLag \in Nat
       /\ Period \in [Items -> Nat] /\ Cost \in [Items -> Nat]
       /\ ShotItem \in Items \cup {NONE} /\ MaxShots \in Nat

VARIABLES
    \* mt_wq_t, read and written under the kernel lock
    fifo,       \* the queued items, oldest first (order/where/head/count)
    running,    \* q->running: the item whose run is in progress, or NONE
    token,      \* q->wake.token
    merged,     \* slot[i].stats.merged
    missed,     \* slot[i].stats.missed
    deadline,   \* slot[i].deadline_us (interval items)
    shot,       \* slot[ShotItem].shot: "none", "armed", "run", "done"
    doneTok,    \* slot[ShotItem].done.token (1: a completion not yet taken)
    \* contexts
    rpc,        \* runner: "idle", "run", "fin", "wait" (the thread after EMPTY or BUSY)
    ritem,      \* runner: the item it runs
    rem,        \* runner: ticks left in the current run
    spc,        \* scheduler: "idle", "locking" (MergeOutsideLock: between read and lock)
    sitem,      \* scheduler: the item it schedules
    sstale,     \* scheduler: the "queued" it read without the lock
    wpc,        \* single-shot caller: "idle", "park", "woken", "ret"
    \* time
    now,        \* ticks
    tproc,      \* time the timer last processed
    \* ghosts
    acts,       \* activations of each item (schedules, ISR, timer, single shot)
    starts,     \* runs started of each item
    since,      \* activations of each item since its last start
    nacts,      \* scheduler and ISR activations so far
    nshots,     \* single-shot calls so far
    armedRun,   \* runner r's run started while the single shot was armed
    okRun,      \* a run started after the single shot armed has ended
    wres,       \* result of the last single-shot call: "none", "OK", "TIMEOUT", "BUSY"
    wok,        \* okRun when the last single-shot call returned
    winStart,   \* start of the current period window of each interval item
    winServed,  \* the item started in that window
    unserved,   \* windows that ended without a start
    timerActs   \* activations of each item by the timer

vars == <<fifo, running, token, merged, missed, deadline, shot, doneTok, rpc, ritem, rem, spc,
          sitem, sstale, wpc, now, tproc, acts, starts, since, nacts, nshots, armedRun, okRun,
          wres, wok, winStart, winServed, unserved, timerActs>>

Timed(i) == Period[i] > 0

\* First grid deadline of every interval item (mt_work_schedule_interval(w, Period, 1) at time 0);
\* the timer processes the ticks after time 0.
First == 1

\* Grid deadlines First + k * Period[i] at or before time t.
GridCount(i, t) == IF t >= First THEN (t - First) \div Period[i] + 1 ELSE 0
InFifo(i) == \E k \in 1 .. Len(fifo) : fifo[k] = i

Init ==
    /\ fifo = <<>> /\ running = NONE /\ token = 0
    /\ merged = [i \in Items |-> 0] /\ missed = [i \in Items |-> 0]
    /\ deadline = [i \in Items |-> First]
    /\ shot = "none" /\ doneTok = 0
    /\ rpc = [r \in Runners |-> "idle"] /\ ritem = [r \in Runners |-> NONE]
    /\ rem = [r \in Runners |-> 0]
    /\ spc = [s \in Schedulers |-> "idle"] /\ sitem = [s \in Schedulers |-> NONE]
    /\ sstale = [s \in Schedulers |-> FALSE]
    /\ wpc = "idle"
    /\ now = 0 /\ tproc = 0
    /\ acts = [i \in Items |-> 0] /\ starts = [i \in Items |-> 0] /\ since = [i \in Items |-> 0]
    /\ nacts = 0 /\ nshots = 0
    /\ armedRun = [r \in Runners |-> FALSE] /\ okRun = FALSE /\ wres = "none" /\ wok = FALSE
    /\ winStart = [i \in Items |-> First] /\ winServed = [i \in Items |-> FALSE]
    /\ unserved = [i \in Items |-> 0] /\ timerActs = [i \in Items |-> 0]

-----------------------------------------------------------------------------
(* schedule_slot_i(q, i, now): the core of every activation.               *)

ScheduleI(i) ==
    /\ acts' = [acts EXCEPT ![i] = @ + 1]
    /\ since' = [since EXCEPT ![i] = @ + 1]
    /\ IF InFifo(i)
       THEN /\ merged' = [merged EXCEPT ![i] = @ + 1]
            /\ UNCHANGED <<fifo, token>>
       ELSE /\ fifo' = Append(fifo, i)
            /\ token' = 1
            /\ UNCHANGED merged

SchedVars == <<running, missed, deadline, shot, doneTok, rpc, ritem, rem, wpc, now, tproc,
               starts, nshots, armedRun, okRun, wres, wok, winStart, winServed, unserved,
               timerActs>>

\* mt_work_schedule(w): lock; mt_work_schedule_i; unlock.
mt_work_schedule(s, i) ==
    /\ spc[s] = "idle" /\ nacts < MaxActs /\ ~MergeOutsideLock
    /\ ScheduleI(i) /\ nacts' = nacts + 1
    /\ UNCHANGED <<spc, sitem, sstale>> /\ UNCHANGED SchedVars

\* BROKEN fast path: "if already queued, just count the merge" decided
\* before the lock is taken ...
SchedReadUnlocked(s, i) ==
    /\ spc[s] = "idle" /\ nacts < MaxActs /\ MergeOutsideLock
    /\ spc' = [spc EXCEPT ![s] = "locking"] /\ sitem' = [sitem EXCEPT ![s] = i]
    /\ sstale' = [sstale EXCEPT ![s] = InFifo(i)] /\ nacts' = nacts + 1
    /\ UNCHANGED <<fifo, token, merged, acts, since>> /\ UNCHANGED SchedVars

\* ... and acted on under the lock without a second look.
SchedLocked(s) ==
    /\ spc[s] = "locking"
    /\ IF sstale[s]
       THEN /\ acts' = [acts EXCEPT ![sitem[s]] = @ + 1]
            /\ since' = [since EXCEPT ![sitem[s]] = @ + 1]
            /\ merged' = [merged EXCEPT ![sitem[s]] = @ + 1]
            /\ UNCHANGED <<fifo, token>>
       ELSE ScheduleI(sitem[s])
    /\ spc' = [spc EXCEPT ![s] = "idle"]
    /\ UNCHANGED <<sitem, sstale, nacts>> /\ UNCHANGED SchedVars

\* mt_work_schedule_isr(w) (and mt_work_notify_i from a publisher's ISR):
\* one step whenever no task is inside a critical section.
mt_work_schedule_isr(i) ==
    /\ nacts < MaxActs
    /\ ScheduleI(i) /\ nacts' = nacts + 1
    /\ UNCHANGED <<spc, sitem, sstale>> /\ UNCHANGED SchedVars

-----------------------------------------------------------------------------
(* The timer: mt_wq_timer_tick_i(q, now) for every tick not yet processed. *)

RECURSIVE AppendInOrder(_, _)
AppendInOrder(f, S) ==
    IF S = {} THEN f
    ELSE LET m == CHOOSE x \in S : \A y \in S : x <= y
         IN AppendInOrder(Append(f, m), S \ {m})

mt_wq_timer_tick_i ==
    /\ tproc < now
    /\ LET due == {i \in Items : Timed(i) /\ deadline[i] <= now}
           \* mt_proc_period_next: whole periods skipped, first grid deadline after now
           skip(i) == (now - deadline[i]) \div Period[i]
       IN /\ fifo' = AppendInOrder(fifo, {i \in due : ~InFifo(i)})
          /\ token' = IF \E i \in due : ~InFifo(i) THEN 1 ELSE token
          /\ merged' = [i \in Items |-> IF i \in due /\ InFifo(i) THEN merged[i] + 1 ELSE merged[i]]
          /\ acts' = [i \in Items |-> IF i \in due THEN acts[i] + 1 ELSE acts[i]]
          /\ since' = [i \in Items |-> IF i \in due THEN since[i] + 1 ELSE since[i]]
          /\ timerActs' = [i \in Items |-> IF i \in due THEN timerActs[i] + 1 ELSE timerActs[i]]
          /\ deadline' = [i \in Items |->
                IF i \notin due THEN deadline[i]
                ELSE IF RelativeDeadline THEN MaxTime + 1   \* re-armed when the run ends
                ELSE deadline[i] + (skip(i) + 1) * Period[i]]
          /\ missed' = [i \in Items |->
                IF i \in due /\ ~MissedNotCounted /\ ~RelativeDeadline
                THEN missed[i] + skip(i) ELSE missed[i]]
    /\ tproc' = now
    /\ UNCHANGED <<running, shot, doneTok, rpc, ritem, rem, spc, sitem, sstale, wpc, now,
                   starts, nacts, nshots, armedRun, okRun, wres, wok, winStart, winServed,
                   unserved>>

-----------------------------------------------------------------------------
(* Runners: the queue's thread (serve loop) and, optionally, a second task *)
(* calling mt_wq_run_once.                                                  *)

RunnerVars == <<merged, missed, deadline, spc, sitem, sstale, wpc, now, tproc, acts, nacts,
                nshots, wres, wok, timerActs>>

\* mt_wq_run_once: lock; start_i; unlock.
start_i(r) ==
    /\ rpc[r] = "idle"
    /\ IF running # NONE /\ ~NoRunnerGuard
       THEN \* MT_E_BUSY (counted in refused): the thread waits on `wake`
            /\ rpc' = [rpc EXCEPT ![r] = IF r = THR THEN "wait" ELSE "idle"]
            /\ UNCHANGED <<fifo, running, ritem, rem, shot, starts, since, armedRun, okRun,
                           token, doneTok, winServed, winStart, unserved>>
       ELSE IF fifo = <<>>
       THEN \* MT_E_EMPTY
            /\ rpc' = [rpc EXCEPT ![r] = IF r = THR THEN "wait" ELSE "idle"]
            /\ UNCHANGED <<fifo, running, ritem, rem, shot, starts, since, armedRun, okRun,
                           token, doneTok, winServed, winStart, unserved>>
       ELSE LET i == Head(fifo) IN
            /\ fifo' = Tail(fifo)
            /\ running' = i
            /\ ritem' = [ritem EXCEPT ![r] = i]
            /\ rem' = [rem EXCEPT ![r] = IF MaxTime > 0 THEN Cost[i] ELSE 0]
            /\ starts' = [starts EXCEPT ![i] = @ + 1]
            /\ since' = [since EXCEPT ![i] = 0]
            /\ armedRun' = [armedRun EXCEPT ![r] = (i = ShotItem /\ shot = "armed")]
            /\ shot' = IF i = ShotItem /\ shot = "armed" THEN "run" ELSE shot
            /\ winServed' = [winServed EXCEPT ![i] = IF Timed(i) /\ now >= winStart[i]
                                                     THEN TRUE ELSE @]
            /\ rpc' = [rpc EXCEPT ![r] = "run"]
            /\ UNCHANGED <<token, doneTok, okRun, winStart, unserved>>
    /\ UNCHANGED RunnerVars

\* The item's run returns (its time, Cost ticks, has passed).
RunEnd(r) ==
    /\ rpc[r] = "run" /\ rem[r] = 0
    /\ rpc' = [rpc EXCEPT ![r] = "fin"]
    /\ UNCHANGED <<fifo, running, token, merged, missed, deadline, shot, doneTok, ritem, rem,
                   spc, sitem, sstale, wpc, now, tproc, acts, starts, since, nacts, nshots,
                   armedRun, okRun, wres, wok, winStart, winServed, unserved, timerActs>>

\* relock_after_run; finish_i; unlock.
finish_i(r) ==
    /\ rpc[r] = "fin"
    /\ LET i == ritem[r]
           completes == i = ShotItem /\ (shot = "run" \/ (SignalAnyRun /\ shot = "armed"))
       IN /\ running' = NONE
          /\ token' = IF fifo # <<>> /\ ~NoWakeAtFinish THEN 1 ELSE token
          /\ shot' = IF completes THEN "done" ELSE shot
          /\ doneTok' = IF completes THEN 1 ELSE doneTok
          /\ okRun' = (okRun \/ (completes /\ armedRun[r]))
          /\ deadline' = IF RelativeDeadline /\ Timed(i)
                         THEN [deadline EXCEPT ![i] = now + Period[i]] ELSE deadline
    /\ rpc' = [rpc EXCEPT ![r] = "idle"]
    /\ ritem' = [ritem EXCEPT ![r] = NONE]
    /\ armedRun' = [armedRun EXCEPT ![r] = FALSE]
    /\ UNCHANGED <<fifo, merged, missed, rem, spc, sitem, sstale, wpc, now, tproc, acts, starts,
                   since, nacts, nshots, wres, wok, winStart, winServed, unserved, timerActs>>

\* The thread's mt_sem_wait(&wake, MT_WAIT_FOREVER): takes the token.
WaitWake ==
    /\ rpc[THR] = "wait" /\ token = 1
    /\ token' = 0
    /\ rpc' = [rpc EXCEPT ![THR] = "idle"]
    /\ UNCHANGED <<fifo, running, merged, missed, deadline, shot, doneTok, ritem, rem, spc,
                   sitem, sstale, wpc, now, tproc, acts, starts, since, nacts, nshots,
                   armedRun, okRun, wres, wok, winStart, winServed, unserved, timerActs>>

-----------------------------------------------------------------------------
(* Single shot: mt_work_run_wait(ShotItem, timeout).                       *)

ShotVars == <<running, missed, deadline, rpc, ritem, rem, spc, sitem, sstale, now, tproc,
              starts, nacts, armedRun, winStart, winServed, unserved, timerActs>>

ShotArm ==
    /\ wpc = "idle" /\ ShotItem # NONE /\ nshots < MaxShots
    /\ nshots' = nshots + 1
    /\ IF shot # "none"
       THEN /\ wres' = "BUSY" /\ wok' = FALSE
            /\ UNCHANGED <<wpc, fifo, token, merged, acts, since, shot, doneTok, okRun>>
       ELSE /\ ScheduleI(ShotItem)
            /\ shot' = "armed" /\ doneTok' = 0 /\ okRun' = FALSE
            /\ wpc' = "park"
            /\ UNCHANGED <<wres, wok>>
    /\ UNCHANGED ShotVars

\* finish_i's mt_sem_signal_i handed the completion over (the waiter resumed).
ShotWake ==
    /\ wpc = "park" /\ doneTok = 1
    /\ doneTok' = 0 /\ wpc' = "ret"
    /\ UNCHANGED <<fifo, token, merged, shot, acts, since, nshots, okRun, wres, wok>>
    /\ UNCHANGED ShotVars

\* The port's timeout: the waiter leaves the semaphore; a completion that
\* comes after this leaves the token set instead.
ShotTimeout ==
    /\ wpc = "park"
    /\ wpc' = "ret"
    /\ UNCHANGED <<fifo, token, merged, shot, doneTok, acts, since, nshots, okRun, wres, wok>>
    /\ UNCHANGED ShotVars

\* With the lock re-taken: OK iff the run has ended (shot DONE); nothing stays.
ShotReturn ==
    /\ wpc = "ret"
    /\ wres' = IF shot = "done" THEN "OK" ELSE "TIMEOUT"
    /\ wok' = okRun
    /\ shot' = "none" /\ doneTok' = 0
    /\ wpc' = "idle"
    /\ UNCHANGED <<fifo, token, merged, acts, since, nshots, okRun>>
    /\ UNCHANGED ShotVars

-----------------------------------------------------------------------------
(* Time.                                                                    *)

\* The thread has a zero-time step to take.
ThreadUrgent ==
    \/ rpc[THR] \in {"idle", "fin"}
    \/ (rpc[THR] = "run" /\ rem[THR] = 0)
    \/ (rpc[THR] = "wait" /\ token = 1)

Tick ==
    /\ MaxTime > 0 /\ now < MaxTime
    /\ ~ThreadUrgent
    /\ now - tproc <= TimerLag
    /\ now' = now + 1
    /\ rem' = [r \in Runners |-> IF rpc[r] = "run" /\ rem[r] > 0 THEN rem[r] - 1 ELSE rem[r]]
    \* period windows [winStart, winStart + Period) of the absolute grid
    /\ LET closes(i) == Timed(i) /\ now + 1 >= winStart[i] + Period[i]
       IN /\ unserved' = [i \in Items |-> IF closes(i) /\ ~winServed[i] THEN unserved[i] + 1
                                          ELSE unserved[i]]
          /\ winStart' = [i \in Items |-> IF closes(i) THEN winStart[i] + Period[i] ELSE winStart[i]]
          /\ winServed' = [i \in Items |-> IF closes(i) THEN FALSE ELSE winServed[i]]
    /\ UNCHANGED <<fifo, running, token, merged, missed, deadline, shot, doneTok, rpc, ritem,
                   spc, sitem, sstale, wpc, tproc, acts, starts, since, nacts, nshots,
                   armedRun, okRun, wres, wok, timerActs>>

-----------------------------------------------------------------------------

\* End of a bounded behaviour: time is used up, or nothing is left to do.
Quiescent ==
    /\ \/ (MaxTime > 0 /\ now = MaxTime)
       \/ (fifo = <<>> /\ rpc[THR] = "wait" /\ token = 0 /\ nacts = MaxActs /\ wpc = "idle" /\
           \A s \in Schedulers : spc[s] = "idle")
    /\ UNCHANGED vars

Next ==
    \/ Quiescent
    \/ \E s \in Schedulers, i \in Items : mt_work_schedule(s, i) \/ SchedReadUnlocked(s, i)
    \/ \E s \in Schedulers : SchedLocked(s)
    \/ \E i \in Items : mt_work_schedule_isr(i)
    \/ mt_wq_timer_tick_i
    \/ \E r \in Runners : start_i(r) \/ RunEnd(r) \/ finish_i(r)
    \/ WaitWake
    \/ ShotArm \/ ShotWake \/ ShotTimeout \/ ShotReturn
    \/ Tick

\* The queue's thread and the timer are fair; schedulers need not schedule.
Fairness ==
    /\ WF_vars(start_i(THR)) /\ WF_vars(RunEnd(THR)) /\ WF_vars(finish_i(THR)) /\ WF_vars(WaitWake)
    /\ (TwoRunners => (WF_vars(RunEnd(AUX)) /\ WF_vars(finish_i(AUX))))
    /\ WF_vars(mt_wq_timer_tick_i)

Spec == Init /\ [][Next]_vars
LiveSpec == Spec /\ Fairness

-----------------------------------------------------------------------------
(* Invariants                                                              *)

TypeOK ==
    /\ fifo \in Seq(Items) /\ running \in Items \cup {NONE} /\ token \in {0, 1}
    /\ shot \in {"none", "armed", "run", "done"} /\ doneTok \in {0, 1}
    /\ rpc \in [Runners -> {"idle", "run", "fin", "wait"}]
    /\ wpc \in {"idle", "park", "ret"}

\* The FIFO holds each item at most once (the permutation of wq.c), so it
\* never holds more than the attached items.
FifoDistinct ==
    \A j, k \in 1 .. Len(fifo) : j # k => fifo[j] # fifo[k]

\* No activation lost without being counted as merged: every activation is a
\* started run, a counted merge, or the pending run; an activation not yet
\* served always has its item queued (it will start).
NoLostActivation ==
    \A i \in Items :
        /\ acts[i] = starts[i] + merged[i] + (IF InFifo(i) THEN 1 ELSE 0)
        /\ since[i] > 0 => InFifo(i)

\* An item never runs twice at once (and, with one runner active at a time,
\* no two items of one queue run at once).
NoConcurrentRun ==
    \A i \in Items : Cardinality({r \in Runners : rpc[r] \in {"run", "fin"} /\ ritem[r] = i}) <= 1

\* An interval item starts in every window [d, d + Period) of its absolute
\* grid (the queue is not overloaded in the configurations that check it).
IntervalWithinPeriod ==
    \A i \in Items : Timed(i) => unserved[i] = 0

\* Every grid deadline the timer has passed is one activation or one counted
\* missed period, and the next deadline is the first grid point ahead.
MissedAccountingExact ==
    \A i \in Items : Timed(i) =>
        /\ timerActs[i] + missed[i] = GridCount(i, tproc)
        /\ deadline[i] = First + GridCount(i, tproc) * Period[i]

\* A single-shot call returns MT_OK only after a run that started after it
\* armed has ended; a completion never stays behind for a later call.
SingleShotNoStale ==
    /\ wres = "OK" => wok
    /\ (wpc = "idle" /\ shot = "none") => doneTok = 0

Safety ==
    /\ TypeOK /\ FifoDistinct /\ NoLostActivation /\ NoConcurrentRun /\ SingleShotNoStale

-----------------------------------------------------------------------------
(* Liveness: a queued item eventually starts (the thread is never left      *)
(* asleep with items queued, also after a refused run).                     *)

QueuedEventuallyStarts ==
    \A i \in Items : InFifo(i) ~> ~InFifo(i)

=============================================================================
