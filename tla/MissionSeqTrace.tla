--------------------------- MODULE MissionSeqTrace ---------------------------
(***************************************************************************)
(* Trace validation of MissionSeq against the C code. tools/trace/        *)
(* mission_trace runs the real mission.c on a fixed mission with seeded    *)
(* random operations and callback outcomes, and logs each call: the        *)
(* callbacks it made (kind, index, outcome, in order) and the cursor state *)
(* it left (MissionSeqTraceData.tla). This module feeds the logged         *)
(* outcomes to the model's *With actions and requires, per event:          *)
(*   - the callbacks the model's step implies, in the same order and with  *)
(*     the same indices (a start index is the model's lastCb after it);   *)
(*   - the state after the event equal to the logged one (st, nav, dcmd,   *)
(*     ddone, wpos, prevNav, the jump counters);                           *)
(*   - a refused call (rc # OK) only where the C guard refuses it, with    *)
(*     no change and no callback.                                          *)
(* mt_mission_update is two model steps (UpdateA, UpdateB) and two events  *)
(* (update_nav, update_do); the state is compared after the second.       *)
(* The trace is accepted iff TLC reports TraceNotAccepted VIOLATED         *)
(* (the whole log matched), rejected iff it reports a deadlock.            *)
(***************************************************************************)
EXTENDS MissionSeq, MissionSeqTraceData, Sequences

VARIABLE ti     \* index of the next log event

tvars == <<allVars, ti>>

E == Trace[ti]

\* outcome of the j-th logged callback of the event (TRUE when there is none:
\* the model reads an outcome only where the C code calls a callback)
Out(j) == IF Len(E.cbs) >= j THEN E.cbs[j].r ELSE TRUE

\* the logged callbacks without their outcomes
Calls == [j \in 1..Len(E.cbs) |-> <<E.cbs[j].k, E.cbs[j].i>>]

StartCb(i) == <<"start", i>>
VerifyCb(i) == <<"verify", i>>
DoneCb == <<"done", 0>>

\* advance(): one nav start (the model's lastCb after the step) or the
\* complete callback
Advance == IF st' = "complete" THEN <<DoneCb>> ELSE <<StartCb(lastCb')>>

Snapshot == /\ st' = E.st /\ nav' = E.nav /\ dcmd' = E.dcmd /\ ddone' = E.ddone
            /\ wpos' = E.wpos /\ prevNav' = E.prev /\ cnt' = E.cnt

Refused(guard) == guard /\ Calls = <<>> /\ UNCHANGED allVars

\* update, nav part: verify the active nav, then advance when it completed
\* (or when none is active)
VN == IF nav # NONE THEN Out(1) ELSE TRUE
SN == IF nav # NONE THEN Out(2) ELSE Out(1)
NavCalls == (IF nav # NONE THEN <<VerifyCb(nav)>> ELSE <<>>)
            \o (IF nav = NONE \/ VN THEN Advance ELSE <<>>)
\* update, do part: verify the active do command, or start the next one
DoCalls == IF st # "running" \/ nav = NONE THEN <<>>
           ELSE IF dcmd # NONE THEN <<VerifyCb(dcmd)>>
           ELSE IF ddone \/ ddone' THEN <<>>
           ELSE <<StartCb(lastCb')>>

Step ==
    CASE E.op = "start" ->
            Idle(StartWith(Out(1))) /\ Calls = Advance
      [] E.op = "stop" ->
            IF E.rc = "OK" THEN Idle(Stop) /\ Calls = <<>>
            ELSE Refused(st # "running")
      [] E.op = "resume" ->
            IF E.rc = "OK"
            THEN \/ Idle(ResumeCompleteWith(Out(1))) /\ Calls = Advance
                 \/ Idle(ResumeFixWith(Out(1))) /\ Calls = Advance
                 \/ /\ Idle(ResumeRestartWith(Out(1), Out(2)))
                    /\ Calls = <<StartCb(nav)>> \o
                               (IF Out(1) THEN (IF dcmd # NONE THEN <<StartCb(dcmd)>> ELSE <<>>)
                                ELSE Advance)
            ELSE Refused(st = "running")
      [] E.op = "set_current" ->
            IF E.rc = "OK"
            THEN \/ Idle(SetCurrentIdleWith(E.arg)) /\ Calls = <<>>
                 \/ Idle(SetCurrentRunningWith(E.arg, Out(1))) /\ Calls = Advance
            ELSE Refused(E.arg >= N)
      [] E.op = "restart_current" ->
            IF E.rc = "OK"
            THEN /\ Idle(RestartCurrentWith(Out(1), Out(2)))
                 /\ Calls = <<StartCb(nav)>> \o (IF Out(1) THEN <<>> ELSE Advance)
            ELSE Refused(~(st = "running" /\ nav # NONE))
      [] E.op = "update" ->
            Refused(st # "running")
      [] E.op = "update_nav" ->
            UpdateAWith(VN, SN) /\ Calls = NavCalls
      [] E.op = "update_do" ->
            UpdateBWith(Out(1), Out(1)) /\ Calls = DoCalls

TraceInit == InitAll /\ ti = 1

TraceNext ==
    \/ /\ ti <= Len(Trace) /\ Step /\ (E.snap => Snapshot) /\ ti' = ti + 1
    \/ ti > Len(Trace) /\ UNCHANGED tvars     \* accepted: stutter

TraceSpec == TraceInit /\ [][TraceNext]_tvars

\* Violated exactly when the whole log has been matched.
TraceNotAccepted == ti <= Len(Trace)

=============================================================================
