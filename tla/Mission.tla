----------------------------- MODULE Mission ------------------------------
(***************************************************************************)
(* Mission-command sequencing (kernel/src/mission*.c, mt/mission.h), with *)
(* ArduPilot AP_Mission's rules.                                           *)
(*                                                                         *)
(* One fixed mission per configuration: Kind, Tgt, Rep over indices        *)
(* 1..N-1 (0 is home, N is the end, so N is the C's m->total). The         *)
(* sequencer is single-threaded and the callbacks may not touch the        *)
(* mission (assumption A1), so one C call is one step; the environment     *)
(* chooses every start and verify outcome. mt_mission_update is two steps  *)
(* no other action can split (UpdateNav: verify the nav command and        *)
(* advance; UpdateDo: verify the do command, also one the advance has just *)
(* started, or search the next one), so that a trace of the C code is      *)
(* compared in the middle of the call too.                                 *)
(*                                                                         *)
(* The C fields are variables of the same meaning (MT_MISSION_NONE is      *)
(* NONE): st = state, nav, navIdx = nav_idx, dcmd = do_cmd, doIdx =        *)
(* do_idx, ddone = do_done, prevNav = prev_nav, cnt = count[]. The C       *)
(* functions are operators on a record of those fields (Cur), named after  *)
(* them: jump_peek JumpPeek, jump_take JumpTake, peek_cmd PeekCmd,         *)
(* take_cmd TakeCmd, look_nav LookNav (mt_mission_next_nav's walk),        *)
(* finish Finish, drop_both DropBoth, set_do SetDo, start_do StartDo,      *)
(* verify_do VerifyDo, set_nav SetNav, note_do NoteDo, forget_nav          *)
(* ForgetNav, load_nav LoadNav, attach_do AttachDo, advance Advance (its   *)
(* loop AdvLoop), advance_or_finish AdvanceOrFinish, zero_counts           *)
(* ZeroCounts, rewind_walk RewindWalk, preload Preload (PreLoop),          *)
(* do_search DoSearch, nav_step NavStep, do_step DoStep. The public calls: *)
(* mt_mission_start StartOp / Start, mt_mission_stop Stop,                 *)
(* mt_mission_resume ResumeOp / Resume, mt_mission_set_current             *)
(* SetCurrentOp / SetCurrentAt(i) (SetCurrentEmpty: its MT_E_EMPTY),       *)
(* mt_mission_restart_current RestartCurrentOp / RestartCurrent,           *)
(* mt_mission_update NavStep / UpdateNav then DoStep / UpdateDo.           *)
(* An *Op is the set of records a call can leave, one per choice of        *)
(* callback outcomes (Advance: each nav start accepted, and the walk       *)
(* stops, or refused; the verify outcomes). A do command's start result is *)
(* ignored by the C code, so it is no choice here.                         *)
(*                                                                         *)
(* Ghost state: runDone (completions in this run), cbs (the callbacks the *)
(* last step made, in order: <<"start" | "verify" | "done", index,         *)
(* outcome>>; outcome TRUE for a do start, whose result is ignored, and    *)
(* for done), adv (where the last step's advance began, from, and the jump *)
(* counters then; from = 0: the step made no advance), phase (the update  *)
(* halves). AdvanceFollowsOrder, FirstDoBeforeNav and TrailingDoStarts     *)
(* are stated over cbs and adv with a walk of their own (Order), not with *)
(* the actions.                                                            *)
(*                                                                         *)
(* VARIANT "ap" is mission*.c. The two broken variants bring back the old *)
(* rules (mission.c before the AP rewrite), each a must-fail control:      *)
(*   "do_after_nav": the advance starts no do command; the do search,      *)
(*     which runs once per update after the nav half, starts the do        *)
(*     commands the advance passed, one per update, from the first one:    *)
(*     each starts after the nav command that follows it;                  *)
(*   "trailing_do_lost": the first do command passed is started only when  *)
(*     the walk reaches a nav command (just before that start), so a do    *)
(*     command after the last nav command is never started.                *)
(* Extra is MT_CFG_MISSION_ADVANCE_EXTRA (the C default is 255; the model  *)
(* configurations use 2, as the CBMC harnesses do).                        *)
(***************************************************************************)
EXTENDS Integers, Sequences, FiniteSets

CONSTANTS N, Kind, Tgt, Rep, NONE, Extra, VARIANT

ASSUME /\ N \in Nat /\ N >= 2 /\ NONE \notin 1..N /\ Extra \in Nat /\ Extra >= 1
       /\ VARIANT \in {"ap", "do_after_nav", "trailing_do_lost"}

Idx == 1..(N-1)
DoClass == {"do", "tag"}        \* take the do slot (a JUMP_TAG is handled here)
Zero == [i \in Idx |-> 0]
Loop == -1                      \* look_nav's MT_MISSION_NONE: its bound was hit
NoAdv == [from |-> 0, c |-> Zero]

VARIABLES st, nav, navIdx, dcmd, doIdx, ddone, prevNav, cnt,   \* the C fields
          runDone, cbs, adv, phase                            \* ghost
vars == <<st, nav, navIdx, dcmd, doIdx, ddone, prevNav, cnt, runDone, cbs, adv>>
allVars == <<vars, phase>>

StartCb(i, r) == <<"start", i, r>>
VerifyCb(i, r) == <<"verify", i, r>>
DoneCb == <<"done", 0, TRUE>>

\* the fields as a record; a step's callbacks and advance start empty
Cur == [st |-> st, nav |-> nav, navIdx |-> navIdx, dcmd |-> dcmd, doIdx |-> doIdx,
        ddone |-> ddone, prevNav |-> prevNav, cnt |-> cnt, runDone |-> runDone,
        cbs |-> <<>>, adv |-> NoAdv]
Set(s) == /\ st' = s.st /\ nav' = s.nav /\ navIdx' = s.navIdx /\ dcmd' = s.dcmd
          /\ doIdx' = s.doIdx /\ ddone' = s.ddone /\ prevNav' = s.prevNav /\ cnt' = s.cnt
          /\ runDone' = s.runDone /\ cbs' = s.cbs /\ adv' = s.adv
Call(s, cb) == [s EXCEPT !.cbs = Append(s.cbs, cb)]

\* ------------------------------------------------------------ execution walk
\* jump_peek: where a resolution goes from the jump at p, without counting
\* (fresh: as if every counter were 0)
JumpPeek(p, c, fresh) ==
    IF Rep[p] < 0 \/ (IF fresh THEN 0 ELSE c[p]) < Rep[p] THEN Tgt[p] ELSE p + 1
\* jump_take: <<where, counters>>: taken Rep[p] times, then fall through and reset
JumpTake(p, c) ==
    IF Rep[p] < 0 THEN <<Tgt[p], c>>
    ELSE IF c[p] < Rep[p] THEN <<Tgt[p], [c EXCEPT ![p] = @ + 1]>>
    ELSE <<p + 1, [c EXCEPT ![p] = 0]>>

\* peek_cmd / take_cmd: the first command at or after p that is not a jump
\* (N at the end, or when the bound of N jumps is hit)
RECURSIVE PeekCmdK(_, _, _)
PeekCmdK(q, c, k) == IF k = 0 THEN N
                     ELSE IF q >= N \/ Kind[q] # "jump" THEN q
                     ELSE PeekCmdK(JumpPeek(q, c, FALSE), c, k - 1)
PeekCmd(p, c) == PeekCmdK(p, c, N)
RECURSIVE TakeCmdK(_, _, _)
TakeCmdK(q, c, k) == IF k = 0 THEN <<N, c>>
                     ELSE IF q >= N \/ Kind[q] # "jump" THEN <<q, c>>
                     ELSE LET t == JumpTake(q, c) IN TakeCmdK(t[1], t[2], k - 1)
TakeCmd(p, c) == TakeCmdK(p, c, N)

\* look_nav: the nav command the walk from p reaches first, jumps followed
\* without counting; N at the end, Loop when the bound (N steps) is hit
RECURSIVE LookNavK(_, _, _, _)
LookNavK(q, c, fresh, k) ==
    IF k = 0 THEN Loop
    ELSE IF q >= N THEN N
    ELSE IF Kind[q] = "nav" THEN q
    ELSE LookNavK(IF Kind[q] = "jump" THEN JumpPeek(q, c, fresh) ELSE q + 1, c, fresh, k - 1)
LookNav(p, c, fresh) == LookNavK(p, c, fresh, N)

\* finish: the only call of the complete callback
Finish(s) == Call([s EXCEPT !.st = "complete", !.nav = NONE, !.dcmd = NONE, !.ddone = FALSE,
                            !.runDone = @ + 1], DoneCb)
DropBoth(s) == [s EXCEPT !.dcmd = NONE, !.doIdx = NONE, !.ddone = FALSE, !.nav = NONE]
SetDo(s, d) == [s EXCEPT !.doIdx = d, !.dcmd = d]
\* start_do: a JUMP_TAG gets no callback; a do command's start result is ignored
StartDo(s) == IF Kind[s.dcmd] = "do" THEN Call(s, StartCb(s.dcmd, TRUE)) ELSE s
\* verify_do (outcome v): [res, s]; a JUMP_TAG verifies at once, no callback
VerifyDo(s, v) == IF Kind[s.dcmd] # "do" THEN [res |-> TRUE, s |-> s]
                  ELSE [res |-> v, s |-> Call(s, VerifyCb(s.dcmd, v))]
SetNav(s, p, started) ==
    [s EXCEPT !.prevNav = s.navIdx, !.navIdx = p, !.nav = IF started THEN p ELSE s.nav]

\* note_do: the first do-class command the walk passed, recorded, not active
NoteDo(s, r) == [s EXCEPT !.doIdx = r]
\* forget_nav / load_nav: the stopped walk found no nav command / found p
ForgetNav(s) == [s EXCEPT !.navIdx = NONE]
LoadNav(s, p) == [s EXCEPT !.navIdx = p, !.nav = p]
\* attach_do: a nav command has just become active; the do-class command d
\* recorded on the way becomes active with it, with none ddone is set
AttachDo(s, d) == IF d # NONE THEN [s EXCEPT !.dcmd = d] ELSE [s EXCEPT !.ddone = TRUE]
\* the advance's attach_do; "do_after_nav": nothing is active, the do search
\* starts at d (doIdx is the index before it)
AdvAttachDo(s, d) ==
    IF VARIANT = "do_after_nav" /\ d # NONE
    THEN [s EXCEPT !.doIdx = IF d = 1 THEN NONE ELSE d - 1]
    ELSE AttachDo(s, d)

\* advance's loop: q the next index, k iterations left, d the first do-class
\* command passed (NONE: none yet), pd a do start held back until the next
\* nav command ("trailing_do_lost" only). The sequence of the [res, s] the
\* loop can return, one per outcome of the nav starts: each nav start is
\* accepted (res 1, the walk stops) or refused (the walk goes on); res 0: the
\* end of the list or the bound.
RECURSIVE AdvLoop(_, _, _, _, _)
AdvLoop(s, q, k, d, pd) ==
    IF k = 0 THEN <<[res |-> 0, s |-> s]>>
    ELSE LET t == TakeCmd(q, s.cnt)
             r == t[1]
             s1 == [s EXCEPT !.cnt = t[2]]
         IN IF r >= N THEN <<[res |-> 0, s |-> s1]>>
            ELSE IF Kind[r] = "nav"
            THEN LET s0 == IF pd # NONE THEN Call(s1, StartCb(pd, TRUE)) ELSE s1
                 IN <<[res |-> 1, s |-> AdvAttachDo(SetNav(Call(s0, StartCb(r, TRUE)), r, TRUE), d)]>>
                    \o AdvLoop(SetNav(Call(s0, StartCb(r, FALSE)), r, FALSE), r + 1, k - 1, d, NONE)
            ELSE IF d = NONE
            THEN LET s2 == NoteDo(s1, r)
                     now == Kind[r] = "do" /\ VARIANT = "ap"
                     held == IF Kind[r] = "do" /\ VARIANT = "trailing_do_lost" THEN r ELSE NONE
                 IN AdvLoop(IF now THEN Call(s2, StartCb(r, TRUE)) ELSE s2, r + 1, k - 1, r, held)
            ELSE AdvLoop(s1, r + 1, k - 1, d, pd)   \* a later do command: passed

\* advance from p: both commands dropped, at most N + Extra commands visited
Advance(s, p) == LET as == AdvLoop(DropBoth(s), p, N + Extra, NONE, NONE)
                 IN {[as[k] EXCEPT !.s.adv = [from |-> p, c |-> s.cnt]] : k \in 1..Len(as)}
\* advance_or_finish: res 0 completes the mission
AdvanceOrFinish(s, p) == {IF a.res = 0 THEN Finish(a.s) ELSE a.s : a \in Advance(s, p)}

ZeroCounts(s) == [s EXCEPT !.cnt = Zero]
RewindWalk(s) == [DropBoth(ZeroCounts(s)) EXCEPT !.navIdx = NONE, !.prevNav = NONE]

\* preload (not running): walk from p, counting, to the first nav command;
\* it and the first do-class command passed become active, nothing starts
RECURSIVE PreLoop(_, _, _, _)
PreLoop(s, q, k, d) ==
    IF k = 0 THEN ForgetNav(s)
    ELSE LET t == TakeCmd(q, s.cnt)
             r == t[1]
             s1 == [s EXCEPT !.cnt = t[2]]
         IN IF r >= N THEN ForgetNav(s1)
            ELSE IF Kind[r] = "nav" THEN AttachDo(LoadNav(s1, r), d)
            ELSE IF d = NONE THEN PreLoop(NoteDo(s1, r), r + 1, k - 1, r)
            ELSE PreLoop(s1, r + 1, k - 1, d)
Preload(s, p) == PreLoop(DropBoth(s), p, N, NONE)

\* do_search: the next command after doIdx (jumps peeked) starts if it is of
\* the do class; a nav command or the end sets ddone
DoSearch(s) ==
    IF s.ddone THEN s
    ELSE LET r == PeekCmd(IF s.doIdx = NONE THEN 1 ELSE s.doIdx + 1, s.cnt)
         IN IF r >= N \/ Kind[r] = "nav" THEN [s EXCEPT !.ddone = TRUE]
            ELSE StartDo(SetDo(s, r))

\* ------------------------------------------------------------ the calls
\* Each *Op is the set of records the call can leave (one per choice of
\* callback outcomes; the outcomes are in the record's cbs).

\* mt_mission_start (N >= 2, so never MT_E_EMPTY); a new run begins
StartOp(s) == AdvanceOrFinish([RewindWalk(s) EXCEPT !.st = "running", !.runDone = 0], 1)

\* mt_mission_resume (not running): COMPLETE or no nav command set: start;
\* else RUNNING and advance from the active do command, or the active nav
ResumeOp(s) ==
    IF s.st = "complete" \/ s.navIdx = NONE THEN StartOp(s)
    ELSE LET s1 == [s EXCEPT !.st = "running"]
         IN IF s.dcmd # NONE THEN AdvanceOrFinish(s1, s.dcmd)
            ELSE IF s.nav # NONE THEN AdvanceOrFinish(s1, s.nav)
            ELSE {s1}

\* mt_mission_set_current(i), i in 0..N-1 (i >= N is MT_E_INVALID): MT_E_EMPTY
\* when not running and no nav command is ahead (nothing changes)
SetCurrentEmpty(i) ==
    st # "running" /\ LookNav(IF i = 0 THEN 1 ELSE i, cnt, i = 0 \/ st = "complete") \notin Idx
SetCurrentOp(s, i) ==
    LET p == IF i = 0 THEN 1 ELSE i
        s0 == IF i = 0 \/ s.st = "complete" THEN [ZeroCounts(s) EXCEPT !.prevNav = NONE] ELSE s
    IN IF s.st = "running" THEN AdvanceOrFinish(s0, p)
       ELSE {[Preload(s0, p) EXCEPT !.st = "stopped", !.runDone = 0]}

\* mt_mission_restart_current (running, a nav command set): advance from it
RestartCurrentOp(s) == AdvanceOrFinish(s, s.navIdx)

\* mt_mission_update, nav half (nav_step): verify the active nav command;
\* when it verifies, or none is active, advance from navIdx + 1; the end
\* completes the mission and ends the call
NavStep(s) ==
    LET from == IF s.navIdx = NONE THEN 1 ELSE s.navIdx + 1
    IN IF s.nav = NONE THEN AdvanceOrFinish(s, from)
       ELSE {Call(s, VerifyCb(s.nav, FALSE))} \cup AdvanceOrFinish(Call(s, VerifyCb(s.nav, TRUE)), from)
\* do half (do_step, none after a completion): verify the active do command,
\* also one the nav half's advance has just started, or run the do search
DoStep(s) ==
    IF s.st # "running" THEN {s}
    ELSE IF s.dcmd = NONE THEN {DoSearch(s)}
    ELSE {LET v == VerifyDo(s, vd) IN IF v.res THEN [v.s EXCEPT !.dcmd = NONE] ELSE v.s : vd \in BOOLEAN}

\* the actions (phase: the update's halves are two steps nothing can split)
Idle(A) == phase = "idle" /\ A /\ phase' = "idle"
Start == Idle(\E r \in StartOp(Cur) : Set(r))
Stop == Idle(st = "running" /\ Set([Cur EXCEPT !.st = "stopped"]))
Resume == Idle(st # "running" /\ \E r \in ResumeOp(Cur) : Set(r))
SetCurrentAt(i) == Idle(~SetCurrentEmpty(i) /\ \E r \in SetCurrentOp(Cur, i) : Set(r))
SetCurrent == \E i \in 0..(N-1) : SetCurrentAt(i)
RestartCurrent == Idle(st = "running" /\ navIdx # NONE /\ \E r \in RestartCurrentOp(Cur) : Set(r))
UpdateNav == phase = "idle" /\ st = "running" /\ phase' = "do" /\ \E r \in NavStep(Cur) : Set(r)
UpdateDo == phase = "do" /\ phase' = "idle" /\ \E r \in DoStep(Cur) : Set(r)

Init == /\ st = "stopped" /\ nav = NONE /\ navIdx = NONE /\ dcmd = NONE /\ doIdx = NONE
        /\ ddone = FALSE /\ prevNav = NONE /\ cnt = Zero
        /\ runDone = 0 /\ cbs = <<>> /\ adv = NoAdv /\ phase = "idle"

Next == Start \/ Stop \/ Resume \/ SetCurrent \/ RestartCurrent \/ UpdateNav \/ UpdateDo
Spec == Init /\ [][Next]_allVars

\* ---------------------------------------------------------------- properties
TypeOK == /\ st \in {"stopped", "running", "complete"} /\ phase \in {"idle", "do"}
          /\ {nav, navIdx, dcmd, doIdx, prevNav} \subseteq Idx \cup {NONE}
          /\ ddone \in BOOLEAN /\ cnt \in [Idx -> Int] /\ runDone \in Nat
          /\ adv.from \in 0..N /\ adv.c \in [Idx -> Int]
          /\ \A k \in 1..Len(cbs) : cbs[k][1] \in {"start", "verify", "done"} /\ cbs[k][3] \in BOOLEAN
\* ~ MtMissionCursors (mission.h)
CursorsValid == /\ navIdx = NONE \/ (navIdx \in Idx /\ Kind[navIdx] = "nav")
                /\ prevNav = NONE \/ (prevNav \in Idx /\ Kind[prevNav] = "nav")
                /\ doIdx = NONE \/ (doIdx \in Idx /\ Kind[doIdx] \in DoClass)
                /\ nav = NONE \/ nav = navIdx
                /\ dcmd = NONE \/ dcmd = doIdx
                /\ dcmd # NONE => nav # NONE
\* a running mission (between calls) has an active nav command, so do a
\* stopped one with a nav command set: resume's "no active command" branch
\* and update's advance without a verify are defensive only
NavActive == /\ (st = "running" /\ phase = "idle") => nav # NONE
             /\ (st = "stopped" /\ navIdx # NONE) => nav # NONE
\* ~ MtMissionCounters, counter_bound
CountersBounded == \A i \in Idx : Kind[i] = "jump" =>
                      IF Rep[i] >= 0 THEN cnt[i] \in 0..Rep[i] ELSE cnt[i] = 0
NoCallbackSeesJump == \A k \in 1..Len(cbs) : cbs[k][1] = "done" \/ Kind[cbs[k][2]] \in {"nav", "do"}
\* ~ complete_once
CompleteOncePerRun == /\ runDone \in 0..1
                      /\ st = "complete" => runDone = 1
                      /\ st = "running" => runDone = 0

\* The execution order, stated apart from the actions: the first k commands
\* that are not jumps reached from p with counters c (a jump is taken while
\* its counter is below its repeat count, and counted; one that falls through
\* resets its counter), N when the end is reached. b bounds the jumps
\* followed in a row (a validated mission has no jump-only cycle).
RECURSIVE OrderB(_, _, _, _)
OrderB(p, c, k, b) ==
    IF k = 0 \/ b = 0 THEN <<>>
    ELSE IF p >= N THEN <<N>>
    ELSE IF Kind[p] = "jump"
         THEN IF Rep[p] < 0 THEN OrderB(Tgt[p], c, k, b - 1)
              ELSE IF c[p] < Rep[p] THEN OrderB(Tgt[p], [c EXCEPT ![p] = @ + 1], k, b - 1)
              ELSE OrderB(p + 1, [c EXCEPT ![p] = 0], k, b - 1)
    ELSE <<p>> \o OrderB(p + 1, c, k - 1, N)
Order(p, c, k) == OrderB(p, c, k, N)
IsNavAt(x) == x < N /\ Kind[x] = "nav"
IsDoAt(x) == x < N /\ Kind[x] \in DoClass
FirstNav(seq) == LET ks == {k \in 1..Len(seq) : seq[k] = N \/ IsNavAt(seq[k])}
                 IN IF ks = {} THEN Loop ELSE seq[CHOOSE k \in ks : \A m \in ks : k <= m]

\* where the next update's advance begins
NextFrom == IF navIdx = NONE THEN 1 ELSE navIdx + 1
\* A-2: the look-ahead from there ends (a do-only loop would not)
LookAheadBounded == LookNav(NextFrom, cnt, FALSE) # Loop
\* A-3: it finds the nav command (or the end) execution reaches first
LookAheadMatches == LookNav(NextFrom, cnt, FALSE) = FirstNav(Order(NextFrom, cnt, N))

\* The last step's advance, read from adv and cbs only
AdvPath == Order(adv.from, adv.c, N + Extra)
NavStarts == SelectSeq(cbs, LAMBDA e : e[1] = "start" /\ Kind[e[2]] = "nav")
DoStarts == SelectSeq(cbs, LAMBDA e : e[1] = "start" /\ Kind[e[2]] = "do")
Completed == \E k \in 1..Len(cbs) : cbs[k][1] = "done"
\* position in path of its m-th nav command (0: it has fewer)
RECURSIVE NavPosR(_, _, _)
NavPosR(path, k, m) == IF k > Len(path) THEN 0
                       ELSE IF IsNavAt(path[k]) THEN (IF m = 1 THEN k ELSE NavPosR(path, k + 1, m - 1))
                       ELSE NavPosR(path, k + 1, m)
NavPos(path, m) == IF m = 0 THEN 0 ELSE NavPosR(path, 1, m)
\* what the advance walked: to the nav command whose start was accepted (the
\* last nav start of the step), or, when the step completes, all of it
Walked(path) == IF Completed THEN path ELSE SubSeq(path, 1, NavPos(path, Len(NavStarts)))
PassedDo(path) == SelectSeq(Walked(path), IsDoAt)
\* the first do-class command passed: a do command starts (once, no other
\* do command does), a JUMP_TAG takes the slot (no do command starts)
FirstDoStarted(f) == IF Kind[f] = "tag" THEN DoStarts = <<>>
                     ELSE Len(DoStarts) = 1 /\ DoStarts[1][2] = f
Before(a, b) == \E x, y \in 1..Len(cbs) : x < y /\ cbs[x] = a /\ cbs[y] = b

\* the advance starts the nav commands of the execution order, in order,
\* each refused but the last, until one is accepted, the end, or the bound;
\* only refused nav starts bring it to the bound (A-1)
AdvanceFollowsOrder ==
    adv.from # 0 =>
        LET path == AdvPath IN
        /\ [k \in 1..Len(NavStarts) |-> NavStarts[k][2]] = SelectSeq(Walked(path), IsNavAt)
        /\ \A k \in 1..Len(NavStarts) : NavStarts[k][3] = (k = Len(NavStarts) /\ ~Completed)
        /\ Completed => Len(path) = N + Extra \/ path[Len(path)] = N
        /\ Completed /\ NavStarts = <<>> => path[Len(path)] = N
        /\ ~Completed => NavPos(path, Len(NavStarts)) # 0
\* (a) an advance that starts nav command n after passing a do command has
\* started the first one passed in the same step, before n
FirstDoBeforeNav ==
    (adv.from # 0 /\ ~Completed) =>
        LET pd == PassedDo(AdvPath) IN
        pd # <<>> =>
            /\ FirstDoStarted(pd[1])
            /\ Kind[pd[1]] = "do" => Before(StartCb(pd[1], TRUE), NavStarts[Len(NavStarts)])
\* (b) an advance that reaches the end (or its bound) after passing a do
\* command has started it in the step that completes the mission, before
\* the complete callback
TrailingDoStarts ==
    (adv.from # 0 /\ Completed) =>
        LET pd == PassedDo(AdvPath) IN
        pd # <<>> =>
            /\ FirstDoStarted(pd[1])
            /\ Kind[pd[1]] = "do" => Before(StartCb(pd[1], TRUE), DoneCb)

\* liveness: only updates after a start; the do half is weakly fair, and an
\* update half whose callbacks all return TRUE (the nav command verifies and
\* the next one starts; the do command verifies) is strongly fair.
\* The fairness conditions are written out, WF_v(A) as <>[]En => []<><<A>>_v
\* and SF_v(A) as []<>En => []<><<A>>_v, with En the state predicate equal to
\* ENABLED <<A>>_allVars: TLC evaluates ENABLED without caching the walk's
\* LET values, which makes it exponential in the walk's length. Each En holds
\* because StartOp, NavStep and DoStep always hold a result whose callbacks
\* all return TRUE (the advance that accepts the first nav start, or, with
\* no nav command on the walk, its one result), and each of these steps
\* changes st or phase.
AllTrue == \A k \in 1..Len(cbs') : cbs'[k][3]
LiveStart == st = "stopped" /\ Start
GoodNav == UpdateNav /\ AllTrue
GoodDo == UpdateDo /\ AllTrue
LiveNext == LiveStart \/ UpdateNav \/ UpdateDo
LiveSpec == /\ Init /\ [][LiveNext]_allVars
            /\ <>[](phase = "idle" /\ st = "stopped") => []<><<LiveStart>>_allVars   \* WF LiveStart
            /\ []<>(phase = "idle" /\ st = "running") => []<><<GoodNav>>_allVars     \* SF GoodNav
            /\ <>[](phase = "do") => []<><<UpdateDo>>_allVars                        \* WF UpdateDo
            /\ []<>(phase = "do") => []<><<GoodDo>>_allVars                          \* SF GoodDo
Completes == <>(st = "complete")
=============================================================================
