---- MODULE MCBrokenDoLoop ----
EXTENDS MissionSeq
\* Must FAIL (LookAheadBounded): the A-2 mission that validation rejects
\* (MT_E_MISSION_LOOP): 1 nav, 2 do, 3 jump->2 forever, 4 nav
MCN == 5
MCKind == <<"nav", "do", "jump", "nav">>
MCTgt == <<0, 0, 2, 0>>
MCRep == <<0, 0, -1, 0>>
====
