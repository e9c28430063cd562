----------------------------- MODULE SemTrace ------------------------------
(***************************************************************************)
(* Trace validation of Sem against the C code. tools/trace/sem_trace       *)
(* runs the real sem.c on the POSIX port with a waiting task, a signalling *)
(* task and a simulated ISR (threads), and logs every call from sem.c into *)
(* the port (lock, unlock with the semaphore's state, suspend_s and its    *)
(* result, resume_i and its result) while the kernel lock is held, so the  *)
(* log order is the order of the critical sections. This module constrains *)
(* Sem (one waiter) to follow the log. The trace is accepted iff TLC       *)
(* reports TraceNotAccepted VIOLATED, rejected iff it reports a deadlock.  *)
(*                                                                         *)
(* Event -> action (steps the log does not show are allowed only where the *)
(* next event needs them: the wait_s check before "suspend" or "unlock",   *)
(* the ref/park steps of suspend_s, and the port's timeout before a        *)
(* "wake TIMEOUT"):                                                        *)
(*   W lock m        mt_sem_wait_lock(W, m)                                *)
(*   W suspend       mt_sem_wait_s_check(W) going to mt_port_suspend_s     *)
(*   W wake r        mt_port_suspend_s_wake(W), status OK iff r = RESUMED  *)
(*   W unlock s      mt_sem_wait_unlock(W); the semaphore state equals s   *)
(*   W ret st        the status recorded at the unlock is st (no step)     *)
(*   S lock / S resume r / S unlock s                                      *)
(*                   mt_sem_signal_lock / mt_sem_signal_signal_i (resume_i *)
(*                   returned r) / mt_sem_signal_unlock (state s)          *)
(*   I lock / I resume r / I unlock s                                      *)
(*                   lock free (no step) / mt_sem_signal_isr (resume_i     *)
(*                   returned r) / state s (no step)                       *)
(***************************************************************************)
EXTENDS Sem, SemTraceData, Sequences

VARIABLES ti,      \* index of the next log event
          lastSt   \* status the waiter's last wait decided (for its "ret" event)

tvars == <<vars, ti, lastSt>>

W == CHOOSE w \in Waiters : TRUE
E == Trace[ti]

Snapshot == token = E.token /\ (ref # NULL) = E.waiting /\ merged = E.merged

Internal ==
    \/ /\ ti <= Len(Trace) /\ E.t = "W" /\ E.k = "unlock"
       /\ mt_sem_wait_s_check(W)
    \/ mt_port_suspend_s_ref(W) \/ mt_port_suspend_s_park(W)
    \/ /\ ti <= Len(Trace) /\ E.t = "W" /\ E.k = "wake" /\ E.r = "TIMEOUT"
       /\ mt_port_timeout(W)

Step ==
    CASE E.t = "W" /\ E.k = "lock" -> mt_sem_wait_lock(W, E.m)
      [] E.t = "W" /\ E.k = "suspend" -> mt_sem_wait_s_check(W) /\ wpc'[W] = "suspend"
      [] E.t = "W" /\ E.k = "wake" ->
            mt_port_suspend_s_wake(W) /\ wst'[W] = (IF E.r = "RESUMED" THEN "OK" ELSE "TIMEOUT")
      [] E.t = "W" /\ E.k = "unlock" -> Snapshot /\ mt_sem_wait_unlock(W)
      [] E.t = "W" /\ E.k = "ret" -> lastSt = E.st /\ UNCHANGED vars
      [] E.t = "S" /\ E.k = "lock" -> mt_sem_signal_lock
      [] E.t = "S" /\ E.k = "resume" -> (ref # NULL) = E.r /\ mt_sem_signal_signal_i
      [] E.t = "S" /\ E.k = "unlock" -> Snapshot /\ mt_sem_signal_unlock
      [] E.t = "I" /\ E.k = "lock" -> lock = FREE /\ UNCHANGED vars
      [] E.t = "I" /\ E.k = "resume" -> (ref # NULL) = E.r /\ mt_sem_signal_isr
      [] E.t = "I" /\ E.k = "unlock" -> Snapshot /\ UNCHANGED vars

TraceInit == Init /\ ti = 1 /\ lastSt = "none"

TraceNext ==
    \/ /\ ti <= Len(Trace) /\ Step /\ ti' = ti + 1
       /\ lastSt' = IF E.t = "W" /\ E.k = "unlock" THEN wst[W] ELSE lastSt
    \/ Internal /\ UNCHANGED <<ti, lastSt>>
    \/ ti > Len(Trace) /\ UNCHANGED tvars     \* accepted: stutter

TraceSpec == TraceInit /\ [][TraceNext]_tvars

\* Violated exactly when the whole log has been matched.
TraceNotAccepted == ti <= Len(Trace)

=============================================================================
