---------------------------- MODULE MissionSeq ----------------------------
(* Mission-command sequencing (kernel/src/mission.c, mt/mission.h).
   One fixed mission per configuration: Kind, Tgt, Rep over indices 1..N-1
   (0 is home, N is the end). Actions are named after the C functions; the
   environment chooses every start and verify outcome. One C call is one step
   (the sequencer is single-threaded; callbacks are the only interleaving
   points and may not touch the mission: assumption A1). *)
EXTENDS Integers, Sequences, FiniteSets

CONSTANTS N, Kind, Tgt, Rep, NONE

Idx == 1..(N-1)
VARIABLES st, nav, dcmd, ddone, wpos, cnt, runDone, lastCb, prevNav
vars == <<st, nav, dcmd, ddone, wpos, cnt, runDone, lastCb, prevNav>>

\* one node of the walk: where it goes, with and without counting
Next1(p, c) == IF Kind[p] = "jump" /\ (Rep[p] < 0 \/ c[p] < Rep[p]) THEN Tgt[p] ELSE p + 1
Count1(p, c) == IF Kind[p] = "jump" /\ Rep[p] >= 0
                THEN IF c[p] < Rep[p] THEN [c EXCEPT ![p] = @ + 1] ELSE [c EXCEPT ![p] = 0]
                ELSE c

\* mt_mission_next_nav: pure look-ahead, bounded by N steps (-1: bound hit)
RECURSIVE Look(_, _, _)
Look(p, c, k) == IF k = 0 THEN -1 ELSE IF p >= N THEN N
                 ELSE IF Kind[p] = "nav" THEN p ELSE Look(Next1(p, c), c, k - 1)

\* walk(): moves the execution position, counting jumps; <<stop index, counters>>
RECURSIVE Walk(_, _, _, _)
Walk(p, c, stopDo, k) == IF k = 0 \/ p >= N THEN <<N, c>>
                         ELSE IF Kind[p] = "nav" \/ (stopDo /\ Kind[p] = "do") THEN <<p, c>>
                         ELSE Walk(Next1(p, c), Count1(p, c), stopDo, k - 1)

Init == /\ st = "stopped" /\ nav = NONE /\ dcmd = NONE /\ ddone = FALSE /\ wpos = 1
        /\ cnt = [i \in Idx |-> 0] /\ runDone = 0 /\ lastCb = NONE /\ prevNav = NONE

\* finish(): the only place the complete callback runs
Finish == /\ st' = "complete" /\ nav' = NONE /\ dcmd' = NONE /\ ddone' = FALSE
          /\ runDone' = runDone + 1

\* nav_done() then advance(): drop the do command, pass the nav, load the next
\* (one start attempt, outcome s)
AdvanceFrom(p, c, s, pn) ==
    LET n == Look(p, c, N) IN
    IF n = N \/ n = -1
    THEN Finish /\ wpos' = p /\ cnt' = c /\ lastCb' = lastCb /\ prevNav' = pn
    ELSE /\ lastCb' = n /\ st' = "running" /\ dcmd' = NONE /\ ddone' = FALSE /\ runDone' = runDone
         /\ IF s THEN nav' = n /\ wpos' = p /\ cnt' = c /\ prevNav' = pn
            ELSE LET w == Walk(p, c, FALSE, N) IN
                 /\ nav' = NONE /\ prevNav' = n
                 /\ wpos' = (IF w[1] < N THEN w[1] + 1 ELSE N) /\ cnt' = w[2]

NavDone == LET w == Walk(wpos, cnt, FALSE, N) IN
           <<IF w[1] < N THEN w[1] + 1 ELSE N, w[2]>>

\* mt_mission_start with start outcome s (the *With forms pin the environment's
\* choices; tla/MissionSeqTrace.tla feeds them from a log of the C code)
StartWith(s) ==
    LET n == Look(1, [i \in Idx |-> 0], N) IN
    IF n = N \/ n = -1
    THEN /\ st' = "complete" /\ nav' = NONE /\ dcmd' = NONE /\ ddone' = FALSE /\ runDone' = 1
         /\ wpos' = 1 /\ cnt' = [i \in Idx |-> 0] /\ lastCb' = lastCb /\ prevNav' = NONE
    ELSE /\ st' = "running" /\ runDone' = 0 /\ lastCb' = n /\ dcmd' = NONE /\ ddone' = FALSE
         /\ IF s THEN nav' = n /\ wpos' = 1 /\ cnt' = [i \in Idx |-> 0] /\ prevNav' = NONE
            ELSE LET w == Walk(1, [i \in Idx |-> 0], FALSE, N) IN
                 /\ nav' = NONE /\ prevNav' = n /\ wpos' = (IF w[1] < N THEN w[1] + 1 ELSE N) /\ cnt' = w[2]

Stop == /\ st = "running" /\ st' = "stopped"
        /\ UNCHANGED <<nav, dcmd, ddone, wpos, cnt, runDone, lastCb, prevNav>>

