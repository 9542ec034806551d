(* Every entry of the shipped atan table kAtanUnits is atan(i/1024) in units of 2^-32 turn
   (2^31/pi units a radian), correctly rounded: within half a unit, i = 0 .. 1025. *)
From Coq Require Import Reals ZArith.
Require Import AntkitAngleTables IntervalAngle.

Theorem atan_entries_rounded : each_entry atan_entry_at 0 kAtanUnits.
Proof. each_entry_by_chunks check_entry. Qed.
