----------------------------- MODULE MissionMC ------------------------------
(* The fixed missions the Mission configurations check (tla/cfg/Mission_*.cfg
   substitute N, Kind, Tgt, Rep with one of them). Index 0 is home, N the end;
   Rep -1 is a repeat-forever jump, a "tag" is a JUMP_TAG marker. *)
EXTENDS Mission

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
=============================================================================
