------------------------------- MODULE Proc --------------------------------
(***************************************************************************)
(* Proc registration (kernel/src/proc.c, mt_proc_register) by several       *)
(* threads under the kernel lock, against the dispatcher (mt_proc_dispatch) *)
(* of the timer or IO thread, which never takes the lock and may be         *)
(* re-entered from inside one of its own procs.                             *)
(*                                                                         *)
(* Actions and the C they abstract:                                        *)
(*  mt_proc_register_lock(r)       mt_proc_register: mt_port_lock()        *)
(*  mt_proc_register_i_check(r)    mt_proc_register_i: n = p->count; the   *)
(*                                 fn == NULL test (fn is never NULL here), *)
(*                                 is_registered() and the n >= MAX test   *)
(*                                 (MT_E_DUPLICATE / MT_E_FULL)            *)
(*  mt_proc_register_i_write_fn(r) p->procs[n].fn = fn                     *)
(*  mt_proc_register_i_write_arg(r) p->procs[n].arg = arg (and the zeroed  *)
(*                                 statistics of entry n)                  *)
(*  mt_proc_register_i_publish(r)  mt_store_release_u32(&p->count, n + 1)  *)
(*  mt_proc_register_unlock(r)     mt_port_unlock()                        *)
(*  mt_proc_dispatch_guard         if (p->running != 0) ...; running = 1   *)
(*  mt_proc_dispatch_load          n = mt_load_acquire_u32(&p->count)      *)
(*  call_one_read_fn / _read_arg   call_one: mt_invoke(e->fn, e->arg)      *)
(*                                 reads e->fn, then e->arg                *)
(*  call_one_invoke                the proc runs and call_one updates the  *)
(*                                 statistics of entry i, or the proc calls *)
(*                                 mt_proc_dispatch(p) itself (refused     *)
(*                                 with MT_E_BUSY: running == 1)           *)
(*  mt_proc_dispatch_end           round statistics; p->running = 0        *)
(*                                                                         *)
(* Simplifications:                                                        *)
(*  - Sequentially consistent interleaving; the release store of count and *)
(*    the acquire load of count are what make this sound for the entry     *)
(*    writes and reads (see Ring.tla).                                     *)
(*  - Inside the register critical section only lock holders write the     *)
(*    data the check reads, so n = count, is_registered and the full test   *)
(*    are one step.                                                        *)
(*  - Statistics (calls, max_us, total_us, refused, dispatches, periods)   *)
(*    are not modelled: only the dispatching thread writes them, for       *)
(*    indices below its n <= count, and a registrar writes only index      *)
(*    count (NeverCallsUnpublished and CountBounded imply the two never    *)
(*    meet).                                                               *)
(*  - A nested dispatch is modelled by its guard only (it is refused); the *)
(*    broken NoGuard variant shows a second round starting.                *)
(*  - fn == NULL (MT_E_INVALID) is not offered; procs do not register      *)
(*    procs in their own set (proof assumption A1).                        *)
(***************************************************************************)
EXTENDS Naturals, Sequences, FiniteSets

CONSTANTS
    Registrars,      \* threads calling mt_proc_register (model values)
    Fns, Args,       \* callbacks and arguments a registrar may pass (model values)
    ProcMax,         \* MT_CFG_PROC_MAX
    MaxRegs,         \* registration calls per registrar
    CountFirst,      \* BROKEN: count published before the entry is written
    NoGuard          \* BROKEN: the re-entrancy test on p->running is missing

ASSUME /\ ProcMax \in Nat \ {0} /\ MaxRegs \in Nat
       /\ CountFirst \in BOOLEAN /\ NoGuard \in BOOLEAN

NULL == "null"
FREE == "free"
Idx == 0 .. ProcMax - 1

VARIABLES
    \* mt_proc_set_t
    fn, arg,     \* p->procs[i].fn, .arg (NULL until written)
    count,       \* p->count: published entries (release/acquire)
    running,     \* p->running
    \* the kernel lock (registrars only; the dispatcher never takes it)
    lock,
    \* registrars
    rpc,         \* program counter
    rf, ra,      \* the (fn, arg) being registered
    rn,          \* n = p->count read under the lock
    rcalls,      \* registration calls made
    \* dispatcher (one thread: the timer or IO thread)
    dpc,
    dn,          \* n = mt_load_acquire_u32(&p->count)
    di,          \* loop index i
    dfn, darg,   \* e->fn, e->arg as read by call_one
    \* ghosts
    Registered,  \* (fn, arg) pairs in publication order
    active       \* dispatch invocations past the re-entrancy test and not finished

vars == <<fn, arg, count, running, lock, rpc, rf, ra, rn, rcalls, dpc, dn, di, dfn, darg,
          Registered, active>>

Pairs == Fns \X Args

