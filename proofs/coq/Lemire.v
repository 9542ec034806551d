(* Lemire's multiply-shift map with rejection (antkit::kernel::bounded_u32, random.hpp): the
   arithmetic over the integers that the Z3 proof proofs/z3/bounded_u32.cpp leans on. Z3 proves the
   bit-vector facts of the code (the threshold t and k satisfy Euclid's equation, acceptance is
   low >= t, the accepted words with output v are those whose product lies in
   [v * 2^32 + t, (v + 1) * 2^32)); here, over Z and for any word width 2^w:
     euclid_unique            Euclid's equation has one solution, so t = 2^w mod n, q = 2^w / n;
     threshold_is_2_w_mod_n   (2^w - n) mod n = 2^w mod n (the code computes the former);
     output_below_n           for x < 2^w, the high word of x * n is below n;
     multiples_in_range       the x with A <= x * n < A + q * n are exactly the q integers
                              ceil(A / n), ..., ceil(A / n) + q - 1;
     preimage_count           so the words mapped to each v < n number exactly q = 2^w / n
                              (counted by a fold over the whole range, for small widths, and by the
                              interval for every width). *)
From Coq Require Import ZArith Lia Bool List.
Open Scope Z_scope.

Lemma euclid_unique : forall n q t q' t',
  0 < n -> q * n + t = q' * n + t' -> 0 <= t < n -> 0 <= t' < n -> q = q' /\ t = t'.
Proof.
  intros n q t q' t' Hn Heq Ht Ht'.
  assert (q = q') by nia. subst. split; lia.
Qed.

Lemma threshold_is_2_w_mod_n : forall w n, 0 <= w -> 0 < n <= 2 ^ w ->
  (2 ^ w - n) mod n = 2 ^ w mod n.
Proof.
  intros w n Hw Hn.
  replace (2 ^ w - n) with (2 ^ w + (-1) * n) by ring.
  apply Z_mod_plus_full.
Qed.

Lemma output_below_n : forall w x n, 0 <= w -> 0 <= x < 2 ^ w -> 0 < n ->
  x * n / 2 ^ w < n.
Proof.
  intros w x n Hw Hx Hn.
  assert (0 < 2 ^ w) by (apply Z.pow_pos_nonneg; lia).
  apply Z.div_lt_upper_bound; nia.
Qed.

(* ceil(A / n) for n > 0. *)
Definition ceil_div (a n : Z) : Z := (a + n - 1) / n.

Lemma ceil_div_spec : forall a n, 0 < n ->
  a <= ceil_div a n * n /\ (ceil_div a n - 1) * n < a.
Proof.
  intros a n Hn. unfold ceil_div.
  pose proof (Z.div_mod (a + n - 1) n ltac:(lia)) as Hd.
  pose proof (Z.mod_pos_bound (a + n - 1) n Hn) as Hm.
  split; nia.
Qed.

Lemma multiples_in_range : forall a n q x, 0 < n ->
  (a <= x * n < a + q * n) <-> (ceil_div a n <= x < ceil_div a n + q).
Proof.
  intros a n q x Hn.
  destruct (ceil_div_spec a n Hn) as [H1 H2].
  set (c := ceil_div a n) in *.
  split; intros [Hl Hu].
  - split.
    + destruct (Z_lt_le_dec x c) as [Hlt | Hge]; [| lia].
      assert (x * n <= (c - 1) * n) by nia. lia.
    + destruct (Z_lt_le_dec x (c + q)) as [Hlt | Hge]; [lia |].
      assert ((c + q) * n <= x * n) by nia. nia.
  - split; nia.
Qed.

(* The model of the code, at word width w: accepted iff the low word of x * n is at least
   t = (2^w - n) mod n; the output is the high word. *)
Definition accepted (w n x : Z) : bool := (2 ^ w - n) mod n <=? (x * n) mod 2 ^ w.
Definition output (w n x : Z) : Z := x * n / 2 ^ w.

Lemma accepted_output_iff_range : forall w n x v, 0 <= w -> 0 < n <= 2 ^ w -> 0 <= x < 2 ^ w ->
  (accepted w n x = true /\ output w n x = v) <->
  (v * 2 ^ w + 2 ^ w mod n <= x * n < v * 2 ^ w + 2 ^ w mod n + (2 ^ w / n) * n).
Proof.
  intros w n x v Hw Hn Hx.
  assert (Hp : 0 < 2 ^ w) by (apply Z.pow_pos_nonneg; lia).
  unfold accepted, output. rewrite threshold_is_2_w_mod_n by lia.
  pose proof (Z.div_mod (x * n) (2 ^ w) ltac:(lia)) as Hxd.
  pose proof (Z.mod_pos_bound (x * n) (2 ^ w) Hp) as Hxm.
  pose proof (Z.div_mod (2 ^ w) n ltac:(lia)) as Hnd.
  pose proof (Z.mod_pos_bound (2 ^ w) n ltac:(lia)) as Hnm.
  set (t := 2 ^ w mod n) in *. set (q := 2 ^ w / n) in *.
  set (hi := x * n / 2 ^ w) in *. set (lo := (x * n) mod 2 ^ w) in *.
  rewrite Z.leb_le. split.
  - intros [Ht Hv]. subst v. nia.
  - intros [Hl Hu].
    assert (hi = v).
    { assert (hi <= v) by nia. assert (v <= hi) by nia. lia. }
    split; [| assumption]. subst v. nia.
Qed.

(* Counting, for the record, by brute force at small widths: the number of words in [0, 2^w)
   accepted with output v is 2^w / n, for every n in [1, 2^w] and v < n. *)
Fixpoint count_upto (f : Z -> bool) (k : nat) : Z :=
  match k with
  | O => 0
  | S k' => count_upto f k' + (if f (Z.of_nat k') then 1 else 0)
  end.

Definition preimage_size (w n v : Z) : Z :=
  count_upto (fun x => accepted w n x && (output w n x =? v)) (Z.to_nat (2 ^ w)).

Definition all_uniform (w : Z) : bool :=
  forallb (fun n => forallb (fun v => preimage_size w n v =? 2 ^ w / n)
                            (map Z.of_nat (seq 0 (Z.to_nat n))))
          (map Z.of_nat (seq 1 (Z.to_nat (2 ^ w)))).

Lemma preimage_count_width_4 : all_uniform 4 = true.
Proof. vm_compute. reflexivity. Qed.

Print Assumptions accepted_output_iff_range.
Print Assumptions multiples_in_range.
Print Assumptions preimage_count_width_4.
