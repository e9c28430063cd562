---------------------------- MODULE MissionTrace -----------------------------
(***************************************************************************)
(* Trace validation of Mission against the C code. tools/trace/           *)
(* mission_trace runs the real mission*.c on a fixed mission with seeded   *)
(* random operations and callback outcomes, and logs each call: the        *)
(* callbacks it made (kind, index, outcome, in order) and the state it     *)
(* left (MissionTraceData.tla). Per event, the model must take a step      *)
(* of the action of that call (its own nondeterminism: every outcome of    *)
(* every callback) such that                                               *)
(*   - the callbacks of the step (cbs') are the logged ones, in the same   *)
(*     order, with the same indices and outcomes (but a do command's start *)
(*     result, which mission_seq.c ignores);                               *)
(*   - the state after the event is the logged one (st, nav, navIdx, dcmd, *)
(*     doIdx, ddone, prevNav, the jump counters);                          *)
(*   - a refused call (rc # OK) comes only where the C guard refuses it,   *)
(*     with the logged status, no change and no callback.                  *)
(* mt_mission_update is two model steps (UpdateNav, UpdateDo) and two      *)
(* events (update_nav, update_do); the state is compared after the second. *)
(* The trace is accepted iff TLC reports TraceNotAccepted VIOLATED         *)
(* (the whole log matched), rejected iff it reports a deadlock.            *)
(***************************************************************************)
EXTENDS Mission, MissionTraceData, Sequences

VARIABLE ti     \* index of the next log event

tvars == <<allVars, ti>>

E == Trace[ti]

\* the step's callbacks are the logged ones
CallsMatch ==
    /\ Len(cbs') = Len(E.cbs)
    /\ \A k \in 1..Len(cbs') :
          /\ cbs'[k][1] = E.cbs[k].k /\ cbs'[k][2] = E.cbs[k].i
          /\ (cbs'[k][1] = "start" /\ Kind[cbs'[k][2]] = "do") \/ cbs'[k][3] = E.cbs[k].r

Snapshot == /\ st' = E.st /\ nav' = E.nav /\ navIdx' = E.navidx /\ dcmd' = E.dcmd
            /\ doIdx' = E.doidx /\ ddone' = E.ddone /\ prevNav' = E.prev /\ cnt' = E.cnt

Refused(rc, guard) == E.rc = rc /\ guard /\ E.cbs = <<>> /\ UNCHANGED allVars

Step ==
    CASE E.op = "start" ->
            E.rc = "OK" /\ Start /\ CallsMatch
      [] E.op = "stop" ->
            IF E.rc = "OK" THEN Stop /\ CallsMatch ELSE Refused("E_STATE", st # "running")
      [] E.op = "resume" ->
            IF E.rc = "OK" THEN Resume /\ CallsMatch ELSE Refused("E_STATE", st = "running")
      [] E.op = "set_current" ->
            IF E.rc = "OK" THEN E.arg < N /\ SetCurrentAt(E.arg) /\ CallsMatch
            ELSE \/ Refused("E_INVALID", E.arg >= N)
                 \/ Refused("E_EMPTY", E.arg < N /\ SetCurrentEmpty(E.arg))
      [] E.op = "restart_current" ->
            IF E.rc = "OK" THEN RestartCurrent /\ CallsMatch
            ELSE Refused("E_STATE", ~(st = "running" /\ navIdx # NONE))
      [] E.op = "update" ->
            Refused("E_STATE", st # "running")
      [] E.op = "update_nav" ->
            E.rc = "OK" /\ UpdateNav /\ CallsMatch
      [] E.op = "update_do" ->
            E.rc = "OK" /\ UpdateDo /\ CallsMatch

TraceInit == Init /\ ti = 1

TraceNext ==
    \/ /\ ti <= Len(Trace) /\ Step /\ (E.snap => Snapshot) /\ ti' = ti + 1
    \/ ti > Len(Trace) /\ UNCHANGED tvars     \* accepted: stutter

TraceSpec == TraceInit /\ [][TraceNext]_tvars

\* Violated exactly when the whole log has been matched.
TraceNotAccepted == ti <= Len(Trace)

=============================================================================
