(* Every entry of the shipped sine table kSineQ30 is sin(i pi/2048) correctly rounded to 2^-30:
   within half a unit, i = 0 .. 1025. *)
From Coq Require Import Reals ZArith.
Require Import AntkitAngleTables IntervalAngle.

Theorem sine_entries_rounded : each_entry sine_entry_at 0 kSineQ30.
Proof. each_entry_by_chunks check_entry. Qed.
