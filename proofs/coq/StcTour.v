(* Spanning Tree Coverage (paper 002, Gabriely & Rimon): the tour that circumnavigates a spanning
   tree of cells through their sub-cells visits every sub-cell exactly once and is closed.

   Model, in the conventions of algorithms/stc/include/antkit/stc/subcell.hpp (x to the right,
   y downward):
     directions  E = 0, N = 1 (y - 1), W = 2, S = 3, counter-clockwise; `succ` is d + 1 mod 4;
     quadrants   named by the same four values: E = SE (1,1), N = NE (1,0), W = NW (0,0),
                 S = SW (0,1), so that sub-cell q has its exterior edges in directions q and q - 1;
     sub-cells   cell (x, y) holds (2x + ox, 2y + oy) for the quadrant offsets above.
   A spanning tree is a rooted tree whose nodes carry one child slot per direction: the child in
   slot d is the 4-neighbour `step c d` of the node's cell c. Cell coordinates are therefore not
   stored but computed from the root's cell, so "every child is a 4-neighbour of its parent" holds
   by construction; "the cells are distinct" is the hypothesis (NoDup of the cell list). The slot of
   a non-root node in the direction of its parent is the parent edge, not a child: neither `tour`
   nor `cells` reads it (the model's choice; the shipped tree cannot have a child there either).

   The tour, as SpanningTree::advance walks it (offline.hpp): entering a cell whose parent lies in
   direction p, the robot arrives in sub-cell p + 1; for each side d = p + 1, p + 2, p + 3 (counter-
   clockwise from the parent) it either descends into the child there (leaving from sub-cell d,
   coming back into sub-cell d + 1) or walks from sub-cell d to sub-cell d + 1; it then stands in
   sub-cell p + 4 = p and crosses back to the parent. The root, started in quadrant q0, has the
   virtual parent direction p = q0 - 1 and also scans side p; the tour stops before re-entering the
   start sub-cell.

   Proved (named like the invariants of tests/support/stc_checkers.hpp, which
   tests/stc/test_stc_properties.cpp and tests/stc/test_stc_exhaustive.cpp check on the code):
     invariant1_coverage_subtree  a subtree's tour is a permutation of the sub-cells of its cells;
     invariant1_coverage          the root tour lists every sub-cell of the spanned cell set
                                  exactly once (Permutation and NoDup), given distinct cells;
     invariant2_moves_subtree     consecutive sub-cells of a subtree's tour are 4-adjacent, it
                                  starts next to where the robot stood and ends in sub-cell p;
     invariant2_moves             the same for the root tour;
     invariant3_return            the last sub-cell of the root tour is 4-adjacent to the first;
     invariant4_length            the root tour has 4 x (cells) positions;
     stc_tour_theorem             all of the above for any spanning tree of any cell set.
   Golden vectors (proofs/golden/StcTour.out): the tours of an L, a T, a plus and a 2 x 3 block;
   tests/proofs/test_stc_golden.cpp runs the shipped offline STC on the same cells from the same
   start sub-cell and requires the same tour (tested correspondence between model and code). The
   same test transcribes `tour` / `stc_tour` over the shipped tree's child bits and requires the
   shipped tour to equal it on every cell map of up to 12 cells from every start sub-cell.
   Not modelled: building the tree (the hypothesis is "any spanning tree"; every 4-connected set
   has one), the map, and the C++ integer arithmetic (coordinates here are unbounded Z). *)

From Coq Require Import ZArith List Lia Permutation.
Import ListNotations.
Open Scope Z_scope.

Inductive dir := E | N | W | S.

Definition succ (d : dir) : dir := match d with E => N | N => W | W => S | S => E end.
Definition opp (d : dir) : dir := succ (succ d).
Definition pred (d : dir) : dir := succ (succ (succ d)).

Lemma succ4 : forall d, succ (succ (succ (succ d))) = d.
Proof. destruct d; reflexivity. Qed.

Definition cell := (Z * Z)%type.

(* kernel::kNeighbours4: E (1,0), N (0,-1), W (-1,0), S (0,1). *)
Definition step (c : cell) (d : dir) : cell :=
  let '(x, y) := c in
  match d with E => (x + 1, y) | N => (x, y - 1) | W => (x - 1, y) | S => (x, y + 1) end.

(* stc::kQuadrantOffset: SE (1,1), NE (1,0), NW (0,0), SW (0,1). *)
Definition sub (c : cell) (q : dir) : cell :=
  let '(x, y) := c in
  match q with
  | E => (2 * x + 1, 2 * y + 1) | N => (2 * x + 1, 2 * y)
  | W => (2 * x, 2 * y) | S => (2 * x, 2 * y + 1)
  end.

Definition subs (c : cell) : list cell := [sub c E; sub c N; sub c W; sub c S].

Definition adj (a b : cell) : Prop :=
  Z.abs (fst a - fst b) + Z.abs (snd a - snd b) = 1.

Inductive tree := Nil | Node (e n w s : tree).

(* The child slot in direction d (a notation, so that the guard checker sees a subterm). *)
Notation sel d e n w s := (match d with E => e | N => n | W => w | S => s end).

(* The tour of the subtree t whose root cell c has its parent in direction p. *)
Fixpoint tour (c : cell) (p : dir) (t : tree) : list cell :=
  match t with
  | Nil => []
  | Node e n w s =>
      let d1 := succ p in let d2 := succ d1 in let d3 := succ d2 in
      sub c d1
        :: (tour (step c d1) (opp d1) (sel d1 e n w s) ++ [sub c d2])
        ++ (tour (step c d2) (opp d2) (sel d2 e n w s) ++ [sub c d3])
        ++ (tour (step c d3) (opp d3) (sel d3 e n w s) ++ [sub c p])
  end.

(* The cells of that subtree, in depth-first order (the same scan). *)
Fixpoint cells (c : cell) (p : dir) (t : tree) : list cell :=
  match t with
  | Nil => []
  | Node e n w s =>
      let d1 := succ p in let d2 := succ d1 in let d3 := succ d2 in
      c :: cells (step c d1) (opp d1) (sel d1 e n w s)
        ++ cells (step c d2) (opp d2) (sel d2 e n w s)
        ++ cells (step c d3) (opp d3) (sel d3 e n w s)
  end.

Definition kid (t : tree) (d : dir) : tree :=
  match t with Nil => Nil | Node e n w s => sel d e n w s end.

(* The whole tour from the start sub-cell (root cell c, quadrant q0). *)
Definition stc_tour (c : cell) (q0 : dir) (t : tree) : list cell :=
  let p := pred q0 in tour c p t ++ tour (step c p) (opp p) (kid t p).

Definition tree_cells (c : cell) (q0 : dir) (t : tree) : list cell :=
  let p := pred q0 in cells c p t ++ cells (step c p) (opp p) (kid t p).

(* ---- Geometry of the sub-cells ---------------------------------------------------------------- *)

(* Unfolds the geometry without unfolding Z's multiplication (which lia needs to see). *)
Ltac geo := cbv beta iota zeta delta [adj sub step opp succ pred fst snd] in *.

(* Walking around a cell: sub-cell d to sub-cell d + 1. *)
Lemma adj_around : forall c d, adj (sub c d) (sub c (succ d)).
Proof. intros [x y] d; destruct d; geo; lia. Qed.

(* Descending into the neighbour in direction d: from sub-cell d into its sub-cell d + 3, which
   is succ (opp d), the first sub-cell of that neighbour's tour. *)
Lemma adj_descend : forall c d, adj (sub c d) (sub (step c d) (succ (opp d))).
Proof. intros [x y] d; destruct d; geo; lia. Qed.

(* Coming back: from the neighbour's last sub-cell opp d into sub-cell d + 1. *)
Lemma adj_return : forall c d, adj (sub (step c d) (opp d)) (sub c (succ d)).
Proof. intros [x y] d; destruct d; geo; lia. Qed.

Lemma sub_inj : forall c c' q q', sub c q = sub c' q' -> c = c' /\ q = q'.
Proof.
  intros [x y] [x' y'] q q' H; destruct q, q'; geo;
    pose proof (f_equal fst H) as Hx; pose proof (f_equal snd H) as Hy; cbn [fst snd] in Hx, Hy;
    (split; [f_equal; lia | reflexivity]) || (exfalso; lia).
Qed.

(* ---- Walks ---------------------------------------------------------------------------------- *)

(* linked x l: from x, each next position of l is 4-adjacent to the one before. *)
Fixpoint linked (x : cell) (l : list cell) : Prop :=
  match l with [] => True | y :: r => adj x y /\ linked y r end.

(* The default of `last` does not matter for a non-empty list. *)
Lemma last_cons_default : forall (l : list cell) c x y, last (c :: l) x = last (c :: l) y.
Proof.
  induction l as [|a l IH]; intros c x y; [reflexivity|].
  change (last (a :: l) x = last (a :: l) y). apply IH.
Qed.

Lemma linked_app : forall l1 l2 x,
  linked x l1 -> linked (last l1 x) l2 -> linked x (l1 ++ l2).
Proof.
  induction l1 as [|a l1 IH]; intros l2 x H1 H2; simpl in *; auto.
  destruct H1 as [Ha H1]; split; auto.
  apply IH; auto. destruct l1; auto.
  rewrite (last_cons_default _ _ a x). exact H2.
Qed.

Lemma last_app_cons : forall (l1 l2 : list cell) a x,
  last (l1 ++ a :: l2) x = last (a :: l2) x.
Proof.
  induction l1 as [|b l1 IH]; intros l2 a x; simpl; auto.
  rewrite IH. destruct l1; simpl; auto.
Qed.

(* ---- Invariant 2 (moves) on subtrees -------------------------------------------------------- *)

Definition moves_ok (c : cell) (p : dir) (t : tree) : Prop :=
  match t with
  | Nil => True
  | Node _ _ _ _ =>
      forall x, adj x (sub c (succ p)) ->
      linked x (tour c p t) /\ last (tour c p t) x = sub c p
  end.

(* One side d of a cell: the child's tour (if any), then sub-cell d + 1. *)
Lemma side_moves : forall c d k,
  moves_ok (step c d) (opp d) k ->
  linked (sub c d) (tour (step c d) (opp d) k ++ [sub c (succ d)]) /\
  last (tour (step c d) (opp d) k ++ [sub c (succ d)]) (sub c d) = sub c (succ d).
Proof.
  intros c d k Hk. split.
  - destruct k as [|e n w s].
    + simpl. split; auto. apply adj_around.
    + destruct (Hk (sub c d) (adj_descend c d)) as [Hl Hlast].
      apply linked_app; auto. rewrite Hlast. simpl. split; auto. apply adj_return.
  - rewrite last_app_cons. reflexivity.
Qed.

Lemma invariant2_moves_subtree : forall t c p, moves_ok c p t.
Proof.
  induction t as [|e IHe n IHn w IHw s IHs]; intros c p; [exact I|].
  assert (Hk : forall d c' p', moves_ok c' p' (sel d e n w s)) by (destruct d; auto).
  unfold moves_ok. intros x Hx. cbn [tour].
  destruct (side_moves c (succ p) (sel (succ p) e n w s) (Hk _ _ _)) as [L1 E1].
  destruct (side_moves c (succ (succ p)) (sel (succ (succ p)) e n w s) (Hk _ _ _)) as [L2 E2].
  destruct (side_moves c (succ (succ (succ p))) (sel (succ (succ (succ p))) e n w s) (Hk _ _ _))
    as [L3 E3].
  rewrite succ4 in L3, E3.
  split.
  - cbn [linked]. split; auto.
    apply linked_app; auto. rewrite E1.
    apply linked_app; auto. rewrite E2. auto.
  - rewrite app_comm_cons, !app_assoc, last_last. reflexivity.
Qed.

(* ---- Invariant 1 (coverage) on subtrees ----------------------------------------------------- *)

Lemma subs_perm : forall c p,
  Permutation [sub c (succ p); sub c (succ (succ p)); sub c (succ (succ (succ p))); sub c p]
              (subs c).
Proof.
  intros c p; unfold subs; destruct p; simpl.
  - (* N W S E *) apply Permutation_sym, (Permutation_cons_append [_;_;_]).
  - (* W S E N *) change [sub c W; sub c S; sub c E; sub c N] with ([sub c W; sub c S] ++ [sub c E; sub c N]).
    apply Permutation_app_comm.
  - (* S E N W *) change [sub c S; sub c E; sub c N; sub c W] with ([sub c S] ++ [sub c E; sub c N; sub c W]).
    apply Permutation_app_comm.
  - apply Permutation_refl.
Qed.

Lemma shuffle4 : forall (a b c d : cell) T1 T2 T3,
  Permutation (a :: (T1 ++ [b]) ++ (T2 ++ [c]) ++ (T3 ++ [d]))
              ([a; b; c; d] ++ T1 ++ T2 ++ T3).
Proof.
  intros. simpl. apply perm_skip.
  rewrite <- !app_assoc. simpl.
  rewrite <- Permutation_middle. apply perm_skip.
  rewrite app_assoc. rewrite <- Permutation_middle. apply perm_skip.
  rewrite app_assoc. rewrite <- Permutation_cons_append. apply perm_skip.
  rewrite app_assoc. apply Permutation_refl.
Qed.

Lemma invariant1_coverage_subtree : forall t c p,
  Permutation (tour c p t) (flat_map subs (cells c p t)).
Proof.
  induction t as [|e IHe n IHn w IHw s IHs]; intros c p; [apply perm_nil|].
  cbn [tour cells flat_map].
  assert (Hk : forall d c' p', Permutation (tour c' p' (sel d e n w s))
                                          (flat_map subs (cells c' p' (sel d e n w s))))
    by (destruct d; auto).
  rewrite shuffle4. rewrite !flat_map_app.
  apply Permutation_app.
  - apply subs_perm.
  - apply Permutation_app; [apply Hk|]. apply Permutation_app; apply Hk.
Qed.

(* Distinct cells have distinct sub-cells. *)
Lemma NoDup_app_disjoint : forall (l1 l2 : list cell),
  NoDup l1 -> NoDup l2 -> (forall x, In x l1 -> ~ In x l2) -> NoDup (l1 ++ l2).
Proof.
  induction l1 as [|a l1 IH]; intros l2 H1 H2 Hd; simpl; auto.
  inversion H1; subst. constructor.
  - rewrite in_app_iff. intros [H|H]; auto. apply (Hd a); simpl; auto.
  - apply IH; auto. intros x Hx. apply Hd; simpl; auto.
Qed.

Lemma NoDup_subs : forall l, NoDup l -> NoDup (flat_map subs l).
Proof.
  induction l as [|c l IH]; intros H; [constructor|].
  cbn [flat_map]. inversion H; subst.
  apply NoDup_app_disjoint; auto.
  - unfold subs.
    repeat constructor; simpl; intros Hin;
      repeat (destruct Hin as [Hin|Hin]; [apply sub_inj in Hin; destruct Hin; discriminate|]);
      exact Hin.
  - intros x Hx Hy. apply in_flat_map in Hy. destruct Hy as [c' [Hc' Hy]].
    unfold subs in Hx, Hy.
    simpl in Hx, Hy.
    destruct Hx as [Hx|[Hx|[Hx|[Hx|[]]]]]; subst x;
      destruct Hy as [Hy|[Hy|[Hy|[Hy|[]]]]]; apply sub_inj in Hy; destruct Hy as [Hy _];
      subst c'; contradiction.
Qed.

(* ---- The root's tour ------------------------------------------------------------------------ *)

Lemma invariant1_coverage : forall c q0 t,
  Permutation (stc_tour c q0 t) (flat_map subs (tree_cells c q0 t)) /\
  (NoDup (tree_cells c q0 t) -> NoDup (stc_tour c q0 t)).
Proof.
  intros c q0 t.
  assert (P : Permutation (stc_tour c q0 t) (flat_map subs (tree_cells c q0 t))).
  { unfold stc_tour, tree_cells. rewrite flat_map_app.
    apply Permutation_app; apply invariant1_coverage_subtree. }
  split; auto.
  intros H. apply (Permutation_NoDup (Permutation_sym P)). apply NoDup_subs; auto.
Qed.

Lemma invariant4_length : forall c q0 t,
  length (stc_tour c q0 t) = (4 * length (tree_cells c q0 t))%nat.
Proof.
  intros c q0 t. rewrite (Permutation_length (proj1 (invariant1_coverage c q0 t))).
  induction (tree_cells c q0 t) as [|x l IH]; simpl; auto.
  rewrite IH. lia.
Qed.

Lemma last_cons : forall (R : list cell) a y, last (a :: R) y = last R a.
Proof.
  intros [|b R] a y; [reflexivity|].
  change (last (b :: R) y = last (b :: R) a). apply last_cons_default.
Qed.

(* The part of the root's tour that is an ordinary cell tour (with p the virtual parent): it
   starts in sub-cell p + 1, moves between 4-adjacent sub-cells and ends in sub-cell p. *)
Lemma root_part : forall c p e n w s, exists R : list cell,
  tour c p (Node e n w s) = sub c (succ p) :: R /\
  linked (sub c (succ p)) R /\ last R (sub c (succ p)) = sub c p.
Proof.
  intros c p e n w s.
  pose proof (invariant2_moves_subtree (Node e n w s) c p) as M.
  specialize (M (sub c p) (adj_around c p)).
  cbn [tour] in *. eexists. split; [reflexivity|].
  destruct M as [[_ L] Lst]. rewrite last_cons in Lst. split; assumption.
Qed.

Lemma pred_succ : forall q0, q0 = succ (pred q0).
Proof. destruct q0; reflexivity. Qed.

(* The root tour of a non-empty tree: the start sub-cell, then positions each 4-adjacent to the
   one before. *)
Lemma invariant2_moves : forall c q0 t, t <> Nil ->
  exists rest, stc_tour c q0 t = sub c q0 :: rest /\ linked (sub c q0) rest.
Proof.
  intros c q0 t Ht. destruct t as [|e n w s]; [congruence|].
  unfold stc_tour. pose proof (pred_succ q0) as Hq. set (p := pred q0) in *.
  destruct (root_part c p e n w s) as [R [HT [L Lst]]].
  rewrite HT. rewrite <- Hq in *.
  exists (R ++ tour (step c p) (opp p) (kid (Node e n w s) p)). split; [reflexivity|].
  apply linked_app; auto. rewrite Lst.
  pose proof (invariant2_moves_subtree (kid (Node e n w s) p) (step c p) (opp p)) as K.
  destruct (kid (Node e n w s) p); [exact I|]. apply K. apply adj_descend.
Qed.

(* ... and the last position is 4-adjacent to the start: the tour is closed. *)
Lemma invariant3_return : forall c q0 t, t <> Nil ->
  adj (last (stc_tour c q0 t) (sub c q0)) (sub c q0).
Proof.
  intros c q0 t Ht. destruct t as [|e n w s]; [congruence|].
  unfold stc_tour. pose proof (pred_succ q0) as Hq. set (p := pred q0) in *.
  destruct (root_part c p e n w s) as [R [HT [L Lst]]].
  rewrite HT. rewrite <- Hq in *.
  pose proof (invariant2_moves_subtree (kid (Node e n w s) p) (step c p) (opp p)) as K.
  destruct (kid (Node e n w s) p) as [|e' n' w' s'].
  - cbn [tour]. rewrite app_nil_r, last_cons, Lst, Hq. apply adj_around.
  - specialize (K (sub c p) (adj_descend c p)). destruct K as [_ KLst].
    revert KLst. cbn [tour]. intros KLst.
    rewrite last_app_cons.
    rewrite (last_cons_default _ _ _ (sub c p)), KLst, Hq. apply adj_return.
Qed.

(* The theorem: for any set X of cells (distinct, listed) and any spanning tree of it rooted at the
   start cell c (its cells are exactly X), the tour from the start sub-cell (c, q0) lists every
   sub-cell of every cell of X exactly once (invariants 1 and 4), starts at the start sub-cell,
   moves between 4-adjacent sub-cells (invariant 2) and ends 4-adjacent to the start (invariant 3).
   X is 4-connected because it has a spanning tree; every 4-connected set has one. *)
Theorem stc_tour_theorem : forall (X : list cell) c q0 t,
  NoDup X -> Permutation (tree_cells c q0 t) X -> t <> Nil ->
  Permutation (stc_tour c q0 t) (flat_map subs X) /\
  NoDup (stc_tour c q0 t) /\
  length (stc_tour c q0 t) = (4 * length X)%nat /\
  (exists rest, stc_tour c q0 t = sub c q0 :: rest /\ linked (sub c q0) rest) /\
  adj (last (stc_tour c q0 t) (sub c q0)) (sub c q0).
Proof.
  intros X c q0 t HX HP Ht.
  destruct (invariant1_coverage c q0 t) as [P ND].
  assert (HN : NoDup (tree_cells c q0 t)) by (apply (Permutation_NoDup (Permutation_sym HP)); auto).
  split; [|split; [|split; [|split]]].
  - rewrite P. apply Permutation_flat_map. exact HP.
  - apply ND. exact HN.
  - rewrite invariant4_length. rewrite (Permutation_length HP). reflexivity.
  - apply invariant2_moves; auto.
  - apply invariant3_return; auto.
Qed.

(* ---- Golden vectors ------------------------------------------------------------------------- *)
(* Each tree below is the depth-first tree the shipped SpanningTree builds (offline.hpp: the root
   scans q0, q0 + 1, q0 + 2, q0 + 3, every other cell scans counter-clockwise starting after its
   parent); for the L, the T and the plus it is the only spanning tree. The C++ test rebuilds each
   cell set from the golden tour (a sub-cell (x, y) lies in cell (x / 2, y / 2)) and starts from
   its first sub-cell, so an error in one of these trees shows up there as a different tour. *)
(* l_shape: cells [(0, 0), (0, 1), (0, 2), (1, 2)], start cell (0, 0), quadrant S *)
Definition l_shape : tree :=
  (Node Nil Nil Nil (Node Nil Nil Nil (Node (Node Nil Nil Nil Nil) Nil Nil Nil))).
(* t_shape: cells [(0, 0), (1, 0), (2, 0), (1, 1)], start cell (1, 1), quadrant N *)
Definition t_shape : tree :=
  (Node Nil (Node (Node Nil Nil Nil Nil) Nil (Node Nil Nil Nil Nil) Nil) Nil Nil).
(* plus_shape: cells [(1, 0), (0, 1), (1, 1), (2, 1), (1, 2)], start cell (1, 1), quadrant E *)
Definition plus_shape : tree :=
  (Node (Node Nil Nil Nil Nil) (Node Nil Nil Nil Nil) (Node Nil Nil Nil Nil) (Node Nil Nil Nil Nil)).
(* block_2x3: cells [(0, 0), (1, 0), (0, 1), (1, 1), (0, 2), (1, 2)], start cell (0, 0), quadrant W *)
Definition block_2x3 : tree :=
  (Node Nil Nil Nil (Node Nil Nil Nil (Node (Node Nil (Node Nil (Node Nil Nil Nil Nil) Nil Nil) Nil Nil) Nil Nil Nil))).
Compute stc_tour (0, 0) S l_shape.
Compute stc_tour (1, 1) N t_shape.
Compute stc_tour (1, 1) E plus_shape.
Compute stc_tour (0, 0) W block_2x3.

Print Assumptions stc_tour_theorem.
