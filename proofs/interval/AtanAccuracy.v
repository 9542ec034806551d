(* atan2's accuracy, machine-checked for the table that ships (issue 41).

   proofs/z3/angle_atan2.cpp proves that the shipped atan2_raw computes exactly "fold (x, y) to the
   first octant (0 <= n <= d), ratio = floor(2^30 n/d + 1/2), interpolate kAtanUnits at the ratio
   (exact), round half up to a unit, unfold with exact binary-angle arithmetic": AngleBounds.v's
   interpolate and the shift below; the unfold (2^30 - base, 2^31 - octant, -half, mod 2^32) is
   exact and maps the true angle the same way. AtanEntries.v and AtanInterpolant.v check, with Coq
   Interval, every entry of the shipped table and every real point of every interval; this file
   adds the terms: 1/2 (the result's rounding) + 53.4 (interpolant and entries) + 1/pi (the
   ratio's rounding) = 54.22 <= 55, the documented bound. *)
From Coq Require Import Reals ZArith List.
Require Import AntkitAngleTables IntervalAngle AngleBounds AtanEntries AtanInterpolant.
Open Scope R_scope.

Lemma kAtanUnits_length : length kAtanUnits = 1026%nat.
Proof. reflexivity. Qed.

(* |kAtanUnits[i] - 2^31/pi atan(i/1024)| <= 1/2 for i = 0 .. 1025. *)
Theorem atan_table_correctly_rounded : forall i, (i < 1026)%nat ->
  Rabs (IZR (nth i kAtanUnits 0%Z) - 2 ^ 31 / PI * atan (INR i / 1024)) <= 1 / 2.
Proof.
  intros i Hi. rewrite INR_IZR_INZ.
  pose proof (each_entry_nth _ kAtanUnits 0 atan_entries_rounded i) as H.
  rewrite kAtanUnits_length in H. exact (H Hi).
Qed.

(* The exact interpolant (in units of 2^-20 unit, so divided by 2^20) is within 53.4 units of
   atan at every ratio r / 2^30 in [0, 1]. *)
Theorem atan_interpolant_accuracy : forall r, (0 <= r <= 2 ^ 30)%Z ->
  Rabs (IZR (interpolate kAtanUnits r) / IZR (2 ^ 20) - 2 ^ 31 / PI * atan (IZR r / IZR (2 ^ 30)))
  <= 534 / 10.
Proof. exact (atan_interpolate_accuracy kAtanUnits kAtanUnits_length atan_interpolant_within). Qed.

(* atan2_raw's first-octant value is within 55 units of atan(n/d), for every 0 <= n <= d, d > 0. *)
Theorem atan_documented_bound : forall n d, (0 <= n <= d)%Z -> (0 < d)%Z ->
  let ratio := ((2 * (n * 2 ^ 30) + d) / (2 * d))%Z in
  let base := Z.shiftr (interpolate kAtanUnits ratio + 2 ^ 19) 20 in
  Rabs (IZR base - 2 ^ 31 / PI * atan (IZR n / IZR d)) <= 55.
Proof.
  intros n d Hn Hd ratio base.
  eapply Rle_trans; [exact (atan_octant_bound kAtanUnits kAtanUnits_length
                              atan_interpolant_within n d Hn Hd) |].
  exact atan_octant_documented.
Qed.

(* The three theorems' assumptions, in one traversal (each `Print Assumptions` walks the
   entries' and intervals' proofs again: about 9 s apiece); the ctest driver requires each
   name it prints to be on the allow-list. *)
Definition atan_accuracy_theorems := (atan_table_correctly_rounded, atan_interpolant_accuracy,
  atan_documented_bound).
Print Assumptions atan_accuracy_theorems.
