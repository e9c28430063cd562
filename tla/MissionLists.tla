---------------------------- MODULE MissionLists -----------------------------
(* The fixed missions the Mission and MissionSwap configurations check. Index 0
   is home, N the end; Rep -1 is a repeat-forever jump, a "tag" is a JUMP_TAG
   marker. *)
EXTENDS Integers

\* nested: 1 nav, 2 do, 3 nav, 4 jump->1 x2, 5 tag, 6 do, 7 nav, 8 jump->3 x1, 9 nav
NestedN == 10
NestedKind == <<"nav", "do", "nav", "jump", "tag", "do", "nav", "jump", "nav">>
NestedTgt == <<0, 0, 0, 1, 0, 0, 0, 3, 0>>
NestedRep == <<0, 0, 0, 2, 0, 0, 0, 1, 0>>

\* forever: 1 nav, 2 do, 3 jump->5 forever (goto), 4 nav, 5 nav, 6 do, 7 jump->1 forever
ForeverN == 8
ForeverKind == <<"nav", "do", "jump", "nav", "nav", "do", "jump">>
ForeverTgt == <<0, 0, 5, 0, 0, 0, 1>>
ForeverRep == <<0, 0, -1, 0, 0, 0, -1>>

\* runs: do commands before the first nav command, a run of three between two
\* nav commands, a jump back into that run, a trailing run of two:
\* 1 do, 2 nav, 3 do, 4 do, 5 do, 6 nav, 7 jump->4 x1, 8 do, 9 do
RunsN == 10
RunsKind == <<"do", "nav", "do", "do", "do", "nav", "jump", "do", "do">>
RunsTgt == <<0, 0, 0, 0, 0, 0, 4, 0, 0>>
RunsRep == <<0, 0, 0, 0, 0, 0, 1, 0, 0>>

\* trailing: a run of two do commands between two nav commands, one trailing
\* do command (a DO_PARACHUTE after the last waypoint):
\* 1 nav, 2 do, 3 do, 4 nav, 5 do
TrailingN == 6
TrailingKind == <<"nav", "do", "do", "nav", "do">>
TrailingTgt == <<0, 0, 0, 0, 0>>
TrailingRep == <<0, 0, 0, 0, 0>>

\* do loop (BROKEN on purpose): the A-2 mission that mt_mission_check rejects
\* (MT_E_MISSION_LOOP): 1 nav, 2 do, 3 jump->2 forever, 4 nav
DoLoopN == 5
DoLoopKind == <<"nav", "do", "jump", "nav">>
DoLoopTgt == <<0, 0, 2, 0>>
DoLoopRep == <<0, 0, -1, 0>>
\* swap targets (MissionSwap replaces nested with one of these in flight):
\* short: 1 nav, 2 do, 3 nav, 4 jump->1 x1, 5 nav: nested's indices 1 and 3 are
\* nav commands here too, its jump at 4 becomes one with fewer repeats, its
\* indices 6..9 are gone
ShortN == 6
ShortKind == <<"nav", "do", "nav", "jump", "nav">>
ShortTgt == <<0, 0, 0, 1, 0>>
ShortRep == <<0, 0, 0, 1, 0>>

\* shifted: 1 do, 2 nav, 3 do, 4 jump->2 forever, 5 tag, 6 nav, 7 do, 8 nav, 9 jump->6 x3:
\* every index of nested exists, most with another class (a do command where
\* nested's nav commands 1, 3, 7 were, a forever jump where a finite one was)
ShiftedN == 10
ShiftedKind == <<"do", "nav", "do", "jump", "tag", "nav", "do", "nav", "jump">>
ShiftedTgt == <<0, 0, 0, 2, 0, 0, 0, 0, 6>>
ShiftedRep == <<0, 0, 0, -1, 0, 0, 0, 0, 3>>
=============================================================================
