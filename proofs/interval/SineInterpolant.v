(* On every interval of the shipped sine table, at every real point, the linear interpolant of the
   two shipped entries is within 32 pi^2 + 1/2 units of 2^-30 (h^2/8 + 2^-31) of the sine. *)
From Coq Require Import Reals ZArith.
Require Import AntkitAngleTables IntervalAngle.

Theorem sine_interpolant_within : each_pair sine_interval_at 0 kSineQ30.
Proof. each_pair_by_chunks check_interval. Qed.
