---------------------------- MODULE MissionSwap -----------------------------
(***************************************************************************)
(* mt_mission_replace (kernel/src/mission.c): a running mission replaced   *)
(* by another, validated list between two updates (a ground station's      *)
(* upload in flight), then the new list run with every operation.          *)
(*                                                                         *)
(* Mission's constants (N, Kind, Tgt, Rep) are the new list; N0, Kind0,    *)
(* Tgt0, Rep0 the old one. The old run is summed up by what the swap reads *)
(* of it: its navIdx and its jump counters, each taken over every value    *)
(* an old run can have (any nav index or none, every counter of a finite   *)
(* jump from 0 to its repeat count, the others 0: a superset of the        *)
(* reachable ones, so nothing the C can meet is left out). The swap is two *)
(* steps nothing can split (phase "swap", as the update's halves are):     *)
(* SwapInit is the state apply leaves (the new list, STOPPED, no cursor,   *)
(* prevNav NONE, the counters Kept), ReplaceRestart the rest of the call:  *)
(* when the old navIdx (swapAt) is an index of the new list, RUNNING and   *)
(* the advance from it (every callback outcome); otherwise it stays        *)
(* STOPPED with nothing set (the vehicle holds). The swap happens only     *)
(* between two updates: the sequencer is single-threaded (mt/mission.h).   *)
(*                                                                         *)
(* Kept (MtMissionKeptCount): a counter survives where both lists have a   *)
(* jump at the index, at most the new repeat count; the others are 0.      *)
(*                                                                         *)
(* SWAP "ap" is mission.c. The broken variant "in_place" writes the new    *)
(* list over the running one and keeps the cursors and counters with no    *)
(* restart (AP's storage writes alone, before its change detector acts):   *)
(* must violate CursorsValid. "no_clamp" keeps a counter above the new    *)
(* repeat count: must violate CountersBounded.                             *)
(*                                                                         *)
(* Checked: every Mission invariant on the new list, from the swap on (the *)
(* advance the swap runs sets adv and cbs, so AdvanceFollowsOrder,         *)
(* FirstDoBeforeNav and TrailingDoStarts check it), and SwapOutcome.       *)
(***************************************************************************)
EXTENDS Mission, MissionLists

CONSTANTS N0, Kind0, Tgt0, Rep0, SWAP

ASSUME N0 \in Nat /\ N0 >= 2 /\ NONE \notin 1..(N0 + N) /\ SWAP \in {"ap", "in_place", "no_clamp"}

VARIABLE swapAt     \* the old navIdx during and after the swap's step (N0 + N for none), 0 after any other step

Idx0 == 1..(N0 - 1)
OldNav == {i \in Idx0 : Kind0[i] = "nav"} \cup {NONE}
MaxRep0 == LET reps == {Rep0[i] : i \in Idx0} IN CHOOSE r \in reps : \A q \in reps : q <= r
OldCounts == {c \in [Idx0 -> 0..MaxRep0] :
                 \A i \in Idx0 : IF Kind0[i] = "jump" /\ Rep0[i] >= 0 THEN c[i] <= Rep0[i] ELSE c[i] = 0}

Min(a, b) == IF a < b THEN a ELSE b
Kept(c) == [i \in Idx |-> IF i < N0 /\ Kind0[i] = "jump" /\ Kind[i] = "jump" /\ Rep[i] >= 0 /\ c[i] > 0
                         THEN (IF SWAP = "no_clamp" THEN c[i] ELSE Min(c[i], Rep[i])) ELSE 0]
InPlace(c) == [i \in Idx |-> IF i < N0 THEN c[i] ELSE 0]

SwapInit ==
    \E at \in OldNav, c \in OldCounts :
        /\ phase = "swap" /\ swapAt = IF at = NONE THEN N0 + N ELSE at
        /\ runDone = 0 /\ cbs = <<>> /\ adv = NoAdv /\ doIdx = NONE /\ dcmd = NONE
        /\ ddone = FALSE /\ prevNav = NONE
        /\ IF SWAP # "in_place"
           THEN st = "stopped" /\ nav = NONE /\ navIdx = NONE /\ cnt = Kept(c)
           ELSE st = "running" /\ nav = at /\ navIdx = at /\ cnt = InPlace(c)

ReplaceRestart ==
    /\ phase = "swap" /\ phase' = "idle" /\ UNCHANGED swapAt
    /\ IF SWAP # "in_place" /\ swapAt < N
       THEN \E r \in AdvanceOrFinish([Cur EXCEPT !.st = "running"], swapAt) : Set(r)
       ELSE UNCHANGED vars

SwapNext == ReplaceRestart \/ (Next /\ swapAt' = 0)
SwapSpec == SwapInit /\ [][SwapNext]_<<allVars, swapAt>>

\* Mission's TypeOK, with the swap's phase
SwapTypeOK == IF phase = "swap" THEN cnt \in [Idx -> Int] /\ swapAt \in 1..(N0 + N) ELSE TypeOK

\* once the swap's step ran: continued from the old index (the advance
\* began there), or held: STOPPED, nothing set, no callback
SwapOutcome ==
    (swapAt # 0 /\ phase = "idle") =>
        IF swapAt < N
        THEN st \in {"running", "complete"} /\ adv.from = swapAt
        ELSE st = "stopped" /\ nav = NONE /\ navIdx = NONE /\ dcmd = NONE /\ cbs = <<>>
=============================================================================
