(* The supercover walk of kernel/include/antkit/kernel/raster.hpp (SupercoverWalk and
   detail::for_each_supercover_cell_until), modelled over the integers Z, for all endpoints.

   Model. In local coordinates the segment runs from (0, 0) to (dx, dy), dx, dy >= 0 (RasterFrame
   reflects any pair of cells there; the reflection is a bijection on cells and is not modelled).
   The state is (i, j, e) with e starting at dy - dx; next is X when e < 0, Y when e > 0, Corner
   when e = 0; advance does i + 1 and e + 2dy (X), j + 1 and e - 2dx (Y), i + 1, j + 1 and
   e + 2(dy - dx) (Corner), exactly as SupercoverWalk::advance. The cells emitted are a, then per
   step: at a corner the x-side cell (i + 1, j) and the y-side cell (i, j + 1), then the cell the
   step lands on (the last one is b), as for_each_supercover_cell_until does. `fuel` bounds the
   loop (Coq needs a structural bound); the theorems show dx + dy is always enough, so the bound
   is never what stops the walk.

   Proved, for every dx, dy >= 0 (by induction, not by computation):
     supercover_decision_variable_invariant  while the walk runs, 0 <= i <= dx, 0 <= j <= dy and
                        e = dy (2i + 1) - dx (2j + 1): the walk never leaves the bounding box of a
                        and b, and e is the quantity raster.hpp documents (its range
                        [-2dx, 2dy] is not proved here: the Z3 proofs and test_raster's
                        property check that);
     supercover_ends_at_b  the walk stops, after at most dx + dy steps, at (dx, dy), and the
                        last cell emitted is b;
     supercover_cell_count the number of cells is dx + dy + 1 plus one per corner step (C++:
                        "|dx| + |dy| + 1 cells plus one per corner passed");
     supercover_steps_are_unit  every step moves i or j or both by exactly one (with the corner's
                        two side cells in between, consecutive cells are then 4-adjacent or the
                        y-side cell is 4-adjacent to the cell two before it).
   Why it matters: the walk is a loop whose only exit is reaching b; if a step could overshoot b
   (step x at i = dx) the loop would never end and index cells outside the segment's box, which
   line_of_sight reads without a bounds check when a and b are on the grid.
   Golden vectors (proofs/golden/Supercover.out): a few walks, compared with the shipped
   supercover() by tests/proofs/test_supercover_golden.cpp. *)
From Coq Require Import ZArith List Lia.
Import ListNotations.
Open Scope Z_scope.

Record walk := mk { dx : Z; dy : Z; i : Z; j : Z; e : Z }.
Inductive step := X | Y | Corner.

Definition start (dx dy : Z) : walk := mk dx dy 0 0 (dy - dx).
Definition done (w : walk) : bool := (i w =? dx w) && (j w =? dy w).
Definition next (w : walk) : step :=
  if e w <? 0 then X else if 0 <? e w then Y else Corner.
Definition advance (w : walk) : walk :=
  match next w with
  | X => mk (dx w) (dy w) (i w + 1) (j w) (e w + dy w + dy w)
  | Y => mk (dx w) (dy w) (i w) (j w + 1) (e w - dx w - dx w)
  | Corner => mk (dx w) (dy w) (i w + 1) (j w + 1) (e w + (dy w - dx w) + (dy w - dx w))
  end.

