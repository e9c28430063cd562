-------------------------------- MODULE Ring --------------------------------
(***************************************************************************)
(* SPSC byte ring (kernel/src/ring.c) and object ring (kernel/src/objring.c)*)
(* at the granularity of single shared-memory operations, in the order the *)
(* C code performs them. One producer and one consumer context (thread,    *)
(* timer thread or ISR), interleaved arbitrarily.                          *)
(*                                                                         *)
(* Actions and the C they abstract (mt_ring_idx.h's mt_idx_count/add/slot  *)
(* are Count/Add/Slot, literally):                                         *)
(*  Producer, byte ring                                                    *)
(*   mt_bring_write_free(op,len)  mt_bring_write / mt_bring_reserve:       *)
(*                 producer_free(): free_now from tail and head_cache      *)
(*                 (producer-owned, no shared access); enough room -> copy *)
(*   mt_bring_write_reload        producer_free(): r->head_cache =         *)
(*                 mt_load_acquire_u32(&r->head); n = min(len, free_now)   *)
(*   prod_copy                    mt_bring_write's two copy loops          *)
(*                 r->buf[slot + k] = src[k] and r->buf[k - first] = src[k] *)
(*                 (one byte a step); for mt_bring_reserve, the caller's   *)
(*                 writes through vec[0], vec[1]                           *)
(*   prod_publish                 mt_store_release_u32(&r->tail,           *)
(*                 mt_idx_add(r->tail, n, ...)) in mt_bring_write, or      *)
(*                 mt_bring_commit(r, c) with any c <= reserved            *)
(*  Producer, object ring                                                  *)
(*   mt_oring_push_count          producer_count(): n from the cached head *)
(*   mt_oring_push_reload         producer_count(): head_cache = acquire   *)
(*                 load of head; then mt_oring_push's `>= cap` or          *)
(*                 mt_oring_push_drop_oldest's `> cap` test and            *)
(*                 note_rejected(), or on to put()                         *)
(*   prod_copy                    put(): copy_bytes(slot_ptr(tail), obj)   *)
(*   prod_publish                 put(): mt_store_release_u32(&r->tail,    *)
(*                 mt_idx_add(r->tail, 1, ...))                            *)
(*   ap_push_force_advance        BROKEN variant only: ArduPilot           *)
(*                 ObjectBuffer::push_force's buffer->advance(1) on a full *)
(*                 ring (the producer stores the consumer's index)         *)
(*  Consumer, byte ring                                                    *)
(*   mt_bring_read_avail(len)     mt_bring_read -> mt_bring_peek ->        *)
(*                 consumer_avail(): avail from tail_cache and head        *)
(*   mt_bring_read_reload         consumer_avail(): r->tail_cache =        *)
(*                 mt_load_acquire_u32(&r->tail); n = min(len, avail)      *)
(*   mt_bring_read_copy           copy_out()'s two loops, one byte a step  *)
(*   cons_release                 mt_bring_read: mt_store_release_u32(     *)
(*                 &r->head, mt_idx_add(r->head, n, ...))                  *)
(*   mt_bring_flush_available     mt_bring_flush -> mt_bring_available():  *)
(*                 acquire load of tail into tail_cache, n = count         *)
(*   cons_flush_store             mt_bring_flush / mt_oring_flush:         *)
(*                 mt_store_release_u32(&r->head, r->tail_cache)           *)
(*  Consumer, object ring                                                  *)
(*   mt_oring_sync(op)            consumer_sync() as called by             *)
(*                 mt_oring_pop / _peek / _update_front / _flush:          *)
(*                 r->tail_cache = mt_load_acquire_u32(&r->tail), n        *)
(*   mt_oring_sync_drop           consumer_sync(), n > cap: release store  *)
(*                 of head + 1, r->lost++ (the drop-oldest, by the owner)  *)
(*   mt_oring_pop_copy            copy_bytes(out, slot_ptr(head)) in pop;  *)
(*                 in peek / update_front, the same slot read / written    *)
(*   cons_release                 mt_oring_pop: release store of head + 1  *)
(*                                                                         *)
(* Ghosts: Sent (items published, in order), Rcvd (items consumed), Lost   *)
(* (items discarded by a drop-oldest, counted in r->lost), Flushed (items  *)
(* discarded by a flush, counted in its return value), Done (Rcvd, Lost and *)
(* Flushed merged in the order the consumer passed them), wr/pb (per slot:  *)
(* data written / index published and not yet freed by the consumer),      *)
(* dreports (MT_W_DROPPED_OLDEST returns, kept when CountReports).        *)
(*                                                                         *)
(* Simplifications:                                                        *)
(*  - Sequentially consistent interleaving of single memory operations.    *)
(*    This is exactly what the acquire/release accessors of mt_atomic.h    *)
(*    guarantee for the protocol: a release store orders every earlier    *)
(*    access of its thread before it, an acquire load every later one      *)
(*    after it, and the only cross-thread communication is through the two *)
(*    indices. Plain accesses to producer- or consumer-owned fields        *)
(*    (head_cache, tail_cache, rejected, lost, the other side never        *)
(*    touches them) are merged into the neighbouring step.                 *)
(*  - An object is one slot value; copy_bytes' byte loop is one step. The   *)
(*    byte ring copies one byte a step. Items are numbered 1..MaxMsg; the  *)
(*    value in a slot is the item number.                                  *)
(*  - Statistics and status returns other than the counters named above    *)
(*    are not modelled; mt_bring_space / _available / mt_oring_space /     *)
(*    _available only load an index into a cache and are covered by the    *)
(*    reload steps; mt_bring_peek is mt_bring_read without the release     *)
(*    store; mt_bring_peek_vec + mt_bring_advance behave as a read whose    *)
(*    tail is always reloaded (not modelled separately).                   *)
(*  - mt_oring_update_front writes the oldest retained object in place; it *)
(*    is modelled as a touch of that slot with the same item number (the   *)
(*    safety question is only whether the slot is the consumer's).         *)
(*  - The reservation of mt_bring_reserve is written whole by the caller   *)
(*    before mt_bring_commit(c), c <= reserved; uncommitted bytes are      *)
(*    simply not published (the next call rewrites them).                  *)
(*  - Init state is the one mt_bring_init / mt_oring_init leave.           *)
(*  - Saturation of the 32-bit counters is not reached (MaxMsg is small).  *)
(***************************************************************************)
EXTENDS Naturals, Sequences

CONSTANTS
    Kind,             \* "byte": mt_bring_* (S = Cap); "obj": mt_oring_* (S = Cap + 1)
    Cap,              \* capacity in bytes (byte ring) or objects (object ring)
    MaxMsg,           \* items the producer offers (bytes or objects, numbered 1..MaxMsg)
    MaxLen,           \* byte ring: largest len of one write / read call
    DropOldest,       \* object ring: the producer calls mt_oring_push_drop_oldest
    Api,              \* "core": write/read, push/pop; "full": also reserve+commit,
                      \*   flush, peek and update_front
    PublishEarly,     \* BROKEN: the index is published before the data is written
    WriterDropOldest, \* BROKEN: on a full ring the producer advances head itself
                      \*         (ArduPilot ObjectBuffer::push_force)
    CountReports      \* keep the history counter dreports (MT_W_DROPPED_OLDEST
                      \*   returns); off, it stays 0 and the state space is smaller

ASSUME /\ Kind \in {"byte", "obj"}
       /\ Cap \in Nat \ {0} /\ MaxMsg \in Nat \ {0} /\ MaxLen \in Nat \ {0}
       /\ Api \in {"core", "full"}
       /\ DropOldest \in BOOLEAN /\ PublishEarly \in BOOLEAN /\ WriterDropOldest \in BOOLEAN
       /\ CountReports \in BOOLEAN
       /\ DropOldest => Kind = "obj"
       /\ WriterDropOldest => (Kind = "obj" /\ ~DropOldest)
       /\ (PublishEarly \/ WriterDropOldest) => Api = "core"

S == IF Kind = "obj" THEN Cap + 1 ELSE Cap     \* storage slots
Slots == 0 .. S - 1
Idx == 0 .. 2 * S - 1                           \* mirror indices
MaxCount == IF DropOldest THEN Cap + 1 ELSE Cap \* published, unconsumed items allowed
Min(a, b) == IF a <= b THEN a ELSE b

\* kernel/src/mt_ring_idx.h, literally: mt_idx_count, mt_idx_add, mt_idx_slot
Count(w, r) == IF w >= r THEN w - r ELSE (w + 2 * S) - r
Add(i, n) == IF i + n < 2 * S THEN i + n ELSE (i + n) - 2 * S
Slot(i) == IF i < S THEN i ELSE i - S

\* The slots of the n indices from i on.
Span(i, n) == {Slot(Add(i, j)) : j \in 0 .. n - 1}

VARIABLES
    \* shared memory
    tail,        \* r->tail: write index, release-stored by the producer
    head,        \* r->head: read index, release-stored by the consumer
    buf,         \* r->buf: slot contents (the item number last written there)
    \* producer half (the consumer never touches it)
    head_cache,  \* r->head_cache
    rejected,    \* r->rejected (object ring)
    \* consumer half (the producer never touches it)
    tail_cache,  \* r->tail_cache
    lost,        \* r->lost (object ring)
    \* producer locals
    ppc,         \* program counter
    pop,         \* the call under way: "write", "reserve" (byte), "push" (object)
    pn,          \* n: items this call writes
    pk,          \* k: items copied so far
    pidx,        \* mirror index of the next slot to copy into
    pwant,       \* len, while the producer reloads head
    \* consumer locals
    cpc,         \* program counter
    cop,         \* the call under way: "read" (byte read, object pop), "peek", "flush"
    cn, ck,      \* n and k as above
    cidx,        \* mirror index of the next slot to copy out of (byte ring)
    cwant,       \* len, while the consumer reloads tail
    cdst,        \* dst: items copied out in this call
    cslots,      \* slots the consumer has read in this call (its own until head moves)
    \* ghosts
    nxt,         \* number of the next item the producer offers
    Sent, Rcvd, Lost, Flushed, Done,
    flushed,     \* sum of the values the flush calls returned
    dreports,    \* MT_W_DROPPED_OLDEST returns of mt_oring_push_drop_oldest
    wr,          \* wr[s]: slot s holds data written by the producer, not yet freed
    pb           \* pb[s]: a published index covers slot s, not yet freed

ring == <<tail, head, buf, head_cache, rejected, tail_cache, lost>>
prod == <<ppc, pop, pn, pk, pidx, pwant>>
cons == <<cpc, cop, cn, ck, cidx, cwant, cdst, cslots>>
ghost == <<nxt, Sent, Rcvd, Lost, Flushed, Done, flushed, dreports, wr, pb>>
vars == <<ring, prod, cons, ghost>>

InSeq(x, q) == \E j \in DOMAIN q : q[j] = x
Increasing(q) == \A j \in 1 .. Len(q) - 1 : q[j] < q[j + 1]

-----------------------------------------------------------------------------
Init ==
    /\ tail = 0 /\ head = 0 /\ buf = [s \in Slots |-> 0]
    /\ head_cache = 0 /\ rejected = 0 /\ tail_cache = 0 /\ lost = 0
    /\ ppc = "idle" /\ pop = "none" /\ pn = 0 /\ pk = 0 /\ pidx = 0 /\ pwant = 0
    /\ cpc = "idle" /\ cop = "none" /\ cn = 0 /\ ck = 0 /\ cidx = 0 /\ cwant = 0
    /\ cdst = <<>> /\ cslots = {}
    /\ nxt = 1 /\ Sent = <<>> /\ Rcvd = <<>> /\ Lost = <<>> /\ Flushed = <<>> /\ Done = <<>>
    /\ flushed = 0 /\ dreports = 0
    /\ wr = [s \in Slots |-> FALSE] /\ pb = [s \in Slots |-> FALSE]

\* Where the producer goes once it knows n >= 1: copy first (the C order),
\* or publish first (the seeded bug).
FirstStep == IF PublishEarly THEN "publish" ELSE "copy"

\* A producer call ends: locals cleared; the next call offers the next items.
ProdDone(n) ==
    /\ ppc' = "idle" /\ pop' = "none" /\ pn' = 0 /\ pk' = 0 /\ pidx' = 0 /\ pwant' = 0
    /\ nxt' = nxt + n

ProdOps == IF Api = "full" THEN {"write", "reserve"} ELSE {"write"}

-----------------------------------------------------------------------------
(* Producer, byte ring: mt_bring_write(r, src, len) and                    *)
(* mt_bring_reserve(r, vec, len) ... mt_bring_commit(r, c)                  *)

WriteLens == 1 .. Min(MaxLen, MaxMsg - nxt + 1)

mt_bring_write_free(op, len) ==
    /\ Kind = "byte" /\ ppc = "idle" /\ nxt <= MaxMsg /\ len \in WriteLens
    /\ pop' = op
    /\ IF S - Count(tail, head_cache) >= len
       THEN /\ pn' = len /\ pidx' = tail /\ ppc' = FirstStep /\ UNCHANGED pwant
       ELSE /\ pwant' = len /\ ppc' = "reload" /\ UNCHANGED <<pn, pidx>>
    /\ UNCHANGED <<ring, pk, cons, ghost>>

mt_bring_write_reload ==
    /\ Kind = "byte" /\ ppc = "reload"
    /\ head_cache' = head
    /\ LET n == Min(pwant, S - Count(tail, head)) IN
         /\ pn' = n /\ pidx' = tail /\ pwant' = 0
         /\ ppc' = IF n = 0 THEN "publish" ELSE FirstStep
    /\ UNCHANGED <<tail, head, buf, rejected, tail_cache, lost, pop, pk, cons, ghost>>

-----------------------------------------------------------------------------
(* Producer, object ring: mt_oring_push / mt_oring_push_drop_oldest        *)

mt_oring_push_count ==
    /\ Kind = "obj" /\ ppc = "idle" /\ nxt <= MaxMsg
    /\ pop' = "push"
    /\ IF Count(tail, head_cache) >= Cap
       THEN /\ ppc' = "reload" /\ UNCHANGED <<pn, pidx>>
       ELSE /\ pn' = 1 /\ pidx' = tail /\ ppc' = FirstStep
    /\ UNCHANGED <<ring, pk, pwant, cons, ghost>>

mt_oring_push_reload ==
    /\ Kind = "obj" /\ ppc = "reload"
    /\ head_cache' = head
    /\ LET n == Count(tail, head) IN
       CASE WriterDropOldest /\ n >= Cap ->
                 /\ ppc' = "force"
                 /\ UNCHANGED <<rejected, pop, pn, pk, pidx, pwant, nxt, dreports>>
         [] (IF DropOldest THEN n > Cap ELSE n >= Cap) ->
                 \* MT_E_FULL, note_rejected(); the item is given up
                 /\ rejected' = rejected + 1
                 /\ ProdDone(1)
                 /\ UNCHANGED dreports
         [] OTHER ->
                 \* put(); push_drop_oldest returns MT_W_DROPPED_OLDEST when n == cap
                 /\ pn' = 1 /\ pidx' = tail /\ ppc' = FirstStep
                 /\ dreports' = IF CountReports /\ DropOldest /\ n = Cap
                                 THEN dreports + 1 ELSE dreports
                 /\ UNCHANGED <<rejected, pop, pk, pwant, nxt>>
    /\ UNCHANGED <<tail, head, buf, tail_cache, lost, cons,
                   Sent, Rcvd, Lost, Flushed, Done, flushed, wr, pb>>

\* BROKEN variant only: the producer drops the oldest item itself.
ap_push_force_advance ==
    /\ ppc = "force"
    /\ head' = Add(head_cache, 1)
    /\ head_cache' = Add(head_cache, 1)
    /\ Lost' = Append(Lost, buf[Slot(head_cache)])
    /\ Done' = Append(Done, buf[Slot(head_cache)])
    /\ wr' = [wr EXCEPT ![Slot(head_cache)] = FALSE]
    /\ pb' = [pb EXCEPT ![Slot(head_cache)] = FALSE]
    /\ pn' = 1 /\ pidx' = tail /\ ppc' = FirstStep
    /\ UNCHANGED <<tail, buf, rejected, tail_cache, lost, pop, pk, pwant, cons,
                   nxt, Sent, Rcvd, Flushed, flushed, dreports>>

-----------------------------------------------------------------------------
(* Producer, both rings: the copy and the release store of tail            *)

prod_copy ==
    /\ ppc = "copy"
    /\ buf' = [buf EXCEPT ![Slot(pidx)] = nxt + pk]
    /\ wr' = [wr EXCEPT ![Slot(pidx)] = TRUE]
    /\ IF pk + 1 < pn \/ ~PublishEarly
       THEN /\ pk' = pk + 1 /\ pidx' = Add(pidx, 1)
            /\ ppc' = IF pk + 1 < pn THEN "copy" ELSE "publish"
            /\ UNCHANGED <<pop, pn, pwant, nxt>>
       ELSE ProdDone(pn)   \* seeded bug: the index went out before this data
    /\ UNCHANGED <<tail, head, head_cache, rejected, tail_cache, lost, cons,
                   Sent, Rcvd, Lost, Flushed, Done, flushed, dreports, pb>>

\* Publish c of the pn items copied: c = pn except for mt_bring_commit(r, c).
Publish(c) ==
    /\ tail' = Add(tail, c)
    /\ pb' = [s \in Slots |-> pb[s] \/ s \in Span(tail, c)]
    /\ wr' = [s \in Slots |-> wr[s] /\ s \notin (Span(tail, pn) \ Span(tail, c))]
    /\ Sent' = Sent \o [j \in 1 .. c |-> nxt + j - 1]

prod_publish ==
    /\ ppc = "publish"
    /\ IF PublishEarly /\ pn > 0
       THEN /\ Publish(pn)
            /\ ppc' = "copy" /\ UNCHANGED <<pop, pn, pk, pidx, pwant, nxt>>
       ELSE \E c \in (IF pop = "reserve" THEN 0 .. pn ELSE {pn}) :
              /\ Publish(c)
              /\ ProdDone(c)
    /\ UNCHANGED <<head, buf, head_cache, rejected, tail_cache, lost, cons,
                   Rcvd, Lost, Flushed, Done, flushed, dreports>>

Producer ==
    \/ \E op \in ProdOps, len \in WriteLens : mt_bring_write_free(op, len)
    \/ mt_bring_write_reload
    \/ mt_oring_push_count \/ mt_oring_push_reload \/ ap_push_force_advance
    \/ prod_copy \/ prod_publish

-----------------------------------------------------------------------------
(* Consumer                                                                *)

ConsDone ==
    /\ cpc' = "idle" /\ cop' = "none" /\ cn' = 0 /\ ck' = 0 /\ cidx' = 0 /\ cwant' = 0
    /\ cdst' = <<>> /\ cslots' = {}

Free(slots) ==
    /\ wr' = [s \in Slots |-> wr[s] /\ s \notin slots]
    /\ pb' = [s \in Slots |-> pb[s] /\ s \notin slots]

\* byte ring, mt_bring_read: consumer_avail() from the cached tail.
mt_bring_read_avail(len) ==
    /\ Kind = "byte" /\ cpc = "idle"
    /\ cop' = "read"
    /\ IF Count(tail_cache, head) >= len
       THEN /\ cn' = len /\ cidx' = head /\ cpc' = "copy" /\ UNCHANGED cwant
       ELSE /\ cwant' = len /\ cpc' = "reload" /\ UNCHANGED <<cn, cidx>>
    /\ UNCHANGED <<ring, prod, ck, cdst, cslots, ghost>>

mt_bring_read_reload ==
    /\ Kind = "byte" /\ cpc = "reload"
    /\ tail_cache' = tail
    /\ LET n == Min(cwant, Count(tail, head)) IN
         /\ cn' = n /\ cidx' = head /\ cwant' = 0
         /\ cpc' = IF n = 0 THEN "release" ELSE "copy"
    /\ UNCHANGED <<tail, head, buf, head_cache, rejected, lost, prod, cop, ck, cdst, cslots, ghost>>

mt_bring_read_copy ==
    /\ Kind = "byte" /\ cpc = "copy"
    /\ cdst' = Append(cdst, buf[Slot(cidx)])
    /\ cslots' = cslots \cup {Slot(cidx)}
    /\ cidx' = Add(cidx, 1)
    /\ ck' = ck + 1
    /\ cpc' = IF ck + 1 < cn THEN "copy" ELSE "release"
    /\ UNCHANGED <<ring, prod, cop, cn, cwant, ghost>>

\* byte ring, mt_bring_flush: mt_bring_available() loads tail, n = count.
mt_bring_flush_available ==
    /\ Kind = "byte" /\ Api = "full" /\ cpc = "idle"
    /\ tail_cache' = tail
    /\ cn' = Count(tail, head)
    /\ cop' = "flush" /\ cpc' = "flush"
    /\ UNCHANGED <<tail, head, buf, head_cache, rejected, lost, prod, ck, cidx, cwant,
                   cdst, cslots, ghost>>

\* object ring: consumer_sync() at the start of pop / peek / update_front / flush.
ConsOps == IF Api = "full" THEN {"read", "peek", "flush"} ELSE {"read"}

mt_oring_sync(op) ==
    /\ Kind = "obj" /\ cpc = "idle"
    /\ tail_cache' = tail
    /\ LET n == Count(tail, head)
           next == CASE n > Cap -> "drop"
                     [] op = "flush" -> "flush"
                     [] n = 0 -> "idle"          \* MT_E_EMPTY
                     [] OTHER -> "copy"
       IN /\ cpc' = next
          /\ cop' = IF next = "idle" THEN "none" ELSE op
    /\ UNCHANGED <<tail, head, buf, head_cache, rejected, lost, prod, cn, ck, cidx, cwant,
                   cdst, cslots, ghost>>

\* consumer_sync(), n > cap: head + 1 (release), r->lost++.
mt_oring_sync_drop ==
    /\ cpc = "drop"
    /\ head' = Add(head, 1)
    /\ lost' = lost + 1
    /\ Lost' = Append(Lost, buf[Slot(head)])
    /\ Done' = Append(Done, buf[Slot(head)])
    /\ Free({Slot(head)})
    /\ cpc' = IF cop = "flush" THEN "flush" ELSE "copy"
    /\ UNCHANGED <<tail, buf, head_cache, rejected, tail_cache, prod, cop, cn, ck, cidx,
                   cwant, cdst, cslots, nxt, Sent, Rcvd, Flushed, flushed, dreports>>

\* pop: copy_bytes(out, slot_ptr(r, slot(r->head))), then release;
\* peek / update_front: the same slot read or written, and the call returns.
mt_oring_pop_copy ==
    /\ Kind = "obj" /\ cpc = "copy"
    /\ IF cop = "read"
       THEN /\ cdst' = <<buf[Slot(head)]>> /\ cslots' = {Slot(head)}
            /\ cn' = 1 /\ ck' = 1 /\ cpc' = "release"
            /\ UNCHANGED <<cop, cidx, cwant>>
       ELSE ConsDone
    /\ UNCHANGED <<ring, prod, ghost>>

\* mt_store_release_u32(&r->head, mt_idx_add(r->head, n, ...)).
cons_release ==
    /\ cpc = "release"
    /\ head' = Add(head, cn)
    /\ Rcvd' = Rcvd \o cdst
    /\ Done' = Done \o cdst
    /\ Free(cslots)
    /\ ConsDone
    /\ UNCHANGED <<tail, buf, head_cache, rejected, tail_cache, lost, prod,
                   nxt, Sent, Lost, Flushed, flushed, dreports>>

\* mt_store_release_u32(&r->head, r->tail_cache): everything up to the tail
\* seen is dropped; the call returns that count.
cons_flush_store ==
    /\ cpc = "flush"
    /\ LET n == Count(tail_cache, head)
           items == [j \in 1 .. n |-> buf[Slot(Add(head, j - 1))]]
       IN /\ head' = tail_cache
          /\ Flushed' = Flushed \o items
          /\ Done' = Done \o items
          /\ flushed' = flushed + n
          /\ Free(Span(head, n))
    /\ ConsDone
    /\ UNCHANGED <<tail, buf, head_cache, rejected, tail_cache, lost, prod,
                   nxt, Sent, Rcvd, Lost, dreports>>

\* The start of a consuming read (mt_bring_read, mt_oring_pop).
ReadStart == (\E len \in 1 .. MaxLen : mt_bring_read_avail(len)) \/ mt_oring_sync("read")

Consumer ==
    \/ \E len \in 1 .. MaxLen : mt_bring_read_avail(len)
    \/ mt_bring_read_reload \/ mt_bring_read_copy \/ mt_bring_flush_available
    \/ \E op \in ConsOps : mt_oring_sync(op)
    \/ mt_oring_sync_drop \/ mt_oring_pop_copy
    \/ cons_release \/ cons_flush_store

-----------------------------------------------------------------------------
Next == Producer \/ Consumer

\* The consumer is always enabled (an empty read or pop is a step), so weak
\* fairness on it means "the consumer keeps calling"; strong fairness on the
\* start of a read means it does not peek or flush for ever instead. The
\* producer gets no fairness: it may stop anywhere, even inside a call.
Spec == Init /\ [][Next]_vars /\ WF_vars(Consumer) /\ SF_vars(ReadStart)

-----------------------------------------------------------------------------
(* Invariants                                                              *)

TypeOK ==
    /\ tail \in Idx /\ head \in Idx /\ head_cache \in Idx /\ tail_cache \in Idx
    /\ buf \in [Slots -> 0 .. MaxMsg]
    /\ rejected \in 0 .. MaxMsg /\ lost \in 0 .. MaxMsg /\ flushed \in 0 .. MaxMsg
    /\ dreports \in 0 .. MaxMsg
    /\ ppc \in {"idle", "reload", "force", "copy", "publish"}
    /\ cpc \in {"idle", "reload", "drop", "copy", "release", "flush"}
    /\ pn \in 0 .. S /\ pk \in 0 .. S /\ pidx \in Idx /\ pwant \in 0 .. MaxLen
    /\ cn \in 0 .. S /\ ck \in 0 .. S /\ cidx \in Idx /\ cwant \in 0 .. MaxLen
    /\ cslots \subseteq Slots
    /\ nxt \in 1 .. MaxMsg + 1
    /\ wr \in [Slots -> BOOLEAN] /\ pb \in [Slots -> BOOLEAN]

\* The index part of the ACSL invariants MtBRingInv / MtORingInv, which WP
\* proves each function preserves when run alone, holds in every
\* interleaved state.
RingInv ==
    /\ Count(tail, head) <= S
    /\ Count(head, head_cache) <= Count(tail, head_cache)
    /\ Count(tail, head_cache) <= S
    /\ Count(tail_cache, head) <= Count(tail, head)

\* The indices are the ghost positions modulo 2S.
IndexMatchesGhost ==
    /\ tail = Len(Sent) % (2 * S)
    /\ head = Len(Done) % (2 * S)

\* At most MaxCount items are published and not yet consumed or dropped.
CountBound ==
    /\ Count(tail, head) <= MaxCount
    /\ Len(Sent) - Len(Done) <= MaxCount

\* The slot the consumer reads next holds data written and published.
ReaderNeverReadsUnwritten ==
    cpc = "copy" =>
        LET s == IF Kind = "obj" THEN Slot(head) ELSE Slot(cidx) IN wr[s] /\ pb[s]

\* The slot the producer writes next holds no unread data and is not one
\* the consumer has read but not yet released.
WriterNeverOverwritesUnread ==
    ppc = "copy" => (~wr[Slot(pidx)] /\ ~pb[Slot(pidx)] /\ Slot(pidx) \notin cslots)

\* FIFO: the consumer receives items in the order they were sent (items are
\* numbered upwards, so Rcvd is a subsequence of Sent).
Fifo ==
    /\ Increasing(Rcvd)
    /\ \A j \in 1 .. Len(Rcvd) : InSeq(Rcvd[j], Sent)

\* No loss: the items the consumer has passed are exactly the first items
\* sent, in order, each received or accounted: r->lost counts the drop-oldest
\* discards and the flush return values count the flushed ones. Without
\* drop-oldest nothing is dropped, and with the core API Rcvd is a prefix of
\* Sent.
NoLoss ==
    /\ Done = SubSeq(Sent, 1, Len(Done))
    /\ Len(Done) = Len(Rcvd) + Len(Lost) + Len(Flushed)
    /\ lost = Len(Lost) /\ flushed = Len(Flushed)
    /\ ~DropOldest => Lost = <<>>
    /\ (~DropOldest /\ Api = "core") => Rcvd = SubSeq(Sent, 1, Len(Rcvd))

\* Every item passes the consumer at most once (received, dropped or flushed).
NoDuplicate == Increasing(Done)

\* Producer side: every item offered was published or counted as rejected.
NoSilentReject ==
    ppc = "idle" => nxt - 1 = Len(Sent) + rejected

\* Every consumer discard follows a push that returned MT_W_DROPPED_OLDEST.
LostBoundedByReports == CountReports => lost <= dreports

Safety ==
    /\ TypeOK /\ RingInv /\ IndexMatchesGhost /\ CountBound
    /\ ReaderNeverReadsUnwritten /\ WriterNeverOverwritesUnread
    /\ Fifo /\ NoLoss /\ NoDuplicate /\ NoSilentReject /\ LostBoundedByReports

\* The claim of objring.h / status.h that each MT_W_DROPPED_OLDEST return
\* means "the oldest unread object is discarded (and counted) by the
\* consumer": the reports not yet matched by a discard are exactly the drop
\* pending in the ring. It is FALSE (config Ring_drop_report): when the
\* consumer has already copied the oldest object and not yet released it,
\* the producer sees count == cap, stores into the spare slot and reports a
\* drop; the consumer's release then brings the count back to cap and
\* nothing is ever discarded. Safety is unaffected (LostBoundedByReports,
\* NoLoss hold); only the status over-reports.
DroppedOldestReportIsExact ==
    (CountReports /\ ppc = "idle") =>
        dreports = lost + (IF Count(tail, head) > Cap THEN 1 ELSE 0)

-----------------------------------------------------------------------------
(* Liveness, under the fairness of Spec                                    *)

\* Every published item is eventually consumed (or accounted as dropped or
\* flushed). One leads-to per item: the cost grows with MaxMsg.
EveryPushedItemPopped ==
    \A x \in 1 .. MaxMsg : InSeq(x, Sent) ~> InSeq(x, Done)

\* The consumer catches up with the producer infinitely often. With NoLoss
\* (Done is a prefix of Sent) this implies EveryPushedItemPopped, at the
\* cost of a single leads-to; used for the larger configurations.
ConsumerCatchesUp == []<>(Len(Done) = Len(Sent))

-----------------------------------------------------------------------------
(* Reachability witnesses: each must be VIOLATED, which shows the          *)
(* interesting paths are explored (non-vacuity).                           *)

NeverFull == Count(tail, head) < Cap
NeverWraps == Len(Sent) < 2 * S + 1
NeverDrops == lost = 0
NeverRejects == rejected = 0
NeverFlushes == flushed = 0

=============================================================================
