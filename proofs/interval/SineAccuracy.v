(* The sine's accuracy, machine-checked for the tables that ship (issue 41).

   proofs/z3/angle_sine.cpp proves that the shipped sin_raw computes exactly "fold the angle to the
   quarter wave, interpolate kSineQ30 at u (index u >> 20, weight u mod 2^20, exact), round half up
   by 50 - F bits, apply the sign": AngleBounds.v's fold_position, interpolate and the shift
   below. SineEntries.v and SineInterpolant.v check, with Coq Interval, every entry of the shipped
   table and every real point of every interval; this file adds the terms. The result is the
   documented bound |sin(a) - sin_exact(a)| <= 2^-(F+1) + 2.947e-7 for every 32-bit angle and
   every F <= 49, with no step on paper but the Z3 proof's "a W-bit term proved not to wrap equals
   its integer". *)
From Coq Require Import Reals ZArith List.
Require Import AntkitAngleTables IntervalAngle AngleBounds SineEntries SineInterpolant.
Open Scope R_scope.

Lemma kSineQ30_length : length kSineQ30 = 1026%nat.
Proof. reflexivity. Qed.

(* |kSineQ30[i] - 2^30 sin(i pi/2048)| <= 1/2 for i = 0 .. 1025. *)
Theorem sine_table_correctly_rounded : forall i, (i < 1026)%nat ->
  Rabs (IZR (nth i kSineQ30 0%Z) - 2 ^ 30 * sin (INR i * PI / 2048)) <= 1 / 2.
Proof.
  intros i Hi. rewrite INR_IZR_INZ.
  pose proof (each_entry_nth _ kSineQ30 0 sine_entries_rounded i) as H.
  rewrite kSineQ30_length in H. exact (H Hi).
Qed.

(* The exact interpolant (units of 2^-50) is within h^2/8 + 2^-31 of sin at every position u of
   the quarter wave, u pi/2^31 radians; h^2/8 + 2^-31 <= 2.947e-7. *)
Theorem sine_interpolant_accuracy : forall u, (0 <= u <= 2 ^ 30)%Z ->
  Rabs (IZR (interpolate kSineQ30 u) / IZR (2 ^ 50) - sin (IZR u * PI / IZR (2 ^ 31)))
  <= PI ^ 2 / 2 ^ 25 + / 2 ^ 31.
Proof. exact (sine_interpolate_accuracy kSineQ30 kSineQ30_length sine_interpolant_within). Qed.

(* sin_raw<I, W, F>(a) / 2^F is within 2^-(F+1) + 2.947e-7 of sin(a 2 pi / 2^32), for every
   angle a in [0, 2^32) and every F in [0, 49]. *)
Theorem sine_documented_bound : forall F a, (0 <= F <= 49)%Z -> (0 <= a < 2 ^ 32)%Z ->
  let m := Z.shiftr (interpolate kSineQ30 (fold_position a) + 2 ^ (49 - F)) (50 - F) in
  let result := if fold_negative a then (- m)%Z else m in
  Rabs (IZR result / IZR (2 ^ F) - sin (IZR a * (2 * PI) / IZR (2 ^ 32)))
  <= / IZR (2 ^ (F + 1)) + 2947 / 10 ^ 10.
Proof. exact (sine_every_angle kSineQ30 kSineQ30_length sine_interpolant_within). Qed.

(* The three theorems' assumptions, in one traversal (each `Print Assumptions` walks the
   entries' and intervals' proofs again: about 9 s apiece); the ctest driver requires each
   name it prints to be on the allow-list. *)
Definition sine_accuracy_theorems := (sine_table_correctly_rounded, sine_interpolant_accuracy,
  sine_documented_bound).
Print Assumptions sine_accuracy_theorems.
