(* The lemmas that add the error terms: from the checks of IntervalAngle.v's predicates on every
   entry and every interval of a table, to the documented bounds of the code that reads it. They
   hold for any table of 1026 entries that passes the checks; SineAccuracy.v and AtanAccuracy.v
   instantiate them with the shipped tables. (A separate file from IntervalAngle.v so that the
   teeth, which tighten a bound there, recompile only the definitions.) *)
From Coq Require Import Reals ZArith List Lia Lra.
From Interval Require Import Tactic.
Require Import IntervalAngle.
Open Scope R_scope.

(* --- The code's interpolation, over Z --------------------------------------------------------- *)

(* kernel/angle.hpp interpolate_exact at the 30-bit position u, term for term: index = u >> 20,
   weight = u & (2^20 - 1), lo << 20 + (hi - lo) * weight (proofs/z3/angle_sine.cpp and
   angle_atan2.cpp prove the shipped template computes exactly this, without overflow). *)
Definition interpolate (tbl : list Z) (u : Z) : Z :=
  let index := Z.shiftr u 20 in
  let weight := Z.land u (2 ^ 20 - 1) in
  let lo := nth (Z.to_nat index) tbl 0%Z in
  let hi := nth (Z.to_nat (index + 1)) tbl 0%Z in
  (lo * 2 ^ 20 + (hi - lo) * weight)%Z.

Lemma interpolate_at (tbl : list Z) (u : Z) :
  (0 <= u)%Z ->
  let j := (u / 2 ^ 20)%Z in
  let w := (u mod 2 ^ 20)%Z in
  interpolate tbl u =
    (nth (Z.to_nat j) tbl 0%Z * 2 ^ 20
     + (nth (S (Z.to_nat j)) tbl 0%Z - nth (Z.to_nat j) tbl 0%Z) * w)%Z.
Proof.
  intros Hu j w. unfold interpolate.
  rewrite Z.shiftr_div_pow2 by lia.
  replace (2 ^ 20 - 1)%Z with (Z.ones 20) by reflexivity.
  rewrite Z.land_ones by lia. fold j w.
  replace (Z.to_nat (j + 1)) with (S (Z.to_nat j)).
  - reflexivity.
  - assert (0 <= j)%Z by (apply Z.div_pos; lia). lia.
Qed.
(* --- Rounding half up by a shift -------------------------------------------------------------- *)

Lemma shift_round_half_up (E s : Z) : (1 <= s)%Z ->
  (Z.abs (Z.shiftr (E + 2 ^ (s - 1)) s * 2 ^ s - E) <= 2 ^ (s - 1))%Z.
Proof.
  intros Hs. rewrite Z.shiftr_div_pow2 by lia.
  assert (Hp : (2 ^ s = 2 * 2 ^ (s - 1))%Z).
  { rewrite <- Z.pow_succ_r by lia. f_equal. lia. }
  assert (Hpos : (0 < 2 ^ (s - 1))%Z) by (apply Z.pow_pos_nonneg; lia).
  pose proof (Z.div_mod (E + 2 ^ (s - 1)) (2 ^ s) ltac:(lia)) as Hdm.
  pose proof (Z.mod_pos_bound (E + 2 ^ (s - 1)) (2 ^ s) ltac:(lia)) as Hb.
  set (q := ((E + 2 ^ (s - 1)) / 2 ^ s)%Z) in *.
  set (r := ((E + 2 ^ (s - 1)) mod 2 ^ s)%Z) in *.
  set (P := (2 ^ (s - 1))%Z) in *. rewrite Hp in *. apply Z.abs_le. lia.
Qed.

Lemma abs_div_le (a k b : R) : 0 < k -> Rabs a <= b * k -> Rabs (a / k) <= b.
Proof.
  intros Hk H. unfold Rdiv.
  rewrite Rabs_mult, (Rabs_right (/ k)) by (left; apply Rinv_0_lt_compat; lra).
  apply (Rmult_le_reg_r k); [lra |]. rewrite Rmult_assoc, Rinv_l, Rmult_1_r by lra. exact H.
Qed.

Lemma pow2_pos (k : Z) : (0 <= k)%Z -> 0 < IZR (2 ^ k).
Proof. intros Hk. apply IZR_lt. apply Z.pow_pos_nonneg; lia. Qed.

(* The same in real units: m / 2^F is within 2^-(F+1) of E / 2^(F+s). *)
Lemma shift_round_half_up_real (E s F : Z) : (1 <= s)%Z -> (0 <= F)%Z ->
  Rabs (IZR (Z.shiftr (E + 2 ^ (s - 1)) s) / IZR (2 ^ F) - IZR E / IZR (2 ^ (F + s)))
  <= / IZR (2 ^ (F + 1)).
Proof.
  intros Hs HF.
  pose proof (shift_round_half_up E s Hs) as H.
  set (m := Z.shiftr (E + 2 ^ (s - 1)) s) in *.
  pose proof (pow2_pos F HF). pose proof (pow2_pos s ltac:(lia)).
  pose proof (pow2_pos (F + 1) ltac:(lia)). pose proof (pow2_pos (s - 1) ltac:(lia)).
  assert (HFs : IZR (2 ^ (F + s)) = IZR (2 ^ F) * IZR (2 ^ s)).
  { rewrite <- mult_IZR. f_equal. apply Z.pow_add_r; lia. }
  assert (HF1 : IZR (2 ^ (F + 1)) * IZR (2 ^ (s - 1)) = IZR (2 ^ F) * IZR (2 ^ s)).
  { rewrite <- !mult_IZR. f_equal. rewrite <- !Z.pow_add_r by lia. f_equal. lia. }
  replace (IZR m / IZR (2 ^ F) - IZR E / IZR (2 ^ (F + s)))
    with (IZR (m * 2 ^ s - E) / (IZR (2 ^ F) * IZR (2 ^ s))).
  2: { rewrite HFs, minus_IZR, mult_IZR. field. split; lra. }
  apply abs_div_le; [nra |].
  replace (/ IZR (2 ^ (F + 1)) * (IZR (2 ^ F) * IZR (2 ^ s))) with (IZR (2 ^ (s - 1))).
  2: { rewrite <- HF1. field. lra. }
  rewrite Rabs_Zabs. apply IZR_le. exact H.
Qed.

(* --- The sine: the code's interpolation at every position of the quarter wave ----------------- *)

(* A position u in [0, 2^30] (units of 2^-32 turn) reads interval j = u / 2^20 at t = w / 2^20,
   w = u mod 2^20; the angle u pi / 2^31 is (j + t) pi / 2048 and the code's value, in units of
   2^-50, is 2^20 times the interpolant in units of 2^-30. *)
Lemma position_split (u : Z) : (0 <= u)%Z ->
  IZR u = 1048576 * IZR (u / 2 ^ 20) + IZR (u mod 2 ^ 20).
Proof.
  intros Hu. rewrite <- mult_IZR, <- plus_IZR. f_equal.
  rewrite (Z.div_mod u (2 ^ 20)) at 1 by lia. reflexivity.
Qed.

Lemma sine_interpolate_accuracy (tbl : list Z) :
  length tbl = 1026%nat -> each_pair sine_interval_at 0 tbl ->
  forall u, (0 <= u <= 2 ^ 30)%Z ->
  Rabs (IZR (interpolate tbl u) / IZR (2 ^ 50) - sin (IZR u * PI / IZR (2 ^ 31)))
  <= PI ^ 2 / 2 ^ 25 + / 2 ^ 31.
Proof.
  intros Hlen Hall u Hu.
  assert (Hj : (0 <= u / 2 ^ 20 <= 1024)%Z).
  { split; [apply Z.div_pos; lia | apply Z.div_le_upper_bound; lia]. }
  pose proof (Z.mod_pos_bound u (2 ^ 20) ltac:(lia)) as Hw.
  pose proof (position_split u ltac:(lia)) as Hsplit.
  rewrite (interpolate_at tbl u) by lia.
  set (j := (u / 2 ^ 20)%Z) in *. set (w := (u mod 2 ^ 20)%Z) in *.
  pose proof (each_pair_nth _ tbl 0 Hall (Z.to_nat j) ltac:(rewrite Hlen; lia)) as H.
  rewrite Z.add_0_l, Z2Nat.id in H by lia.
  set (lo := nth (Z.to_nat j) tbl 0%Z) in *. set (hi := nth (S (Z.to_nat j)) tbl 0%Z) in *.
  unfold sine_interval_at, sine_interp_bound in H.
  assert (Ht : 0 <= IZR w / 1048576 <= 1).
  { destruct Hw as [Hw0 Hw1]. apply IZR_le in Hw0. apply IZR_lt in Hw1.
    change (IZR (2 ^ 20)) with 1048576 in Hw1. split; unfold Rdiv; nra. }
  specialize (H _ Ht).
  change (IZR (2 ^ 50)) with 1125899906842624. change (IZR (2 ^ 31)) with 2147483648.
  rewrite plus_IZR, !mult_IZR, minus_IZR. change (IZR (2 ^ 20)) with 1048576.
  rewrite Hsplit.
  replace ((1048576 * IZR j + IZR w) * PI / 2147483648) with ((IZR j + IZR w / 1048576) * PI / 2048)
    by field.
  set (x := (IZR j + IZR w / 1048576) * PI / 2048) in *.
  replace (((IZR lo * 1048576 + (IZR hi - IZR lo) * IZR w) / 1125899906842624) - sin x)
    with ((IZR lo + (IZR hi - IZR lo) * (IZR w / 1048576) - 2 ^ 30 * sin x) / 1073741824)
    by field.
  apply abs_div_le; [lra |].
  replace ((PI ^ 2 / 2 ^ 25 + / 2 ^ 31) * 1073741824) with (32 * PI ^ 2 + 1 / 2) by field.
  exact H.
Qed.

(* The documented constant: h^2/8 + 2^-31 = 2.94603e-7, below 2.947e-7. *)
Lemma sine_constant_documented : PI ^ 2 / 2 ^ 25 + / 2 ^ 31 <= 2947 / 10 ^ 10.
Proof. interval with (i_prec 40). Qed.

(* sin_raw's magnitude at F fraction bits, for a quarter-wave position u: the interpolation
   rounded half up by 50 - F bits is within 2^-(F+1) + 2.947e-7 of sin. *)
Lemma sine_quarter_wave_bound (tbl : list Z) :
  length tbl = 1026%nat -> each_pair sine_interval_at 0 tbl ->
  forall F u, (0 <= F <= 49)%Z -> (0 <= u <= 2 ^ 30)%Z ->
  Rabs (IZR (Z.shiftr (interpolate tbl u + 2 ^ (49 - F)) (50 - F)) / IZR (2 ^ F)
        - sin (IZR u * PI / IZR (2 ^ 31)))
  <= / IZR (2 ^ (F + 1)) + 2947 / 10 ^ 10.
Proof.
  intros Hlen Hall F u HF Hu.
  pose proof (sine_interpolate_accuracy tbl Hlen Hall u Hu) as Hi.
  pose proof (shift_round_half_up_real (interpolate tbl u) (50 - F) F ltac:(lia) ltac:(lia)) as Hr.
  replace (50 - F - 1)%Z with (49 - F)%Z in Hr by lia.
  replace (F + (50 - F))%Z with 50%Z in Hr by lia.
  pose proof sine_constant_documented.
  eapply Rle_trans;
    [| apply Rplus_le_compat; [exact Hr | eapply Rle_trans; [exact Hi | assumption]]].
  eapply Rle_trans; [| apply Rabs_triang]. right. f_equal. ring.
Qed.

(* --- atan: the code's interpolation at every ratio in [0, 1] ---------------------------------- *)

Lemma atan_interpolate_accuracy (tbl : list Z) :
  length tbl = 1026%nat -> each_pair atan_interval_at 0 tbl ->
  forall r, (0 <= r <= 2 ^ 30)%Z ->
  Rabs (IZR (interpolate tbl r) / IZR (2 ^ 20) - 2 ^ 31 / PI * atan (IZR r / IZR (2 ^ 30)))
  <= 534 / 10.
Proof.
  intros Hlen Hall r Hr.
  assert (Hj : (0 <= r / 2 ^ 20 <= 1024)%Z).
  { split; [apply Z.div_pos; lia | apply Z.div_le_upper_bound; lia]. }
  pose proof (Z.mod_pos_bound r (2 ^ 20) ltac:(lia)) as Hw.
  pose proof (position_split r ltac:(lia)) as Hsplit.
  rewrite (interpolate_at tbl r) by lia.
  set (j := (r / 2 ^ 20)%Z) in *. set (w := (r mod 2 ^ 20)%Z) in *.
  pose proof (each_pair_nth _ tbl 0 Hall (Z.to_nat j) ltac:(rewrite Hlen; lia)) as H.
  rewrite Z.add_0_l, Z2Nat.id in H by lia.
  set (lo := nth (Z.to_nat j) tbl 0%Z) in *. set (hi := nth (S (Z.to_nat j)) tbl 0%Z) in *.
  unfold atan_interval_at, atan_interp_bound in H.
  assert (Ht : 0 <= IZR w / 1048576 <= 1).
  { destruct Hw as [Hw0 Hw1]. apply IZR_le in Hw0. apply IZR_lt in Hw1.
    change (IZR (2 ^ 20)) with 1048576 in Hw1. split; unfold Rdiv; nra. }
  specialize (H _ Ht).
  change (IZR (2 ^ 30)) with 1073741824.
  rewrite plus_IZR, !mult_IZR, minus_IZR. change (IZR (2 ^ 20)) with 1048576.
  rewrite Hsplit.
  replace ((1048576 * IZR j + IZR w) / 1073741824) with ((IZR j + IZR w / 1048576) / 1024)
    by field.
  replace ((IZR lo * 1048576 + (IZR hi - IZR lo) * IZR w) / 1048576)
    with (IZR lo + (IZR hi - IZR lo) * (IZR w / 1048576)) by field.
  exact H.
Qed.

Lemma atan_lipschitz (x y : R) : Rabs (atan x - atan y) <= Rabs (x - y).
Proof.
  destruct (MVT_abs atan (fun c => / (1 + c ^ 2)) y x (fun c _ => derivable_pt_lim_atan c))
    as [c [Hc _]].
  rewrite Hc. rewrite <- (Rmult_1_l (Rabs (x - y))) at 2.
  apply Rmult_le_compat_r; [apply Rabs_pos |].
  assert (0 < 1 + c ^ 2) by nra.
  rewrite Rabs_right by (apply Rle_ge; left; apply Rinv_0_lt_compat; assumption).
  rewrite <- Rinv_1. apply Rinv_le_contravar; [lra | nra].
Qed.

(* atan2_raw's first-octant value for 0 <= n <= d, d > 0: the ratio floor(2^30 n/d + 1/2)
   (div_round_half_up(n << 30, d), as proofs/z3/angle_atan2.cpp proves the code computes), the
   interpolation at it, rounded half up to a unit, is within 55 units of atan(n/d) in units of
   2^-32 turn: 1/2 (the result's rounding) + 53.4 (interpolant and entries) + 1/pi (the ratio's
   rounding: 2^-31 in t, and |atan'| <= 1) = 54.22. *)
Lemma atan_octant_bound (tbl : list Z) :
  length tbl = 1026%nat -> each_pair atan_interval_at 0 tbl ->
  forall n d, (0 <= n <= d)%Z -> (0 < d)%Z ->
  let ratio := ((2 * (n * 2 ^ 30) + d) / (2 * d))%Z in
  let base := Z.shiftr (interpolate tbl ratio + 2 ^ 19) 20 in
  Rabs (IZR base - 2 ^ 31 / PI * atan (IZR n / IZR d)) <= / 2 + 534 / 10 + / PI.
Proof.
  intros Hlen Hall n d Hn Hd ratio base.
  pose proof (Z.div_mod (2 * (n * 2 ^ 30) + d) (2 * d) ltac:(lia)) as Hdm.
  pose proof (Z.mod_pos_bound (2 * (n * 2 ^ 30) + d) (2 * d) ltac:(lia)) as Hb.
  fold ratio in Hdm, Hb.
  assert (Hr : (0 <= ratio <= 2 ^ 30)%Z).
  { split; [apply Z.div_pos; lia |].
    apply Zlt_succ_le. apply Z.div_lt_upper_bound; lia. }
  assert (Hq : (Z.abs (2 * (d * ratio - 2 ^ 30 * n)) <= d)%Z) by (apply Z.abs_le; lia).
  pose proof (atan_interpolate_accuracy tbl Hlen Hall ratio Hr) as Hi.
  pose proof (shift_round_half_up_real (interpolate tbl ratio) 20 0 ltac:(lia) ltac:(lia)) as Hs.
  change (20 - 1)%Z with 19%Z in Hs. change (IZR (2 ^ 0)) with 1 in Hs.
  change (0 + 20)%Z with 20%Z in Hs. change (IZR (2 ^ (0 + 1))) with 2 in Hs.
  fold base in Hs. replace (IZR base / 1) with (IZR base) in Hs by field.
  (* the ratio's rounding *)
  assert (Ht : Rabs (IZR ratio / IZR (2 ^ 30) - IZR n / IZR d) <= / 2 ^ 31).
  { change (IZR (2 ^ 30)) with 1073741824.
    assert (0 < IZR d) by (apply IZR_lt; lia).
    replace (IZR ratio / 1073741824 - IZR n / IZR d)
      with (2 * (IZR d * IZR ratio - 1073741824 * IZR n) / (2147483648 * IZR d))
      by (field; lra).
    apply abs_div_le; [lra |].
    apply IZR_le in Hq. rewrite <- Rabs_Zabs in Hq.
    rewrite mult_IZR, minus_IZR, !mult_IZR in Hq. change (IZR (2 ^ 30)) with 1073741824 in Hq.
    replace (/ 2 ^ 31 * (2147483648 * IZR d)) with (IZR d) by field. exact Hq. }
  assert (Ha : Rabs (2 ^ 31 / PI * atan (IZR ratio / IZR (2 ^ 30))
                     - 2 ^ 31 / PI * atan (IZR n / IZR d)) <= / PI).
  { pose proof PI_RGT_0.
    replace (2 ^ 31 / PI * atan (IZR ratio / IZR (2 ^ 30)) - 2 ^ 31 / PI * atan (IZR n / IZR d))
      with (2 ^ 31 / PI * (atan (IZR ratio / IZR (2 ^ 30)) - atan (IZR n / IZR d))) by ring.
    rewrite Rabs_mult, (Rabs_right (2 ^ 31 / PI)).
    2: { apply Rle_ge. unfold Rdiv. left. apply Rmult_lt_0_compat; [lra |].
         apply Rinv_0_lt_compat. lra. }
    eapply Rle_trans.
    { apply Rmult_le_compat_l.
      - unfold Rdiv. left. apply Rmult_lt_0_compat; [lra | apply Rinv_0_lt_compat; lra].
      - eapply Rle_trans; [apply atan_lipschitz | exact Ht]. }
    right. field. lra. }
  eapply Rle_trans;
    [| apply Rplus_le_compat; [apply Rplus_le_compat; [exact Hs | exact Hi] | exact Ha]].
  eapply Rle_trans; [| apply Rplus_le_compat_r; apply Rabs_triang].
  eapply Rle_trans; [| apply Rabs_triang]. right. f_equal. ring.
Qed.

Lemma atan_octant_documented : / 2 + 534 / 10 + / PI <= 55.
Proof. interval with (i_prec 40). Qed.

(* --- The sine of every angle: the quadrant fold of sin_raw ------------------------------------ *)

(* sin_raw reads an angle a (units of 2^-32 turn) as quadrant q = a >> 30 and offset
   a & (2^30 - 1); odd quadrants read the quarter wave backwards (u = 2^30 - offset), quadrants 2
   and 3 are negative: sin(a) = +-sin(u), exactly. *)
Definition fold_position (a : Z) : Z :=
  let q := Z.shiftr a 30 in
  let offset := Z.land a (2 ^ 30 - 1) in
  if Z.odd q then (2 ^ 30 - offset)%Z else offset.

Definition fold_negative (a : Z) : bool := Z.testbit (Z.shiftr a 30) 1.

Lemma fold_exact (a : Z) : (0 <= a < 2 ^ 32)%Z ->
  (0 <= fold_position a <= 2 ^ 30)%Z /\
  sin (IZR a * PI / IZR (2 ^ 31))
  = (if fold_negative a then -1 else 1) * sin (IZR (fold_position a) * PI / IZR (2 ^ 31)).
Proof.
  intros Ha. unfold fold_position, fold_negative.
  rewrite Z.shiftr_div_pow2 by lia.
  replace (2 ^ 30 - 1)%Z with (Z.ones 30) by reflexivity.
  rewrite Z.land_ones by lia.
  pose proof (Z.div_mod a (2 ^ 30) ltac:(lia)) as Hdm.
  pose proof (Z.mod_pos_bound a (2 ^ 30) ltac:(lia)) as Hb.
  assert (Hq : (0 <= a / 2 ^ 30 < 4)%Z).
  { split; [apply Z.div_pos; lia | apply Z.div_lt_upper_bound; lia]. }
  set (q := (a / 2 ^ 30)%Z) in *. set (off := (a mod 2 ^ 30)%Z) in *.
  assert (Hy : IZR a * PI / IZR (2 ^ 31) = IZR q * (PI / 2) + IZR off * PI / IZR (2 ^ 31)).
  { rewrite Hdm at 1. rewrite plus_IZR, mult_IZR. change (IZR (2 ^ 30)) with 1073741824.
    change (IZR (2 ^ 31)) with 2147483648. field. }
  rewrite Hy.
  assert (Hm : IZR (2 ^ 30 - off) * PI / IZR (2 ^ 31) = PI / 2 - IZR off * PI / IZR (2 ^ 31)).
  { rewrite minus_IZR. change (IZR (2 ^ 30)) with 1073741824.
    change (IZR (2 ^ 31)) with 2147483648. field. }
  set (y := IZR off * PI / IZR (2 ^ 31)) in *.
  assert (Hq4 : q = 0%Z \/ q = 1%Z \/ q = 2%Z \/ q = 3%Z) by lia.
  destruct Hq4 as [-> | [-> | [-> | ->]]];
    repeat match goal with
    | |- context [Z.testbit ?x ?i] =>
        let b := eval vm_compute in (Z.testbit x i) in change (Z.testbit x i) with b
    | |- context [Z.odd ?x] => let b := eval vm_compute in (Z.odd x) in change (Z.odd x) with b
    end;
    cbv iota; fold y; (split; [lia |]).
  - rewrite Rmult_0_l, Rplus_0_l. ring.
  - rewrite Hm, sin_shift, Rmult_1_l, Rplus_comm, sin_plus, sin_PI2, cos_PI2. ring.
  - replace (2 * (PI / 2)) with PI by field.
    rewrite Rplus_comm, neg_sin. ring.
  - rewrite Hm, sin_shift. replace (3 * (PI / 2) + y) with ((y + PI / 2) + PI) by field.
    rewrite neg_sin, sin_plus, sin_PI2, cos_PI2. ring.
Qed.

(* sin_raw<I, W, F> for every 32-bit angle a: the sign applied after the rounding, so the result is
   within 2^-(F+1) + 2.947e-7 of sin(a 2 pi / 2^32), the documented bound. *)
Lemma sine_every_angle (tbl : list Z) :
  length tbl = 1026%nat -> each_pair sine_interval_at 0 tbl ->
  forall F a, (0 <= F <= 49)%Z -> (0 <= a < 2 ^ 32)%Z ->
  let m := Z.shiftr (interpolate tbl (fold_position a) + 2 ^ (49 - F)) (50 - F) in
  let result := if fold_negative a then (- m)%Z else m in
  Rabs (IZR result / IZR (2 ^ F) - sin (IZR a * (2 * PI) / IZR (2 ^ 32)))
  <= / IZR (2 ^ (F + 1)) + 2947 / 10 ^ 10.
Proof.
  intros Hlen Hall F a HF Ha m result.
  destruct (fold_exact a Ha) as [Hu Hs].
  replace (IZR a * (2 * PI) / IZR (2 ^ 32)) with (IZR a * PI / IZR (2 ^ 31))
    by (change (IZR (2 ^ 32)) with 4294967296; change (IZR (2 ^ 31)) with 2147483648; field).
  rewrite Hs.
  pose proof (sine_quarter_wave_bound tbl Hlen Hall F (fold_position a) HF Hu) as H.
  fold m in H. unfold result.
  destruct (fold_negative a).
  - rewrite opp_IZR.
    replace (- IZR m / IZR (2 ^ F) - -1 * sin (IZR (fold_position a) * PI / IZR (2 ^ 31)))
      with (- (IZR m / IZR (2 ^ F) - sin (IZR (fold_position a) * PI / IZR (2 ^ 31)))).
    + rewrite Rabs_Ropp. exact H.
    + field. apply not_0_IZR. apply Z.pow_nonzero; lia.
  - rewrite Rmult_1_l. exact H.
Qed.
