(* SPDX-License-Identifier: Apache-2.0 *)
(* proofs/wp/wp_poll.ml -- loaded into every WP run (frama-c -load-module, proofs/proofs.mk).

   Frama-C drives WP's proof tasks (VC generation, cache look-up, prover calls) from a task
   server that advances every running task by one step per round and then sleeps 50 ms in
   Task.on_idle before the next round. With -wp-par 2 only two tasks advance per round, so a
   module whose verdicts all come from the WP cache spent about half of its wall time asleep
   (strace of `make wp-sem`: 114 sleeps of 50 ms in an 8 s run; sched 248 s wall for 92 s of
   CPU). This module polls every 2 ms instead. It changes when the server looks at its tasks,
   nothing else: goals, prover tasks, time limits (enforced by Why3's own server) and
   verdicts are those of the stock loop. *)
let poll_seconds = 0.002

let () =
  Task.on_idle :=
    fun ready ->
      try
        while ready () do
          Unix.sleepf poll_seconds
        done
      with Db.Cancel -> ()
