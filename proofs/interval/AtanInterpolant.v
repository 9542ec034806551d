(* On every interval of the shipped atan table, at every real point, the linear interpolant of the
   two shipped entries is within 53.4 units (2^-32 turn) of atan: the documented h^2/8 max|atan''|
   (52.93 units) plus the entries' rounding (1/2). *)
From Coq Require Import Reals ZArith.
Require Import AntkitAngleTables IntervalAngle.

Theorem atan_interpolant_within : each_pair atan_interval_at 0 kAtanUnits.
Proof. each_pair_by_chunks check_interval. Qed.
