(* What the Coq Interval proofs of the angle tables are about, and the tactics that check them.

   The tables themselves are not here: AntkitAngleTables.v is written at build time from the
   shipped C++ arrays (proofs/interval/gen_tables.cpp prints kernel/angle.hpp's kSineQ30 and
   kAtanUnits), so every statement below is instantiated with the tables that ship.

   Scalings (kernel/angle.hpp):
   - kSineQ30[i] is sin(i h) in units of 2^-30, h = (pi/2)/1024 = pi/2048, i = 0 .. 1025;
   - kAtanUnits[i] is atan(i/1024) in units of 2^-32 turn: a radian is 2^32/(2 pi) = 2^31/pi units.
   - interpolate_exact reads a 30-bit position u as index j = u >> 20 and weight w = u mod 2^20 and
     returns lo 2^20 + (hi - lo) w, exact: the table's units times 2^20.
   A table interval j is read at the points j + t, t = w / 2^20 in [0, 1); the checks below cover
   every real t in [0, 1], and every j from 0 to 1024 (the code reads interval 1024 only at t = 0,
   where it is entry 1024). *)
From Coq Require Import Reals ZArith List Lia Lra.
From Interval Require Import Tactic.
Open Scope R_scope.

(* Entry i (value x) is the correctly rounded value: within half a unit. *)
Definition sine_entry_at (i x : Z) : Prop :=
  Rabs (IZR x - 2 ^ 30 * sin (IZR i * PI / 2048)) <= 1 / 2.

Definition atan_entry_at (i x : Z) : Prop :=
  Rabs (IZR x - 2 ^ 31 / PI * atan (IZR i / 1024)) <= 1 / 2.

(* The linear interpolant between entries j (value lo) and j + 1 (value hi), at every real point
   of the interval, is within the bound of the function, in the table's units. For the sine the
   bound is h^2/8 + 2^-31 (the documented interpolation error plus the entries' rounding), which in
   units of 2^-30 is 2^30 (pi/2048)^2 / 8 + 1/2 = 32 pi^2 + 1/2 = 316.327; the shipped table's
   worst interval (1016) comes to about 316.132 (sampled in long double, not proved). *)
Definition sine_interp_bound : R := 32 * PI ^ 2 + 1 / 2.

Definition sine_interval_at (j lo hi : Z) : Prop :=
  forall t, 0 <= t <= 1 ->
  Rabs (IZR lo + (IZR hi - IZR lo) * t - 2 ^ 30 * sin ((IZR j + t) * PI / 2048))
  <= sine_interp_bound.

(* For atan the documentation's h^2/8 max|atan''| + 1/2 unit is 52.93 + 0.5 units, which its
   text rounds to 53.4; the shipped table's worst interval (591) comes to about 53.347 (sampled
   in long double, not proved). *)
Definition atan_interp_bound : R := 534 / 10.

Definition atan_interval_at (j lo hi : Z) : Prop :=
  forall t, 0 <= t <= 1 ->
  Rabs (IZR lo + (IZR hi - IZR lo) * t - 2 ^ 31 / PI * atan ((IZR j + t) / 1024))
  <= atan_interp_bound.

(* --- Every entry, every interval: walking the list -------------------------------------------- *)