\* resume from STOPPED with no active nav: advance from the position
ResumeFixWith(s) ==
    /\ st = "stopped" /\ nav = NONE
    /\ LET n == Look(wpos, cnt, N) IN
       IF n = N \/ n = -1
       THEN /\ st' = "complete" /\ nav' = NONE /\ dcmd' = NONE /\ ddone' = FALSE /\ runDone' = runDone + 1
            /\ UNCHANGED <<wpos, cnt, lastCb, prevNav>>
       ELSE /\ st' = "running" /\ runDone' = runDone /\ lastCb' = n /\ dcmd' = NONE /\ ddone' = FALSE
            /\ IF s THEN nav' = n /\ UNCHANGED <<wpos, cnt, prevNav>>
               ELSE LET w == Walk(wpos, cnt, FALSE, N) IN
                    /\ nav' = NONE /\ prevNav' = n /\ wpos' = (IF w[1] < N THEN w[1] + 1 ELSE N) /\ cnt' = w[2]
\* resume with an active nav: start it (outcome s) and then the do command
\* (outcome s2) again; a refused nav = done, and advance() loads the next one
\* at once (outcome s2) or completes the mission (restart_nav)
ResumeRestartWith(s, s2) ==
    /\ st = "stopped" /\ nav # NONE
    /\ IF s THEN /\ st' = "running" /\ lastCb' = (IF dcmd # NONE THEN dcmd ELSE nav)
                 \* the do command's new start (outcome s2): refused = done
                 /\ dcmd' = (IF dcmd # NONE /\ ~s2 THEN NONE ELSE dcmd)
                 /\ UNCHANGED <<nav, ddone, wpos, cnt, runDone, prevNav>>
       ELSE LET w == NavDone IN AdvanceFrom(w[1], w[2], s2, nav)
ResumeCompleteWith(s) == st = "complete" /\ StartWith(s)

\* set_current while not running: position only (COMPLETE resets counters)
SetCurrentIdleWith(i) ==
    /\ st # "running"
    /\ st' = "stopped" /\ nav' = NONE /\ dcmd' = NONE /\ ddone' = FALSE
    /\ wpos' = (IF i = 0 THEN 1 ELSE i)
    /\ cnt' = (IF i = 0 \/ st = "complete" THEN [j \in Idx |-> 0] ELSE cnt)
    /\ prevNav' = (IF i = 0 \/ st = "complete" THEN NONE ELSE prevNav)
    /\ runDone' = (IF st = "complete" THEN 0 ELSE runDone)   \* a new run begins
    /\ UNCHANGED lastCb
\* set_current while running: drop both cursors, load the nav at or after i
SetCurrentRunningWith(i, s) ==
    /\ st = "running"
    /\ LET p == IF i = 0 THEN 1 ELSE i
           c == IF i = 0 THEN [j \in Idx |-> 0] ELSE cnt
           n == Look(p, c, N)
           pn == IF i = 0 THEN NONE ELSE prevNav   \* rewind() when i = 0
       IN
       IF n = N \/ n = -1
       THEN /\ st' = "complete" /\ nav' = NONE /\ dcmd' = NONE /\ ddone' = FALSE /\ runDone' = runDone + 1
            /\ wpos' = p /\ cnt' = c /\ lastCb' = lastCb /\ prevNav' = pn
       ELSE /\ st' = "running" /\ runDone' = runDone /\ lastCb' = n /\ dcmd' = NONE /\ ddone' = FALSE
            /\ IF s THEN nav' = n /\ wpos' = p /\ cnt' = c /\ prevNav' = pn
               ELSE LET w == Walk(p, c, FALSE, N) IN
                    /\ nav' = NONE /\ prevNav' = n /\ wpos' = (IF w[1] < N THEN w[1] + 1 ELSE N) /\ cnt' = w[2]

\* restart_current (restart_nav): start the nav again (outcome s); a refusal
\* completes it and advance() loads the next one at once (start outcome s2)
\* or completes the mission
RestartCurrentWith(s, s2) ==
    /\ st = "running" /\ nav # NONE
    /\ IF s THEN lastCb' = nav /\ UNCHANGED <<st, nav, dcmd, ddone, wpos, cnt, runDone, prevNav>>
       ELSE LET w == NavDone IN AdvanceFrom(w[1], w[2], s2, nav)

\* the actions with every outcome (and every index) the environment may choose
StartAct == \E s \in BOOLEAN : StartWith(s)
ResumeFix == \E s \in BOOLEAN : ResumeFixWith(s)
ResumeRestart == \E s, s2 \in BOOLEAN : ResumeRestartWith(s, s2)
ResumeComplete == \E s \in BOOLEAN : ResumeCompleteWith(s)
mt_mission_resume == ResumeFix \/ ResumeRestart \/ ResumeComplete
SetCurrentIdle == \E i \in 0..(N-1) : SetCurrentIdleWith(i)
SetCurrentRunning == \E i \in 0..(N-1), s \in BOOLEAN : SetCurrentRunningWith(i, s)
RestartCurrent == \E s, s2 \in BOOLEAN : RestartCurrentWith(s, s2)

\* mt_mission_update, nav part (vn: verify outcome, sn: start outcome)
UpdateNav(vn, sn) ==
    /\ st = "running"
    /\ IF nav = NONE
       THEN AdvanceFrom(wpos, cnt, sn, prevNav)
       ELSE IF vn THEN LET w == NavDone IN AdvanceFrom(w[1], w[2], sn, nav)
            ELSE UNCHANGED <<st, nav, dcmd, ddone, wpos, cnt, runDone, lastCb, prevNav>>
\* do part (vd: verify outcome, sd: start outcome), after the nav part
DoPart(vd, sd) ==
    IF st # "running" \/ nav = NONE THEN UNCHANGED <<dcmd, ddone, wpos, cnt, lastCb>>
    ELSE IF dcmd # NONE
         THEN /\ dcmd' = (IF vd THEN NONE ELSE dcmd) /\ UNCHANGED <<ddone, wpos, cnt, lastCb>>
         ELSE IF ddone THEN UNCHANGED <<dcmd, ddone, wpos, cnt, lastCb>>
         ELSE LET w == Walk(wpos, cnt, TRUE, N) IN
              IF w[1] < N /\ Kind[w[1]] = "do"
              THEN /\ wpos' = w[1] + 1 /\ cnt' = w[2] /\ lastCb' = w[1]
                   /\ dcmd' = (IF sd THEN w[1] ELSE NONE) /\ ddone' = FALSE
              ELSE /\ ddone' = TRUE /\ wpos' = w[1] /\ cnt' = w[2] /\ UNCHANGED <<dcmd, lastCb>>

\* the do part reads the state left by the nav part: compose through a
\* separate step flag would double the state space; instead the C order
\* (nav then do) is modelled as two steps that no other action can split.
VARIABLE phase
UpdateAWith(vn, sn) == phase = "idle" /\ UpdateNav(vn, sn) /\ phase' = "do"
UpdateBWith(vd, sd) == phase = "do" /\ phase' = "idle" /\ DoPart(vd, sd)
                       /\ UNCHANGED <<st, nav, runDone, prevNav>>
UpdateA == \E vn, sn \in BOOLEAN : UpdateAWith(vn, sn)
UpdateB == \E vd, sd \in BOOLEAN : UpdateBWith(vd, sd)
UpdateGoodA == phase = "idle" /\ UpdateNav(TRUE, TRUE) /\ phase' = "do"
UpdateGoodB == phase = "do" /\ phase' = "idle" /\ DoPart(TRUE, TRUE) /\ UNCHANGED <<st, nav, runDone, prevNav>>

allVars == <<vars, phase>>
Idle(A) == phase = "idle" /\ A /\ phase' = "idle"

Next == \/ Idle(StartAct) \/ Idle(Stop) \/ Idle(mt_mission_resume)
        \/ Idle(SetCurrentIdle) \/ Idle(SetCurrentRunning) \/ Idle(RestartCurrent)
        \/ UpdateA \/ UpdateB

InitAll == Init /\ phase = "idle"
Spec == InitAll /\ [][Next]_allVars

\* ---------------------------------------------------------------- properties
CursorsValid == /\ nav = NONE \/ (nav \in Idx /\ Kind[nav] = "nav")
                /\ dcmd = NONE \/ (dcmd \in Idx /\ Kind[dcmd] = "do" /\ nav # NONE)
                /\ prevNav = NONE \/ (prevNav \in Idx /\ Kind[prevNav] = "nav")
                /\ wpos \in 1..N
CountersBounded == \A i \in Idx : Kind[i] = "jump" =>
                      IF Rep[i] >= 0 THEN cnt[i] \in 0..Rep[i] ELSE cnt[i] = 0
NoCallbackSeesJump == lastCb = NONE \/ Kind[lastCb] \in {"nav", "do"}
CompleteOncePerRun == /\ runDone \in 0..1
                      /\ st = "complete" => runDone = 1
                      /\ st = "running" => runDone = 0
LookAheadBounded == Look(wpos, cnt, N) # -1
\* the look-ahead from the execution position finds the active nav command
LookAheadMatches == (phase = "idle" /\ nav # NONE) => Look(wpos, cnt, N) = nav
TypeOK == st \in {"stopped", "running", "complete"} /\ phase \in {"idle", "do"}

\* liveness: only updates (verifies and starts eventually succeed) after a start
LiveStart == st = "stopped" /\ StartAct
LiveNext == Idle(LiveStart) \/ UpdateA \/ UpdateB
LiveSpec == InitAll /\ [][LiveNext]_allVars /\ WF_allVars(Idle(LiveStart))
            /\ SF_allVars(UpdateGoodA) /\ WF_allVars(UpdateB) /\ SF_allVars(UpdateGoodB)
Completes == <>(st = "complete")
=============================================================================