Init ==
    /\ fn = [i \in Idx |-> NULL] /\ arg = [i \in Idx |-> NULL]
    /\ count = 0 /\ running = 0
    /\ lock = FREE
    /\ rpc = [r \in Registrars |-> "idle"]
    /\ rf = [r \in Registrars |-> NULL] /\ ra = [r \in Registrars |-> NULL]
    /\ rn = [r \in Registrars |-> 0] /\ rcalls = [r \in Registrars |-> 0]
    /\ dpc = "idle" /\ dn = 0 /\ di = 0 /\ dfn = NULL /\ darg = NULL
    /\ Registered = <<>> /\ active = 0

regvars == <<rpc, rf, ra, rn, rcalls>>
dispvars == <<dpc, dn, di, dfn, darg>>

-----------------------------------------------------------------------------
(* Registrar r: mt_proc_register(p, fn, arg)                               *)

\* mt_port_lock().
mt_proc_register_lock(r) ==
    /\ rpc[r] = "idle" /\ lock = FREE /\ rcalls[r] < MaxRegs
    /\ lock' = r
    /\ \E pr \in Pairs : rf' = [rf EXCEPT ![r] = pr[1]] /\ ra' = [ra EXCEPT ![r] = pr[2]]
    /\ rcalls' = [rcalls EXCEPT ![r] = @ + 1]
    /\ rpc' = [rpc EXCEPT ![r] = "check"]
    /\ UNCHANGED <<fn, arg, count, running, rn, dispvars, Registered, active>>

\* mt_proc_register_i(): n = p->count; is_registered() scan; full test. All
\* of it reads data that only lock holders write, so one step.
mt_proc_register_i_check(r) ==
    /\ rpc[r] = "check"
    /\ LET n == count
           dup == \E i \in 0 .. n - 1 : fn[i] = rf[r] /\ arg[i] = ra[r]
       IN /\ rn' = [rn EXCEPT ![r] = n]
          /\ rpc' = [rpc EXCEPT ![r] =
                       IF dup \/ n >= ProcMax THEN "unlock"          \* MT_E_DUPLICATE / MT_E_FULL
                       ELSE IF CountFirst THEN "publish" ELSE "write_fn"]
    /\ UNCHANGED <<fn, arg, count, running, lock, rf, ra, rcalls, dispvars, Registered, active>>

\* p->procs[n].fn = fn.
mt_proc_register_i_write_fn(r) ==
    /\ rpc[r] = "write_fn"
    /\ fn' = [fn EXCEPT ![rn[r]] = rf[r]]
    /\ rpc' = [rpc EXCEPT ![r] = "write_arg"]
    /\ UNCHANGED <<arg, count, running, lock, rf, ra, rn, rcalls, dispvars, Registered, active>>

\* p->procs[n].arg = arg (and the statistics zeroed, which the dispatcher
\* never touches for an index >= its n).
mt_proc_register_i_write_arg(r) ==
    /\ rpc[r] = "write_arg"
    /\ arg' = [arg EXCEPT ![rn[r]] = ra[r]]
    /\ rpc' = [rpc EXCEPT ![r] = IF CountFirst THEN "unlock" ELSE "publish"]
    /\ UNCHANGED <<fn, count, running, lock, rf, ra, rn, rcalls, dispvars, Registered, active>>

\* mt_store_release_u32(&p->count, n + 1).
mt_proc_register_i_publish(r) ==
    /\ rpc[r] = "publish"
    /\ count' = rn[r] + 1
    /\ Registered' = Append(Registered, <<rf[r], ra[r]>>)
    /\ rpc' = [rpc EXCEPT ![r] = IF CountFirst THEN "write_fn" ELSE "unlock"]
    /\ UNCHANGED <<fn, arg, running, lock, rf, ra, rn, rcalls, dispvars, active>>

\* mt_port_unlock().
mt_proc_register_unlock(r) ==
    /\ rpc[r] = "unlock"
    /\ lock' = FREE
    /\ rpc' = [rpc EXCEPT ![r] = "idle"]
    /\ rf' = [rf EXCEPT ![r] = NULL] /\ ra' = [ra EXCEPT ![r] = NULL]
    /\ rn' = [rn EXCEPT ![r] = 0]
    /\ UNCHANGED <<fn, arg, count, running, rcalls, dispvars, Registered, active>>

Registrar(r) ==
    \/ mt_proc_register_lock(r) \/ mt_proc_register_i_check(r)
    \/ mt_proc_register_i_write_fn(r) \/ mt_proc_register_i_write_arg(r)
    \/ mt_proc_register_i_publish(r) \/ mt_proc_register_unlock(r)

-----------------------------------------------------------------------------
(* Dispatcher: mt_proc_dispatch(p), called by the timer/IO thread and,     *)
(* re-entrantly, possibly from inside one of its procs.                     *)

