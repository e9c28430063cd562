-------------------------------- MODULE Bus ---------------------------------
(***************************************************************************)
(* Topic bus (kernel/src/bus.c, bus_sub.c): publishers (task or ISR,      *)
(* serialised by the kernel lock) racing one subscriber's lock-free copy,  *)
(* at the granularity of single shared-memory operations, in the order the *)
(* C code performs them.                                                   *)
(*                                                                         *)
(* Actions and the C they abstract:                                        *)
(*  Publisher (mt_topic_publish_i, lock held; one process stands for every *)
(*  publisher: the lock serialises them and the subscriber takes no lock)  *)
(*   PubBegin       any_behind() (acquire loads of rel_gen; a refused      *)
(*                  publish changes nothing the subscriber sees), then     *)
(*                  put(): ng = gen_next(gen), nh = slot_next(head)        *)
(*   PubStamp       put(): mt_seq_stamp_u32(&stamp[nh], ng) (store +       *)
(*                  release fence)                                         *)
(*   PubByte        write_bytes(): one relaxed byte store a step           *)
(*   PubHead        put(): release stores of head, then published          *)
(*   PubGen         put(): release store of gen (the message is published) *)
(*  Subscriber (mt_sub_copy_next / mt_sub_copy_latest, no lock)            *)
(*   SubStart(op)   a call begins (copy_latest: acquire load of published, *)
(*                  MT_E_EMPTY when 0)                                     *)
(*   SubGen         acquire load of gen                                    *)
(*   SubHead        acquire load of head; pending = gen_dist(gen, s->gen); *)
(*                  MT_E_EMPTY (copy_next) when 0; d = next_dist(...) or 0;*)
(*                  slot = slot_back(head, d), want = gen_back(gen, d)     *)
(*   SubStamp1      try_copy(): acquire load of stamp[slot] == want?       *)
(*   SubByte        read_bytes(): one relaxed byte load a step             *)
(*   SubStamp2      try_copy(): mt_seq_recheck_u32 (acquire fence +        *)
(*                  load) == want? A failed attempt retries; after Tries   *)
(*                  attempts: MT_E_BUS_TORN, note_torn()                   *)
(*   SubCommit      consume() + note_update(): s->gen = want, missed and   *)
(*                  skipped from the observed generation, reliable         *)
(*                  subscribers' release store of rel_gen; the copy is     *)
(*                  returned as valid (MT_OK / MT_W_BUS_MISSED)            *)
(*                                                                         *)
(* Ghosts: pubs (publishes completed, unbounded), pos (unbounded id of the *)
(* last message the subscriber consumed; message n is the n-th publish),   *)
(* buf holds, per byte, the id of the message whose publish wrote it,      *)
(* obs (pubs when the subscriber loaded gen), tid (id of the message the   *)
(* attempt copies), gMissed / gSkipped (the definition of mt/bus.h: a      *)
(* message passed over is missed when the publish that overwrote it had    *)
(* completed before the subscriber loaded the generation, else skipped).   *)
(*                                                                         *)
(* Simplifications:                                                        *)
(*  - Sequentially consistent interleaving of single memory operations;    *)
(*    this is what the accessors give the protocol (mt_atomic.h): the      *)
(*    stamp store is ordered before the byte stores (release fence), the   *)
(*    byte loads before the re-check (acquire fence), head/published/gen   *)
(*    are release-stored and acquire-loaded.                               *)
(*  - One subscriber: subscribers never write anything another subscriber  *)
(*    reads (rel_gen[i] belongs to one); several only add interleavings of *)
(*    independent readers.                                                 *)
(*  - Generations modulo GenMod (a small power of two standing for 2^32);  *)
(*    MaxPub < GenMod, so the subscriber is never GenMod or more behind    *)
(*    (assumption G1). FirstGen near GenMod makes the generation wrap.     *)
(*  - torn saturates at 2 here (2^32 - 1 in C): a subscriber can give up  *)
(*    again and again while a publisher is paused mid-publish, and only    *)
(*    "it happened" matters to the properties.                             *)
(*  - Notifiers, poll, intervals and statistics are not modelled: they run *)
(*    under the kernel lock or in the subscriber's own thread (poll's      *)
(*    semaphore is tla/Sem.tla).                                           *)
(***************************************************************************)
EXTENDS Naturals, FiniteSets

CONSTANTS
    Q,           \* queue length (slots)
    B,           \* bytes per message
    GenMod,      \* generation modulus (2^32 in C)
    FirstGen,    \* generation before the first publish (mt_topic_desc_t.first_gen)
    MaxPub,      \* publishes in a behaviour
    Tries,       \* MT_CFG_BUS_COPY_TRIES
    Reliable,    \* the subscriber is a registered reliable subscriber
    NoRecheck,   \* BROKEN: the subscriber does not re-check the stamp after the copy
    StampLate,   \* BROKEN: the publisher stamps the slot after writing the bytes
    NaiveDist    \* BROKEN: distances by a saturating subtraction (no wrap case)

ASSUME /\ Q \in Nat \ {0} /\ B \in Nat \ {0} /\ Tries \in Nat \ {0}
       /\ GenMod \in Nat \ {0} /\ FirstGen \in 0 .. GenMod - 1
       /\ MaxPub \in Nat /\ MaxPub < GenMod
       /\ Reliable \in BOOLEAN /\ NoRecheck \in BOOLEAN /\ StampLate \in BOOLEAN
       /\ NaiveDist \in BOOLEAN

Slots == 0 .. Q - 1
Bytes == 0 .. B - 1
Gens == 0 .. GenMod - 1

\* kernel/src/bus.c and bus_sub.c, literally (mt_spec_bus.h): the case splits, GenMod for 2^32
GenDist(a, b) == IF a >= b THEN a - b ELSE IF NaiveDist THEN 0 ELSE (a + GenMod) - b
GenNext(g) == IF g < GenMod - 1 THEN g + 1 ELSE 0
GenBack(g, d) == IF g >= d THEN g - d ELSE (g + GenMod) - d
SlotNext(h) == IF h + 1 < Q THEN h + 1 ELSE 0
SlotBack(h, d) == IF h >= d THEN h - d ELSE (h + Q) - d
NextDist(p) == IF p > Q THEN Q - 1 ELSE p - 1

\* The wrapped generation of message n (n = 0: before the first publish).
GenOf(n) == (FirstGen + n) % GenMod

Max(a, b) == IF a >= b THEN a ELSE b
Min(a, b) == IF a <= b THEN a ELSE b

VARIABLES
    \* topic (shared)
    gen, head, published, stamp, buf, relGen,
    \* publisher locals
    ppc, ng, nh, pk,
    \* subscriber object
    sgen, missed, skipped, received, torn,
    \* subscriber locals (cleared whenever a call ends, so that equal states are one)
    spc, op, tries, g, slot, want, pend, k, out,
    \* ghosts
    pubs, pos, obs, tid, gMissed, gSkipped, stamped

topic == <<gen, head, published, stamp, buf, relGen>>
pub == <<ppc, ng, nh, pk>>
sub == <<sgen, missed, skipped, received, torn>>
subl == <<spc, op, tries, g, slot, want, pend, k, out>>
ghost == <<pubs, pos, obs, tid, gMissed, gSkipped, stamped>>
vars == <<topic, pub, sub, subl, ghost>>

NoBytes == [b \in Bytes |-> 0]

Init ==
    /\ gen = FirstGen /\ head = Q - 1 /\ published = 0
    /\ stamp = [s \in Slots |-> FirstGen]
    /\ buf = [s \in Slots |-> NoBytes]
    /\ relGen = FirstGen
    /\ ppc = "idle" /\ ng = 0 /\ nh = 0 /\ pk = 0
    \* mt_sub_init before any publish: s->gen = gen, nothing pending
    /\ sgen = FirstGen /\ missed = 0 /\ skipped = 0 /\ received = 0 /\ torn = 0
    /\ spc = "idle" /\ op = "none" /\ tries = 0 /\ g = 0 /\ slot = 0
    /\ want = 0 /\ pend = 0 /\ k = 0 /\ out = NoBytes
    /\ pubs = 0 /\ pos = 0 /\ obs = 0 /\ tid = 0 /\ gMissed = 0 /\ gSkipped = 0
    /\ stamped = 0

-----------------------------------------------------------------------------
(* Publisher                                                               *)

Behind == Reliable /\ GenDist(gen, relGen) >= Q

PubBegin ==
    /\ ppc = "idle" /\ stamped < MaxPub
    /\ ~Behind                  \* MT_E_BUS_BEHIND otherwise: nothing changes
    /\ ng' = GenNext(gen) /\ nh' = SlotNext(head)
    /\ ppc' = IF StampLate THEN "byte" ELSE "stamp"
    /\ pk' = 0
    /\ stamped' = stamped + 1
    /\ UNCHANGED <<topic, sub, subl, pubs, pos, obs, tid, gMissed, gSkipped>>

PubStamp ==
    /\ ppc = "stamp"
    /\ stamp' = [stamp EXCEPT ![nh] = ng]
    /\ ppc' = IF StampLate THEN "head" ELSE "byte"
    /\ UNCHANGED <<gen, head, published, buf, relGen, ng, nh, pk, sub, subl, ghost>>

PubByte ==
    /\ ppc = "byte"
    /\ buf' = [buf EXCEPT ![nh][pk] = pubs + 1]
    /\ pk' = IF pk + 1 < B THEN pk + 1 ELSE 0
    /\ ppc' = IF pk + 1 < B THEN "byte" ELSE IF StampLate THEN "stamp" ELSE "head"
    /\ UNCHANGED <<gen, head, published, stamp, relGen, ng, nh, sub, subl, ghost>>

PubHead ==
    /\ ppc = "head"
    /\ head' = nh /\ published' = 1
    /\ ppc' = "gen"
    /\ UNCHANGED <<gen, stamp, buf, relGen, ng, nh, pk, sub, subl, ghost>>

PubGen ==
    /\ ppc = "gen"
    /\ gen' = ng
    /\ pubs' = pubs + 1
    /\ ppc' = "idle" /\ ng' = 0 /\ nh' = 0
    /\ UNCHANGED <<head, published, stamp, buf, relGen, pk, sub, subl,
                   pos, obs, tid, gMissed, gSkipped, stamped>>

Publisher == PubBegin \/ PubStamp \/ PubByte \/ PubHead \/ PubGen

-----------------------------------------------------------------------------
(* Subscriber                                                              *)

\* A call ends: every local cleared.
SubEnd ==
    /\ spc' = "idle" /\ op' = "none" /\ tries' = 0 /\ g' = 0 /\ slot' = 0
    /\ want' = 0 /\ pend' = 0 /\ k' = 0 /\ out' = NoBytes /\ obs' = 0 /\ tid' = 0

\* mt_sub_copy_latest on a topic never published returns MT_E_EMPTY at once: a
\* step that changes nothing, left out.
SubStart(o) ==
    /\ spc = "idle"
    /\ ~(o = "latest" /\ published = 0)
    /\ op' = o /\ spc' = "gen"
    /\ UNCHANGED <<topic, pub, sub, tries, g, slot, want, pend, k, out, ghost>>

SubGen ==
    /\ spc = "gen"
    /\ g' = gen /\ obs' = pubs
    /\ spc' = "head"
    /\ UNCHANGED <<topic, pub, sub, op, tries, slot, want, pend, k, out,
                   pubs, pos, tid, gMissed, gSkipped, stamped>>

SubHead ==
    /\ spc = "head"
    /\ LET p == GenDist(g, sgen)
           dd == IF op = "next" THEN NextDist(p) ELSE 0
       IN IF op = "next" /\ p = 0
          THEN SubEnd                                \* MT_E_EMPTY
          ELSE /\ pend' = p
               /\ slot' = SlotBack(head, dd) /\ want' = GenBack(g, dd)
               /\ tid' = obs - dd
               /\ spc' = "stamp1" /\ g' = 0
               /\ UNCHANGED <<op, tries, k, out, obs>>
    /\ UNCHANGED <<topic, pub, sub, pubs, pos, gMissed, gSkipped, stamped>>

\* A failed attempt: retry from the generation load, or give up (MT_E_BUS_TORN).
Retry ==
    IF tries + 1 < Tries
    THEN /\ tries' = tries + 1 /\ spc' = "gen" /\ k' = 0 /\ out' = NoBytes
         /\ slot' = 0 /\ want' = 0 /\ pend' = 0 /\ obs' = 0 /\ tid' = 0
         /\ UNCHANGED <<op, g, torn>>
    ELSE /\ torn' = Min(torn + 1, 2) /\ SubEnd

SubStamp1 ==
    /\ spc = "stamp1"
    /\ IF stamp[slot] = want
       THEN /\ spc' = "byte" /\ UNCHANGED <<op, tries, g, slot, want, pend, k, out, obs, tid,
                                              torn>>
       ELSE Retry
    /\ UNCHANGED <<topic, pub, sgen, missed, skipped, received,
                   pubs, pos, gMissed, gSkipped, stamped>>

SubByte ==
    /\ spc = "byte"
    /\ out' = [out EXCEPT ![k] = buf[slot][k]]
    /\ k' = IF k + 1 < B THEN k + 1 ELSE 0
    /\ spc' = IF k + 1 < B THEN "byte" ELSE "stamp2"
    /\ UNCHANGED <<topic, pub, sub, op, tries, g, slot, want, pend, ghost>>

SubStamp2 ==
    /\ spc = "stamp2"
    /\ IF stamp[slot] = want \/ NoRecheck
       THEN /\ spc' = "commit" /\ UNCHANGED <<op, tries, g, slot, want, pend, k, out, obs, tid,
                                                torn>>
       ELSE Retry
    /\ UNCHANGED <<topic, pub, sgen, missed, skipped, received,
                   pubs, pos, gMissed, gSkipped, stamped>>

\* consume(): the C arithmetic on wrapped generations (lost, passed), and the
\* ghost definition on unbounded ids: the messages between pos and tid whose
\* overwriting publish (id m + Q) had completed when gen was loaded.
SubCommit ==
    /\ spc = "commit"
    /\ LET lost == IF pend > Q THEN pend - Q ELSE 0
           passed == IF op = "latest" /\ pend # 0 THEN (pend - 1) - lost ELSE 0
           fresh == IF op = "next" \/ pend # 0 THEN 1 ELSE 0
           between == pos + 1 .. tid - 1
           gone == {m \in between : m + Q <= obs}
       IN /\ sgen' = want
          /\ missed' = missed + lost
          /\ skipped' = skipped + passed
          /\ received' = received + fresh
          /\ relGen' = IF Reliable THEN want ELSE relGen
          /\ gMissed' = gMissed + Cardinality(gone)
          /\ gSkipped' = gSkipped + Cardinality(between \ gone)
          /\ pos' = Max(pos, tid)
    /\ spc' = "done"
    /\ UNCHANGED <<gen, head, published, stamp, buf, pub, torn, op, tries, g, slot,
                   want, pend, k, out, pubs, obs, tid, stamped>>

\* The call returns the copy as valid (MT_OK / MT_W_BUS_MISSED).
SubReturn ==
    /\ spc = "done"
    /\ SubEnd
    /\ UNCHANGED <<topic, pub, sub, pubs, pos, gMissed, gSkipped, stamped>>

Subscriber ==
    \/ SubStart("next") \/ SubStart("latest")
    \/ SubGen \/ SubHead \/ SubStamp1 \/ SubByte \/ SubStamp2 \/ SubCommit \/ SubReturn

Next == Publisher \/ Subscriber

Spec == Init /\ [][Next]_vars

-----------------------------------------------------------------------------
(* Properties (names shared with mt/bus.h and tests/test_bus.cpp)          *)

TypeOK ==
    /\ gen \in Gens /\ head \in Slots /\ published \in {0, 1}
    /\ stamp \in [Slots -> Gens] /\ relGen \in Gens /\ sgen \in Gens
    /\ pos \in 0 .. pubs /\ pubs \in 0 .. MaxPub

\* The topic's wrapped generation is the number of publishes, the subscriber's
\* the number it consumed, and their case-split distance is the exact lag.
GenerationExact ==
    /\ gen = GenOf(pubs)
    /\ sgen = GenOf(pos)
    /\ GenDist(gen, sgen) = pubs - pos

\* No torn read is returned as valid: a copy that commits holds every byte of
\* one message, the one the subscriber aimed at.
NoTornRead ==
    spc \in {"commit", "done"} => \A b \in Bytes : out[b] = tid

\* The message copied is the right one: copy_next the next after pos or the
\* oldest retained one, copy_latest the newest at the generation load.
RightMessage ==
    spc = "commit" =>
        IF op = "next" THEN tid = Max(pos + 1, obs - Q + 1) ELSE tid = obs

\* missed / skipped as defined in mt/bus.h, counted exactly.
MissedExact == missed = gMissed /\ skipped = gSkipped

\* Every message published is received, missed, skipped or still pending.
AccountingExact == received + missed + skipped + (pubs - pos) = pubs

\* A registered reliable subscriber never misses a message (MT_E_BUS_BEHIND).
ReliableNeverMisses == Reliable => missed = 0

Safety == TypeOK /\ GenerationExact /\ NoTornRead /\ RightMessage /\ MissedExact
          /\ AccountingExact /\ ReliableNeverMisses

\* Witnesses (configs that must violate them): each path is reachable.
NeverGivesUp == torn = 0
NeverMisses == missed = 0
NeverWraps == pubs = 0 \/ gen > FirstGen
=============================================================================
