---- MODULE MCForever ----
EXTENDS MissionSeq
\* 1 nav, 2 do, 3 jump->5 forever (goto), 4 nav, 5 nav, 6 do, 7 jump->1 forever
MCN == 8
MCKind == <<"nav", "do", "jump", "nav", "nav", "do", "jump">>
MCTgt == <<0, 0, 5, 0, 0, 0, 1>>
MCRep == <<0, 0, -1, 0, 0, 0, -1>>
====