(* The cells a step emits: the corner's two side cells, then the cell it lands on. *)
Definition step_cells (w : walk) : list (Z * Z) :=
  match next w with
  | Corner => [(i w + 1, j w); (i w, j w + 1); (i w + 1, j w + 1)]
  | X => [(i w + 1, j w)]
  | Y => [(i w, j w + 1)]
  end.

Fixpoint finish (fuel : nat) (w : walk) : walk :=
  match fuel with
  | O => w
  | S f => if done w then w else finish f (advance w)
  end.
Fixpoint steps (fuel : nat) (w : walk) : list step :=
  match fuel with
  | O => []
  | S f => if done w then [] else next w :: steps f (advance w)
  end.
Fixpoint cells_after (fuel : nat) (w : walk) : list (Z * Z) :=
  match fuel with
  | O => []
  | S f => if done w then [] else step_cells w ++ cells_after f (advance w)
  end.

Definition fuel_of (dx dy : Z) : nat := Z.to_nat (dx + dy).
Definition supercover (dx dy : Z) : list (Z * Z) := (0, 0) :: cells_after (fuel_of dx dy) (start dx dy).
Definition corners (l : list step) : nat :=
  length (filter (fun s => match s with Corner => true | _ => false end) l).

Definition inv (w : walk) : Prop :=
  0 <= i w <= dx w /\ 0 <= j w <= dy w /\ e w = dy w * (2 * i w + 1) - dx w * (2 * j w + 1).
Definition measure (w : walk) : Z := (dx w - i w) + (dy w - j w).

Lemma inv_start : forall dx dy, 0 <= dx -> 0 <= dy -> inv (start dx dy).
Proof. intros. unfold inv, start; simpl. lia. Qed.

(* i = dx forces e >= dx + dy; j = dy forces e <= -(dx + dy). *)
Lemma at_right_edge : forall dx dy j e, 0 <= dx -> 0 <= j -> j < dy ->
  e = dy * (2 * dx + 1) - dx * (2 * j + 1) -> e >= dx + dy.
Proof.
  intros dx dy j e Hx Hj Hlt He.
  assert (dx * (2 * j + 1) <= dx * (2 * dy - 1)) by (apply Z.mul_le_mono_nonneg_l; lia).
  subst e. nia.
Qed.

Lemma at_top_edge : forall dx dy i e, 0 <= dy -> 0 <= i -> i < dx ->
  e = dy * (2 * i + 1) - dx * (2 * dy + 1) -> e <= - (dx + dy).
Proof.
  intros dx dy i e Hy Hi Hlt He.
  assert (dy * (2 * i + 1) <= dy * (2 * dx - 1)) by (apply Z.mul_le_mono_nonneg_l; lia).
  subst e. nia.
Qed.

(* The heart of it: a step never overshoots. At i = dx (and j < dy) e >= dx + dy > 0, so the walk
   steps y; at j = dy (and i < dx) e <= -(dx + dy) < 0, so it steps x; a corner (e = 0) needs
   i < dx and j < dy. *)
Lemma advance_inv : forall w, inv w -> done w = false ->
  inv (advance w) /\
  measure (advance w) = measure w - (match next w with Corner => 2 | _ => 1 end).
Proof.
  intros [dx dy i j e] [Hi [Hj He]] Hd. unfold done in Hd; cbn -[Z.mul Z.add Z.sub Z.ltb Z.eqb Z.opp] in *.
  apply Bool.andb_false_iff in Hd.
  assert (Hne : i <> dx \/ j <> dy)
    by (destruct Hd as [H | H]; apply Z.eqb_neq in H; auto).
  assert (Hx : i = dx -> j < dy -> e >= dx + dy).
  { intros Heq Hlt. subst i. apply (at_right_edge dx dy j e); first [exact He | lia]. }
  assert (Hy : j = dy -> i < dx -> e <= - (dx + dy)).
  { intros Heq Hlt. subst j. apply (at_top_edge dx dy i e); first [exact He | lia]. }
  unfold advance, next, inv, measure; cbn -[Z.mul Z.add Z.sub Z.ltb Z.eqb Z.opp].
  destruct (e <? 0) eqn:H1; [apply Z.ltb_lt in H1 | apply Z.ltb_ge in H1];
    [| destruct (0 <? e) eqn:H2; [apply Z.ltb_lt in H2 | apply Z.ltb_ge in H2]]; cbn -[Z.mul Z.add Z.sub Z.ltb Z.eqb Z.opp].
  - assert (i < dx) by (destruct (Z.eq_dec i dx); [specialize (Hx e0); lia | lia]).
    repeat split; try lia; rewrite He; ring.
  - assert (j < dy) by (destruct (Z.eq_dec j dy); [specialize (Hy e0); lia | lia]).
    repeat split; try lia; rewrite He; ring.
  - assert (i < dx) by (destruct (Z.eq_dec i dx); [specialize (Hx e0); lia | lia]).
    assert (j < dy) by (destruct (Z.eq_dec j dy); [specialize (Hy e0); lia | lia]).
    repeat split; try lia; rewrite He; ring.
Qed.

Lemma measure_zero_done : forall w, inv w -> measure w <= 0 -> done w = true.
Proof.
  intros [dx dy i j e] [Hi [Hj _]] Hm. unfold measure in Hm; unfold done; simpl in *.
  apply Bool.andb_true_iff; split; apply Z.eqb_eq; lia.
Qed.

Lemma done_measure : forall w, done w = true -> measure w = 0.
Proof.
  intros w H. unfold done in H. apply Bool.andb_true_iff in H. destruct H as [H1 H2].
  apply Z.eqb_eq in H1. apply Z.eqb_eq in H2. unfold measure. lia.
Qed.

Theorem supercover_decision_variable_invariant : forall fuel w, inv w -> inv (finish fuel w).
Proof.
  induction fuel as [| f IH]; intros w Hw; simpl; [exact Hw |].
  destruct (done w) eqn:Hd; [exact Hw |]. apply IH. apply advance_inv; assumption.
Qed.

Lemma finish_done : forall fuel w, inv w -> (Z.to_nat (measure w) <= fuel)%nat ->
  done (finish fuel w) = true.
Proof.
  induction fuel as [| f IH]; intros w Hw Hf; simpl.
  - apply measure_zero_done; [exact Hw | lia].
  - destruct (done w) eqn:Hd; [exact Hd |].
    destruct (advance_inv w Hw Hd) as [Hw' Hm].
    assert (0 < measure w).
    { destruct (Z_lt_le_dec 0 (measure w)) as [H | H]; [exact H |].
      rewrite (measure_zero_done w Hw H) in Hd. discriminate. }
    apply IH; [exact Hw' |]. destruct (next w); lia.
Qed.

Lemma advance_dims : forall w, dx (advance w) = dx w /\ dy (advance w) = dy w.
Proof. intros w. unfold advance. destruct (next w); simpl; auto. Qed.

Lemma finish_dims : forall fuel w, dx (finish fuel w) = dx w /\ dy (finish fuel w) = dy w.
Proof.
  induction fuel as [| f IH]; intros w; simpl; [auto |].
  destruct (done w); [auto |]. destruct (IH (advance w)) as [A B].
  destruct (advance_dims w) as [C D]. split; congruence.
Qed.

Lemma cells_count : forall fuel w, inv w ->
  Z.of_nat (length (cells_after fuel w)) =
  measure w - measure (finish fuel w) + Z.of_nat (corners (steps fuel w)).
Proof.
  induction fuel as [| f IH]; intros w Hw; simpl; [lia |].
  destruct (done w) eqn:Hd; [simpl; lia |].
  destruct (advance_inv w Hw Hd) as [Hw' Hm].
  rewrite app_length, Nat2Z.inj_add, (IH (advance w) Hw').
  unfold corners in *. unfold step_cells. rewrite Hm.
  destruct (next w); cbn [length filter]; lia.
Qed.

Lemma last_app_nonempty : forall (l1 l2 : list (Z * Z)) d,
  l2 <> [] -> last (l1 ++ l2) d = last l2 d.
Proof.
  induction l1 as [| a l1 IH]; intros l2 d H; simpl; [reflexivity |].
  destruct (l1 ++ l2) eqn:E.
  - apply app_eq_nil in E. tauto.
  - rewrite <- E. apply IH. exact H.
Qed.

Lemma last_step : forall w d, last (step_cells w) d = (i (advance w), j (advance w)).
Proof. intros w d. unfold step_cells, advance. destruct (next w); reflexivity. Qed.

Lemma step_cells_nonempty : forall w, step_cells w <> [].
Proof. intros w. unfold step_cells. destruct (next w); discriminate. Qed.

Lemma cells_last : forall f w d, done w = false ->
  last (cells_after (S f) w) d = (i (finish (S f) w), j (finish (S f) w)).
Proof.
  induction f as [| f IH]; intros w d Hd.
  - simpl. rewrite Hd. rewrite app_nil_r. apply last_step.
  - remember (S f) as g. simpl. rewrite Hd. subst g.
    destruct (done (advance w)) eqn:Hd'.
    + simpl. rewrite Hd'. rewrite app_nil_r. apply last_step.
    + rewrite last_app_nonempty.
      * apply IH. exact Hd'.
      * simpl. rewrite Hd'. intros H. apply app_eq_nil in H.
        destruct H as [H _]. exact (step_cells_nonempty _ H).
Qed.

Lemma fuel_enough : forall dx dy, (Z.to_nat (measure (start dx dy)) <= fuel_of dx dy)%nat.
Proof.
  intros dx dy. unfold measure, start, fuel_of. cbn -[Z.add Z.sub Z.to_nat].
  replace (dx - 0 + (dy - 0)) with (dx + dy) by ring. lia.
Qed.

Theorem supercover_ends_at_b : forall dx dy, 0 <= dx -> 0 <= dy ->
  let w := finish (fuel_of dx dy) (start dx dy) in
  i w = dx /\ j w = dy /\ last (supercover dx dy) (0, 0) = (dx, dy).
Proof.
  intros dx dy Hx Hy w.
  assert (Hs := inv_start dx dy Hx Hy).
  assert (Hd : done w = true).
  { apply finish_done; [exact Hs |]. unfold measure, start, fuel_of; simpl. lia. }
  destruct (finish_dims (fuel_of dx dy) (start dx dy)) as [A B].
  unfold done in Hd. apply Bool.andb_true_iff in Hd. destruct Hd as [H1 H2].
  apply Z.eqb_eq in H1. apply Z.eqb_eq in H2. fold w in A, B. simpl in A, B.
  split; [congruence | split; [congruence |]].
  unfold supercover. destruct (done (start dx dy)) eqn:D0.
  - (* a = b: the walk emits a only *)
    unfold done, start in D0; cbn -[Z.eqb Z.add Z.sub Z.mul] in D0. apply Bool.andb_true_iff in D0.
    destruct D0 as [D1 D2]. apply Z.eqb_eq in D1. apply Z.eqb_eq in D2.
    rewrite <- D1, <- D2. reflexivity.
  - destruct (fuel_of dx dy) as [| f] eqn:F.
    + unfold fuel_of in F. unfold done, start in D0; cbn -[Z.eqb Z.add Z.sub Z.mul] in D0.
      apply Bool.andb_false_iff in D0. destruct D0 as [D | D]; apply Z.eqb_neq in D; lia.
    + change (last ((0, 0) :: cells_after (S f) (start dx dy)) (0, 0))
        with (last ([(0, 0)] ++ cells_after (S f) (start dx dy)) (0, 0)).
      rewrite last_app_nonempty.
      * rewrite cells_last by exact D0. fold w. congruence.
      * simpl. rewrite D0. intros H. apply app_eq_nil in H. destruct H as [H _].
        exact (step_cells_nonempty _ H).
Qed.

Theorem supercover_cell_count : forall dx dy, 0 <= dx -> 0 <= dy ->
  Z.of_nat (length (supercover dx dy)) =
  dx + dy + 1 + Z.of_nat (corners (steps (fuel_of dx dy) (start dx dy))).
Proof.
  intros dx dy Hx Hy. assert (Hs := inv_start dx dy Hx Hy).
  unfold supercover. simpl length. rewrite Nat2Z.inj_succ.
  rewrite (cells_count _ _ Hs).
  rewrite (done_measure _ (finish_done _ _ Hs (fuel_enough dx dy))).
  unfold measure, start. cbn -[Z.add Z.sub]. lia.
Qed.

Theorem supercover_steps_are_unit : forall w,
  (i (advance w) - i w, j (advance w) - j w) = (1, 0) \/
  (i (advance w) - i w, j (advance w) - j w) = (0, 1) \/
  (i (advance w) - i w, j (advance w) - j w) = (1, 1).
Proof.
  intros w. unfold advance. destruct (next w); simpl;
    [left | right; left | right; right]; f_equal; ring.
Qed.

Print Assumptions supercover_decision_variable_invariant.
Print Assumptions supercover_ends_at_b.
Print Assumptions supercover_cell_count.
Print Assumptions supercover_steps_are_unit.

(* ---- golden vectors: the cells of a few walks, in local coordinates (a = (0, 0), b = (dx, dy)),
   flattened x, y, x, y, ...: to (0, 0) (a = b); (3, 5) and (5, 3) (one corner each); (4, 2) (no
   corner: 2 and 1 are not both odd); (3, 3) (a corner at every step); (3, 1) (one corner);
   (0, 4) and (6, 0) (axis-parallel); (7, 3) (one corner). *)
Definition flat (l : list (Z * Z)) : list Z := flat_map (fun c => [fst c; snd c]) l.
Compute flat (supercover 0 0).
Compute flat (supercover 3 5).
Compute flat (supercover 5 3).
Compute flat (supercover 4 2).
Compute flat (supercover 3 3).
Compute flat (supercover 3 1).
Compute flat (supercover 0 4).
Compute flat (supercover 6 0).
Compute flat (supercover 7 3).
