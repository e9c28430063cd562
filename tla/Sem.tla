-------------------------------- MODULE Sem ---------------------------------
(***************************************************************************)
(* Binary semaphore (kernel/src/sem.c) with the port contract of           *)
(* kernel/port/mt_port.h (mt_port_suspend_s / mt_port_resume_i), as the     *)
(* POSIX (hal_posix/port.c) and ChibiOS (hal_chibios/port/                 *)
(* mt_port_chibios.c) ports implement it. Waiting tasks, a signalling task *)
(* and an ISR interleave; the kernel lock excludes the ISR only while a    *)
(* task holds it.                                                          *)
(*                                                                         *)
(* Actions and the C they abstract:                                        *)
(*  mt_sem_wait_lock(w, m)    mt_sem_wait: mt_port_lock(); the timeout     *)
(*                            class (0, finite, MT_WAIT_FOREVER) is chosen *)
(*  mt_sem_wait_s_check(w)    mt_sem_wait_s: if token {token = 0; OK}      *)
(*                            else if waiter {BUSY} else if timeout == 0   *)
(*                            {TIMEOUT} else mt_port_suspend_s(...)        *)
(*  mt_port_suspend_s_ref(w)  suspend_s: *ref = the calling thread         *)
(*                            (POSIX: waiter_prepare; *ref = me;           *)
(*                            ChibiOS: chThdSuspendTimeoutS's *trp = curr) *)
(*  mt_port_suspend_s_park(w) the thread sleeps and the lock is released   *)
(*                            in one step (pthread_cond_timedwait /        *)
(*                            chSchGoSleepS)                               *)
(*  mt_port_timeout(w)        the timeout path under the lock: ChibiOS's   *)
(*                            virtual-timer callback chThdResumeI(trp,     *)
(*                            MSG_TIMEOUT) (or the RT timeout handler), or *)
(*                            POSIX's `now >= deadline` branch after the   *)
(*                            `while (me->resumed == 0)` test: clears *ref *)
(*  mt_port_suspend_s_wake(w) suspend_s returns with the lock re-taken;    *)
(*                            wait_s maps RESUMED to MT_OK, else TIMEOUT   *)
(*  mt_sem_wait_unlock(w)     mt_port_unlock(); return st                  *)
(*  mt_sem_signal_lock        mt_sem_signal: mt_port_lock()                *)
(*  mt_sem_signal_signal_i    mt_sem_signal_i (SignalI below):             *)
(*                            if (!mt_port_resume_i(&s->waiter)) {if       *)
(*                            token: merged++; token = 1}; resume_i: if    *)
(*                            *ref: *ref = NULL, ready with MSG_OK /       *)
(*                            resumed = 1, return true                     *)
(*  mt_sem_signal_unlock      mt_port_unlock()                             *)
(*  mt_sem_signal_isr         mt_sem_signal_isr: lock_isr; signal_i;       *)
(*                            unlock_isr, one step when the lock is free   *)
(*                                                                         *)
(* Simplifications:                                                        *)
(*  - Time is not modelled: a finite wait may time out at any moment while *)
(*    it is parked and not resumed (mt_port_timeout is enabled then); the  *)
(*    chunking of long timeouts in both ports is inside that one event.    *)
(*  - The ISR runs to completion once it has the lock (single core, or     *)
(*    the POSIX port's mutex), so its critical section is one step.        *)
(*  - Everything inside a critical section touches only lock-protected     *)
(*    data; the finer steps kept here (check / set ref / park) show that    *)
(*    the lock alone orders them.                                          *)
(*  - Thread priorities and the scheduler are abstracted: any ready        *)
(*    context may take the next step. The kernel lock is assumed           *)
(*    starvation-free for a woken waiter (strong fairness on its wake).    *)
(*  - The `merged` counter does not saturate (MaxSignals is small); the    *)
(*    POSIX simulated-time path of suspend_s is not modelled.              *)
(***************************************************************************)
EXTENDS Naturals, FiniteSets

CONSTANTS
    Waiters,              \* waiting tasks (model values); two or more exercise MT_E_BUSY
    MaxSignals,           \* signals in a behaviour (task and ISR together)
    InitToken,            \* mt_sem_init(s, available): 0 or 1
    SignalNoResume,       \* BROKEN: signal_i sets the token without mt_port_resume_i
    TimeoutIgnoresResume  \* BROKEN: the port's timeout path wins even after a resume

ASSUME /\ Waiters # {} /\ MaxSignals \in Nat /\ InitToken \in {0, 1}
       /\ SignalNoResume \in BOOLEAN /\ TimeoutIgnoresResume \in BOOLEAN

NULL == "null"
FREE == "free"
SIG == "sigtask"                      \* the signalling task, as a lock holder
Modes == {"poll", "timed", "forever"} \* timeout_us == 0, finite, MT_WAIT_FOREVER

VARIABLES
    \* mt_sem_t
    token,      \* s->token
    ref,        \* s->waiter (the port reference of the parked thread), NULL or a waiter
    merged,     \* s->merged
    \* the kernel lock
    lock,       \* FREE, a waiter, or SIG (the ISR holds it only inside one atomic step)
    \* waiting tasks
    wpc,        \* program counter
    wmode,      \* timeout class of the current wait
    wmsg,       \* port wake-up message of a parked waiter: "none", "resumed", "timeout"
    wst,        \* status mt_sem_wait returns ("none" while undecided)
    \* signalling task
    spc,
    \* ghosts
    signals,    \* calls of mt_sem_signal_i so far (task and ISR)
    consumed,   \* waits that returned MT_OK
    handed      \* handed[w]: a signal resumed w, whose wait has not yet returned

vars == <<token, ref, merged, lock, wpc, wmode, wmsg, wst, spc, signals, consumed, handed>>

Init ==
    /\ token = InitToken /\ ref = NULL /\ merged = 0
    /\ lock = FREE
    /\ wpc = [w \in Waiters |-> "idle"]
    /\ wmode = [w \in Waiters |-> "poll"]
    /\ wmsg = [w \in Waiters |-> "none"]
    /\ wst = [w \in Waiters |-> "none"]
    /\ spc = "idle"
    /\ signals = 0 /\ consumed = 0
    /\ handed = [w \in Waiters |-> FALSE]

-----------------------------------------------------------------------------
(* mt_sem_signal_i(s): the I-class core, run with the lock held by a task  *)
(* (mt_sem_signal) or inside the ISR (mt_sem_signal_isr).                   *)

SignalI ==
    /\ signals' = signals + 1
    /\ IF ref # NULL /\ ~SignalNoResume
       THEN \* mt_port_resume_i(&s->waiter) returns true: *ref = NULL, the
            \* thread is readied with MSG_OK; the token goes straight to it.
            /\ ref' = NULL
            /\ wmsg' = [wmsg EXCEPT ![ref] = "resumed"]
            /\ handed' = [handed EXCEPT ![ref] = TRUE]
            /\ UNCHANGED <<token, merged>>
       ELSE \* nobody woken: merge into an existing token (counted), set it.
            /\ merged' = IF token # 0 THEN merged + 1 ELSE merged
            /\ token' = 1
            /\ UNCHANGED <<ref, wmsg, handed>>

-----------------------------------------------------------------------------
(* Waiting task: mt_sem_wait(s, timeout_us)                                 *)

\* mt_port_lock().
mt_sem_wait_lock(w, m) ==
    /\ wpc[w] = "idle" /\ lock = FREE
    /\ lock' = w
    /\ wmode' = [wmode EXCEPT ![w] = m]
    /\ wpc' = [wpc EXCEPT ![w] = "check"]
    /\ UNCHANGED <<token, ref, merged, wmsg, wst, spc, signals, consumed, handed>>

\* mt_sem_wait_s(): the if-chain (token, busy, poll), or on to mt_port_suspend_s.
mt_sem_wait_s_check(w) ==
    /\ wpc[w] = "check"
    /\ CASE token # 0 ->
              /\ token' = 0 /\ consumed' = consumed + 1
              /\ wst' = [wst EXCEPT ![w] = "OK"] /\ wpc' = [wpc EXCEPT ![w] = "ret"]
         [] ref # NULL ->
              /\ wst' = [wst EXCEPT ![w] = "BUSY"] /\ wpc' = [wpc EXCEPT ![w] = "ret"]
              /\ UNCHANGED <<token, consumed>>
         [] wmode[w] = "poll" ->
              /\ wst' = [wst EXCEPT ![w] = "TIMEOUT"] /\ wpc' = [wpc EXCEPT ![w] = "ret"]
              /\ UNCHANGED <<token, consumed>>
         [] OTHER ->
              /\ wpc' = [wpc EXCEPT ![w] = "suspend"]
              /\ UNCHANGED <<token, consumed, wst>>
    /\ UNCHANGED <<ref, merged, lock, wmode, wmsg, spc, signals, handed>>

\* mt_port_suspend_s(): *ref = current thread (lock held).
mt_port_suspend_s_ref(w) ==
    /\ wpc[w] = "suspend"
    /\ ref' = w
    /\ wmsg' = [wmsg EXCEPT ![w] = "none"]
    /\ wpc' = [wpc EXCEPT ![w] = "park"]
    /\ UNCHANGED <<token, merged, lock, wmode, wst, spc, signals, consumed, handed>>

\* mt_port_suspend_s(): sleep, releasing the lock in the same step
\* (chThdSuspendTimeoutS / pthread_cond_timedwait).
mt_port_suspend_s_park(w) ==
    /\ wpc[w] = "park"
    /\ lock' = FREE
    /\ wpc' = [wpc EXCEPT ![w] = "parked"]
    /\ UNCHANGED <<token, ref, merged, wmode, wmsg, wst, spc, signals, consumed, handed>>

\* The port's timeout path, under the lock (ChibiOS: the virtual-timer
\* callback, chThdResumeI(trp, MSG_TIMEOUT); POSIX: the woken thread with the
\* mutex re-taken): only while the thread is still referenced, i.e. not
\* resumed; it clears *ref itself. The broken port decides "timeout" even
\* when a resume got in first.
mt_port_timeout(w) ==
    /\ wpc[w] = "parked" /\ wmode[w] = "timed" /\ lock = FREE
    /\ IF TimeoutIgnoresResume THEN wmsg[w] # "timeout" ELSE ref = w
    /\ ref' = IF ref = w THEN NULL ELSE ref
    /\ wmsg' = [wmsg EXCEPT ![w] = "timeout"]
    /\ UNCHANGED <<token, merged, lock, wpc, wmode, wst, spc, signals, consumed, handed>>

\* mt_port_suspend_s() returns with the lock re-taken; mt_sem_wait_s maps
\* MT_PORT_RESUMED to MT_OK and MT_PORT_TIMEOUT to MT_E_TIMEOUT.
mt_port_suspend_s_wake(w) ==
    /\ wpc[w] = "parked" /\ wmsg[w] # "none" /\ lock = FREE
    /\ lock' = w
    /\ IF wmsg[w] = "resumed"
       THEN /\ wst' = [wst EXCEPT ![w] = "OK"] /\ consumed' = consumed + 1
       ELSE /\ wst' = [wst EXCEPT ![w] = "TIMEOUT"] /\ UNCHANGED consumed
    /\ handed' = [handed EXCEPT ![w] = FALSE]
    /\ wmsg' = [wmsg EXCEPT ![w] = "none"]
    /\ wpc' = [wpc EXCEPT ![w] = "ret"]
    /\ UNCHANGED <<token, ref, merged, wmode, spc, signals>>

\* mt_port_unlock(); return st.
mt_sem_wait_unlock(w) ==
    /\ wpc[w] = "ret"
    /\ lock' = FREE
    /\ wpc' = [wpc EXCEPT ![w] = "idle"]
    /\ wst' = [wst EXCEPT ![w] = "none"]
    /\ wmode' = [wmode EXCEPT ![w] = "poll"]
    /\ UNCHANGED <<token, ref, merged, wmsg, spc, signals, consumed, handed>>

Waiter(w) ==
    \/ \E m \in Modes : mt_sem_wait_lock(w, m)
    \/ mt_sem_wait_s_check(w)
    \/ mt_port_suspend_s_ref(w) \/ mt_port_suspend_s_park(w)
    \/ mt_port_suspend_s_wake(w) \/ mt_sem_wait_unlock(w)

-----------------------------------------------------------------------------
(* Signalling task: mt_sem_signal(s)                                        *)

mt_sem_signal_lock ==
    /\ spc = "idle" /\ lock = FREE /\ signals < MaxSignals
    /\ lock' = SIG
    /\ spc' = "signal"
    /\ UNCHANGED <<token, ref, merged, wpc, wmode, wmsg, wst, signals, consumed, handed>>

mt_sem_signal_signal_i ==
    /\ spc = "signal"
    /\ SignalI
    /\ spc' = "unlock"
    /\ UNCHANGED <<lock, wpc, wmode, wst, consumed>>

mt_sem_signal_unlock ==
    /\ spc = "unlock"
    /\ lock' = FREE
    /\ spc' = "idle"
    /\ UNCHANGED <<token, ref, merged, wpc, wmode, wmsg, wst, signals, consumed, handed>>

-----------------------------------------------------------------------------
(* ISR: mt_sem_signal_isr(s) = lock_isr; signal_i; unlock_isr. It runs to   *)
(* completion once it has the lock, so it is one step, enabled between any  *)
(* two task-level steps except while a task holds the lock.                 *)

mt_sem_signal_isr ==
    /\ lock = FREE /\ signals < MaxSignals
    /\ SignalI
    /\ UNCHANGED <<lock, wpc, wmode, wst, spc, consumed>>

-----------------------------------------------------------------------------
\* The only end state: every signal given, and every waiter blocked without
\* a time limit and not woken. Stuttering there is not a deadlock; any other
\* state without a successor is.
Quiescent ==
    /\ signals = MaxSignals /\ spc = "idle" /\ lock = FREE
    /\ \A w \in Waiters : wpc[w] = "parked" /\ wmode[w] = "forever" /\ wmsg[w] = "none"
    /\ UNCHANGED vars

Next ==
    \/ \E w \in Waiters : Waiter(w) \/ mt_port_timeout(w)
    \/ mt_sem_signal_lock \/ mt_sem_signal_signal_i \/ mt_sem_signal_unlock
    \/ mt_sem_signal_isr
    \/ Quiescent

\* Waiting tasks and the port timer are fair; the signalling task, once it
\* holds the lock, finishes; nobody is obliged to signal. A woken waiter gets
\* the kernel lock eventually even if other tasks keep taking it (strong
\* fairness: the lock is starvation-free for a readied thread; without it a
\* second waiter polling in a loop could starve the first).
Fairness ==
    /\ \A w \in Waiters : /\ WF_vars(Waiter(w)) /\ WF_vars(mt_port_timeout(w))
                          /\ SF_vars(mt_port_suspend_s_wake(w))
    /\ WF_vars(mt_sem_signal_signal_i) /\ WF_vars(mt_sem_signal_unlock)

Spec == Init /\ [][Next]_vars /\ Fairness

-----------------------------------------------------------------------------
(* Invariants                                                              *)

TypeOK ==
    /\ token \in {0, 1} /\ ref \in Waiters \cup {NULL} /\ merged \in 0 .. MaxSignals
    /\ lock \in Waiters \cup {FREE, SIG}
    /\ wpc \in [Waiters -> {"idle", "check", "suspend", "park", "parked", "ret"}]
    /\ wmode \in [Waiters -> Modes]
    /\ wmsg \in [Waiters -> {"none", "resumed", "timeout"}]
    /\ wst \in [Waiters -> {"none", "OK", "BUSY", "TIMEOUT"}]
    /\ spc \in {"idle", "signal", "unlock"}
    /\ signals \in 0 .. MaxSignals /\ consumed \in 0 .. MaxSignals + InitToken
    /\ handed \in [Waiters -> BOOLEAN]

\* The lock is held by whoever is in a locked section, and by nobody else.
LockedBy(x) ==
    IF x = SIG THEN spc \in {"signal", "unlock"}
    ELSE wpc[x] \in {"check", "suspend", "park", "ret"}
MutualExclusion ==
    /\ \A x \in Waiters \cup {SIG} : LockedBy(x) <=> lock = x

\* At most one token, and never a token while a thread is referenced (MtSemInv).
AtMostOneToken == token \in {0, 1} /\ (token = 1 => ref = NULL)

\* At most one waiter is parked and referenced; a second gets MT_E_BUSY.
OneWaiter ==
    \A v, w \in Waiters : (v # w /\ wpc[v] \in {"park", "parked"} /\ wpc[w] \in {"park", "parked"})
                           => (ref # v \/ ref # w)

\* No lost wake-up. Every signal is accounted for: consumed by a wait that
\* returned MT_OK, merged into a token already set (counted), the pending
\* token, or handed to a resumed waiter that has not returned yet. And a
\* pending token never coexists with a thread parked on the semaphore.
NoLostWakeup ==
    /\ signals + InitToken =
           consumed + merged + token + Cardinality({w \in Waiters : handed[w]})
    /\ token = 1 => \A w \in Waiters : ~(wpc[w] = "parked" /\ ref = w)

\* A wait that times out has been handed no signal (it consumed nothing).
TimedOutWaitConsumedNothing ==
    \A w \in Waiters :
        (wmsg[w] = "timeout" \/ (wpc[w] = "ret" /\ wst[w] = "TIMEOUT")) => ~handed[w]

\* A resumed waiter really is referenced no more, and only parked waiters are resumed.
ResumeConsistent ==
    \A w \in Waiters : handed[w] => (wpc[w] = "parked" /\ ref # w)

Safety ==
    /\ TypeOK /\ MutualExclusion /\ AtMostOneToken /\ OneWaiter
    /\ NoLostWakeup /\ TimedOutWaitConsumedNothing /\ ResumeConsistent

-----------------------------------------------------------------------------
(* Liveness: a waiter blocked without a time limit while a signal is        *)
(* pending for it (handed over, or a token set) eventually returns MT_OK.   *)

WaiterGetsPendingSignal ==
    \A w \in Waiters :
        (wpc[w] = "parked" /\ wmode[w] = "forever" /\ (handed[w] \/ token = 1))
            ~> (wpc[w] = "ret" /\ wst[w] = "OK")

=============================================================================
