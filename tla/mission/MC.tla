---- MODULE MC ----
EXTENDS MissionSeq
\* 1 nav, 2 do, 3 nav, 4 jump->1 x2, 5 tag, 6 do, 7 nav, 8 jump->3 x1, 9 nav
MCN == 10
MCKind == <<"nav", "do", "nav", "jump", "tag", "do", "nav", "jump", "nav">>
MCTgt == <<0, 0, 0, 1, 0, 0, 0, 3, 0>>
MCRep == <<0, 0, 0, 2, 0, 0, 0, 1, 0>>
====
