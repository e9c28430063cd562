------------------------------- MODULE WqMC --------------------------------
(* Item tables of the Wq configurations (tla/cfg/Wq_*.cfg
   substitute Period and Cost with one of them). Items are 1..NItems. *)
EXTENDS Wq

\* No timers, runs without time (the race configurations).
Untimed2 == <<0, 0>>

\* Item 1 every 3 ticks, item 2 activated by the schedulers; each run takes one
\* tick. Not overloaded: item 1 waits at most for the rest of one run and one
\* queued run of item 2 (FIFO, merged activations): 2 ticks < 3.
Period3 == <<3, 0>>
Cost1 == <<1, 1>>

\* Item 1 every 2 ticks; item 2 runs 2 ticks: overloaded (item 1 can wait
\* 1 + 2 ticks > 2).
Period2 == <<2, 0>>
Cost12 == <<1, 2>>
=============================================================================
