----------------------------- MODULE RingTrace -----------------------------
(***************************************************************************)
(* Trace validation of Ring against the C code. tools/trace/ring_trace     *)
(* runs the real ring.c / objring.c under a random interleaving of a       *)
(* producer and a consumer, switching at every acquire load and release    *)
(* store, and logs each API call, index access (with the value read or     *)
(* written), return (with the items read) and, at the end, the ring's      *)
(* fields and slots. This module constrains Ring to follow that log:       *)
(* each event must be one step of the matching action with the logged      *)
(* values; steps that touch no index (slot copies) may happen in between.  *)
(* The trace is accepted iff a state with the whole log consumed is        *)
(* reachable, i.e. iff TLC reports TraceNotAccepted VIOLATED; it is        *)
(* rejected iff TLC reports a deadlock (no step matches the next event;    *)
(* the accepted end state stutters, so it is not a deadlock).              *)
(*                                                                         *)
(* Event -> action:                                                        *)
(*   P call write n   mt_bring_write_free("write", n)                      *)
(*   P call push      mt_oring_push_count                                  *)
(*   P load head v    mt_bring_write_reload / mt_oring_push_reload, head=v *)
(*   P store tail v   prod_publish with tail' = v                          *)
(*   P ret            the producer is idle (no step)                       *)
(*   C call read n    mt_bring_read_avail(n)                               *)
(*   C call pop       no step (consumer_sync's load is the next event)     *)
(*   C load tail v    mt_bring_read_reload / mt_oring_sync("read"), tail=v *)
(*   C store head v   cons_release / mt_oring_sync_drop with head' = v     *)
(*   C ret n d        the consumer is idle and the last n items received   *)
(*                    are d (no step)                                      *)
(*   end              every ring field and slot equals the model's         *)
(***************************************************************************)
EXTENDS Ring, RingTraceData

VARIABLE ti     \* index of the next log event

tvars == <<vars, ti>>

E == Trace[ti]

\* Steps that access no shared index: they leave no event in the log.
Internal == prod_copy \/ mt_bring_read_copy \/ mt_oring_pop_copy

LastRcvd(n) == SubSeq(Rcvd, Len(Rcvd) - n + 1, Len(Rcvd))

Step ==
    CASE E.k = "call" /\ E.s = "P" ->
            IF Kind = "byte" THEN mt_bring_write_free(E.op, E.n) ELSE mt_oring_push_count
      [] E.k = "call" /\ E.s = "C" ->
            IF Kind = "byte" THEN mt_bring_read_avail(E.n) ELSE (cpc = "idle" /\ UNCHANGED vars)
      [] E.k = "load" /\ E.s = "P" ->
            E.f = "head" /\ head = E.v /\ (mt_bring_write_reload \/ mt_oring_push_reload)
      [] E.k = "load" /\ E.s = "C" ->
            E.f = "tail" /\ tail = E.v /\ (mt_bring_read_reload \/ mt_oring_sync("read"))
      [] E.k = "store" /\ E.s = "P" ->
            E.f = "tail" /\ prod_publish /\ tail' = E.v
      [] E.k = "store" /\ E.s = "C" ->
            E.f = "head" /\ (cons_release \/ mt_oring_sync_drop) /\ head' = E.v
      [] E.k = "ret" /\ E.s = "P" ->
            ppc = "idle" /\ UNCHANGED vars
      [] E.k = "ret" /\ E.s = "C" ->
            /\ cpc = "idle" /\ UNCHANGED vars
            /\ Len(Rcvd) >= E.n /\ LastRcvd(E.n) = E.d
      [] E.k = "end" ->
            /\ tail = E.tail /\ head = E.head /\ head_cache = E.hc /\ tail_cache = E.tc
            /\ lost = E.lost /\ rejected = E.rej
            /\ \A s \in Slots : buf[s] = E.buf[s + 1]
            /\ UNCHANGED vars

TraceInit == Init /\ ti = 1

TraceNext ==
    \/ ti <= Len(Trace) /\ Step /\ ti' = ti + 1
    \/ Internal /\ UNCHANGED ti
    \/ ti > Len(Trace) /\ UNCHANGED tvars     \* accepted: stutter

TraceSpec == TraceInit /\ [][TraceNext]_tvars

\* Violated exactly when the whole log has been matched.
TraceNotAccepted == ti <= Len(Trace)

=============================================================================