\* if (p->running != 0) { refused } else p->running = 1.
mt_proc_dispatch_guard ==
    /\ dpc = "idle"
    /\ running' = 1
    /\ active' = active + 1
    /\ dpc' = "load"
    /\ UNCHANGED <<fn, arg, count, lock, regvars, dn, di, dfn, darg, Registered>>

\* n = mt_load_acquire_u32(&p->count).
mt_proc_dispatch_load ==
    /\ dpc = "load"
    /\ dn' = count
    /\ di' = 0
    /\ dpc' = IF count > 0 THEN "read_fn" ELSE "end"
    /\ UNCHANGED <<fn, arg, count, running, lock, regvars, dfn, darg, Registered, active>>

\* call_one(p, i): mt_invoke(e->fn, e->arg) reads fn, then arg.
call_one_read_fn ==
    /\ dpc = "read_fn"
    /\ dfn' = fn[di]
    /\ dpc' = "read_arg"
    /\ UNCHANGED <<fn, arg, count, running, lock, regvars, dn, di, darg, Registered, active>>

call_one_read_arg ==
    /\ dpc = "read_arg"
    /\ darg' = arg[di]
    /\ dpc' = "call"
    /\ UNCHANGED <<fn, arg, count, running, lock, regvars, dn, di, dfn, Registered, active>>

\* The proc runs and returns (and its statistics are updated), or it calls
\* mt_proc_dispatch(p) on its own set: the nested call meets running == 1
\* and returns MT_E_BUSY (refused++), unless the guard is missing, in which
\* case a second dispatch round is under way.
call_one_invoke ==
    /\ dpc = "call"
    /\ \/ /\ di' = di + 1
          /\ dpc' = IF di + 1 < dn THEN "read_fn" ELSE "end"
          /\ dfn' = NULL /\ darg' = NULL
          /\ UNCHANGED active
       \/ /\ NoGuard \/ running = 0
          /\ active' = active + 1          \* a nested round starts
          /\ UNCHANGED <<dpc, di, dfn, darg>>
       \/ /\ ~NoGuard /\ running # 0       \* nested call refused (MT_E_BUSY)
          /\ UNCHANGED <<dpc, di, dfn, darg, active>>
    /\ UNCHANGED <<fn, arg, count, running, lock, regvars, dn, Registered>>

\* Statistics of the round, then p->running = 0.
mt_proc_dispatch_end ==
    /\ dpc = "end"
    /\ running' = 0
    /\ active' = active - 1
    /\ dpc' = "idle" /\ dn' = 0 /\ di' = 0
    /\ UNCHANGED <<fn, arg, count, lock, regvars, dfn, darg, Registered>>

Dispatcher ==
    \/ mt_proc_dispatch_guard \/ mt_proc_dispatch_load
    \/ call_one_read_fn \/ call_one_read_arg \/ call_one_invoke \/ mt_proc_dispatch_end

-----------------------------------------------------------------------------
Next == Dispatcher \/ \E r \in Registrars : Registrar(r)

Spec == Init /\ [][Next]_vars /\ WF_vars(Dispatcher)
            /\ \A r \in Registrars : WF_vars(Registrar(r))

-----------------------------------------------------------------------------
(* Invariants                                                              *)

TypeOK ==
    /\ fn \in [Idx -> Fns \cup {NULL}] /\ arg \in [Idx -> Args \cup {NULL}]
    /\ count \in 0 .. ProcMax /\ running \in {0, 1}
    /\ lock \in Registrars \cup {FREE}
    /\ dn \in 0 .. ProcMax /\ di \in 0 .. ProcMax
    /\ active \in 0 .. 2

\* The dispatcher calls only an entry that was published, whole: the fn and
\* arg it passes are those registered at that index.
NeverCallsUnpublished ==
    dpc = "call" =>
        /\ di < count
        /\ dfn # NULL
        /\ <<dfn, darg>> = Registered[di + 1]

\* At most one dispatch round of the set is under way.
NoReentrantRun == active <= 1

CountBounded == count <= ProcMax /\ count = Len(Registered)

\* MtProcSetInv: every published entry has a callback; published entries
\* never change (append-only) and are never duplicated.
ProcSetInv ==
    /\ \A i \in 0 .. count - 1 : fn[i] # NULL /\ <<fn[i], arg[i]>> = Registered[i + 1]
    /\ \A i, j \in 1 .. Len(Registered) : i # j => Registered[i] # Registered[j]

\* Only lock holders are inside the register critical section.
MutualExclusion ==
    \A r \in Registrars : (rpc[r] # "idle") <=> (lock = r)

Safety ==
    /\ TypeOK /\ NeverCallsUnpublished /\ NoReentrantRun /\ CountBounded
    /\ ProcSetInv /\ MutualExclusion

-----------------------------------------------------------------------------
(* Liveness: every published proc is called (the dispatcher keeps running) *)

EveryPublishedProcCalled ==
    \A i \in Idx : (count > i) ~> (dpc = "call" /\ di = i)

=============================================================================
