----------------------------- MODULE MissionMC ------------------------------
(* The Mission model over the fixed missions of MissionLists.tla (the
   configurations tla/cfg/Mission_*.cfg substitute N, Kind, Tgt, Rep with one
   of them). *)
EXTENDS Mission, MissionLists
=============================================================================