(* P holds of every entry x of l with its index (the first entry's index is i). *)
Fixpoint each_entry (P : Z -> Z -> Prop) (i : Z) (l : list Z) : Prop :=
  match l with
  | nil => True
  | x :: r => P i x /\ each_entry P (Z.succ i) r
  end.

(* P holds of every two neighbouring entries x, y of l with the index of x. *)
Fixpoint each_pair (P : Z -> Z -> Z -> Prop) (i : Z) (l : list Z) : Prop :=
  match l with
  | x :: (y :: _) as r => P i x y /\ each_pair P (Z.succ i) r
  | _ => True
  end.

Lemma each_entry_cons (P : Z -> Z -> Prop) i x r :
  P i x -> each_entry P (Z.succ i) r -> each_entry P i (x :: r).
Proof. now split. Qed.

Lemma each_pair_cons (P : Z -> Z -> Z -> Prop) i x y r :
  P i x y -> each_pair P (Z.succ i) (y :: r) -> each_pair P i (x :: y :: r).
Proof. now split. Qed.

Lemma each_entry_nth (P : Z -> Z -> Prop) :
  forall l i, each_entry P i l ->
  forall k, (k < length l)%nat -> P (i + Z.of_nat k)%Z (nth k l 0%Z).
Proof.
  induction l as [| x r IH]; intros i H k Hk; simpl in Hk; [lia |].
  destruct H as [H0 H1]. destruct k as [| k].
  - simpl. now rewrite Z.add_0_r.
  - replace (i + Z.of_nat (S k))%Z with (Z.succ i + Z.of_nat k)%Z by lia.
    apply (IH _ H1 k). lia.
Qed.

Lemma each_pair_nth (P : Z -> Z -> Z -> Prop) :
  forall l i, each_pair P i l ->
  forall k, (S k < length l)%nat -> P (i + Z.of_nat k)%Z (nth k l 0%Z) (nth (S k) l 0%Z).
Proof.
  induction l as [| x r IH]; intros i H k Hk; simpl in Hk; [lia |].
  destruct r as [| y r']; simpl in Hk; [lia |].
  destruct H as [H0 H1]. destruct k as [| k].
  - simpl. now rewrite Z.add_0_r.
  - replace (i + Z.of_nat (S k))%Z with (Z.succ i + Z.of_nat k)%Z by lia.
    apply (IH _ H1 k). simpl. lia.
Qed.

Lemma each_entry_split (P : Z -> Z -> Prop) :
  forall n l i, each_entry P i (firstn n l) -> each_entry P (i + Z.of_nat n) (skipn n l) ->
  each_entry P i l.
Proof.
  induction n as [| n IH]; intros l i H0 H1.
  - simpl in H1. now rewrite Z.add_0_r in H1.
  - destruct l as [| x r]; [exact I |]. destruct H0 as [Hx H0]. split; [exact Hx |].
    apply (IH r (Z.succ i) H0). now replace (Z.succ i + Z.of_nat n)%Z with (i + Z.of_nat (S n))%Z
      by lia.
Qed.

Lemma each_pair_split (P : Z -> Z -> Z -> Prop) :
  forall n l i, each_pair P i (firstn (S n) l) -> each_pair P (i + Z.of_nat n) (skipn n l) ->
  each_pair P i l.
Proof.
  induction n as [| n IH]; intros l i H0 H1.
  - simpl in H1. now rewrite Z.add_0_r in H1.
  - destruct l as [| x [| y r]]; [exact I | exact I |]. destruct H0 as [Hx H0]. split; [exact Hx |].
    apply (IH (y :: r) (Z.succ i) H0). now replace (Z.succ i + Z.of_nat n)%Z
      with (i + Z.of_nat (S n))%Z by lia.
Qed.

(* Proves `each_entry P i l` (`each_pair`) by running `check` on each entry (pair) in turn. The
   list is cut into chunks of `chunk_size` entries that are computed to literals one at a time
   (a goal holding the whole 1026-entry literal makes every step of the walk slow), and the index
   of each step is computed to a literal, so every goal `check` sees is closed: literal index,
   literal entries. The recursion makes a failing `check` fail the whole proof with its own
   message (proof.teeth.interval_* look for Interval's). *)
Definition chunk_size : nat := 32.

Ltac next_index :=
  match goal with
  | |- context [Z.succ ?i] => let j := eval vm_compute in (Z.succ i) in change (Z.succ i) with j
  end.

Ltac walk_entries check :=
  lazymatch goal with
  | |- each_entry _ _ nil => exact I
  | |- each_entry _ _ (_ :: _) => apply each_entry_cons; [check | next_index; walk_entries check]
  end.

Ltac walk_pairs check :=
  lazymatch goal with
  | |- each_pair _ _ nil => exact I
  | |- each_pair _ _ (_ :: nil) => exact I
  | |- each_pair _ _ (_ :: _ :: _) => apply each_pair_cons; [check | next_index; walk_pairs check]
  end.

Ltac literal_list l :=
  let c := eval vm_compute in l in change l with c.

Ltac literal_index i :=
  let j := eval vm_compute in i in change i with j.

Ltac each_entry_by_chunks check :=
  lazymatch goal with
  | |- each_entry ?P ?i ?l =>
      let len := eval vm_compute in (length l) in
      lazymatch len with
      | O => literal_list l; exact I
      | _ =>
          apply (each_entry_split P chunk_size l i);
          [ literal_list (firstn chunk_size l); walk_entries check
          | literal_index (i + Z.of_nat chunk_size)%Z; each_entry_by_chunks check ]
      end
  end.

Ltac each_pair_by_chunks check :=
  lazymatch goal with
  | |- each_pair ?P ?i ?l =>
      let len := eval vm_compute in (length l) in
      lazymatch len with
      | O => literal_list l; exact I
      | S O => literal_list l; exact I
      | _ =>
          apply (each_pair_split P chunk_size l i);
          [ literal_list (firstn (S chunk_size) l); walk_pairs check
          | literal_index (i + Z.of_nat chunk_size)%Z; each_pair_by_chunks check ]
      end
  end.

(* The precision and the Taylor degree were chosen for speed with a margin: the entries need
   about 45 bits (the closest entry to a tie is 0.4993 units off, in 2^30), the interpolants a
   degree-3 Taylor model in t. Every `interval` here names a precision other than 53 bits: at 53
   Interval computes with the kernel's primitive floats, which would add their assumptions
   (PrimFloat, FloatAxioms) to allowed_assumptions.txt; at any other it uses Bignums. *)
Ltac check_entry := unfold sine_entry_at, atan_entry_at; interval with (i_prec 70).

Ltac check_interval :=
  let t := fresh "t" in
  let Ht := fresh "Ht" in
  unfold sine_interval_at, atan_interval_at; intros t Ht;
  unfold sine_interp_bound, atan_interp_bound;
  interval with (i_prec 40, i_taylor t, i_degree 3).
