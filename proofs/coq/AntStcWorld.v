(* Ant-like STC (paper 002) in its marks world: the robot that runs the shipped decision function
   (AntDecide.v's `decide`, unchanged: the line-for-line transcription of ant.hpp `ant_decide` that
   the C++ tie test checks on its whole domain) on the floor of floor.hpp covers EVERY map:
   from any start sub-cell it walks the spanning-tree tour of StcTour.v around a depth-first tree of
   the start's 4-connected component, visiting each of its sub-cells exactly once, and stops one
   move before re-entering the start sub-cell.

   Model (conventions of StcTour.v / subcell.hpp: E = 0, N = 1 (y - 1), W = 2, S = 3; quadrants
   0 = SE, 1 = NE, 2 = NW, 3 = SW; `sub`, `step` from StcTour.v):
     map         a list X of free cells (duplicates allowed, any Z coordinates); a cell is free when
                 it is in X (`memb`, decided by Z.eqb). The sub-cell map is taken at cell level: a
                 sub-cell is free iff its cell is (the shipped Floor refuses a move into a sub-cell
                 that is not free; here, into a sub-cell whose cell is not in X).
     position    a sub-cell as Z x Z sub-cell coordinates, moved by `step`; its cell and quadrant
                 are `cell_of` (x >> 1, y >> 1 = Z.div by 2) and `quadrant_of` (the parities), as
                 subcell.hpp computes them.
     state       position, the controller's quadrant q and done flag (AntStc's two bytes), and the
                 marks: cell -> dir -> bool (bit q of the cell's mark byte).
     observation Floor::observe_marks without noise: free mask of the four neighbour cells, the
                 marks of the robot's cell, and each neighbour's marks (none when not free).
     one step    `run`: decide; Stop ends the run (Stopped); Go m q' marks the sub-cell the robot
                 leaves (bit quadrant_of(position) of its cell: every Go of ant_decide marks), moves
                 the position one sub-cell in direction m and sets q := q'; a move into a sub-cell of
                 a cell not in X is refused (Refused), as Floor::apply refuses it. Fuel counts
                 decisions, like drive_tour's max_moves; the trace lists (position, q) after each
                 move, `ant_run` puts the start (sub c0 q0, q0) first.
   The exploration the marks drive is modelled separately as a relation (`dfs`, `side`, `root`):
   entering a cell c from its parent in direction p, the sides p + 1, p + 2, p + 3 are scanned in
   order, descending into a neighbour when it is free and not yet visited at that moment; the root
   (virtual parent p = q0 - 1) also scans side p last. Its tree is built with `mkt`.

   Proved:
     dv1 .. dv4          the decision at each moment of a pass through a cell (finite case analyses
                         over `decide_view`): parent_dir reads the parent, first_new the next
                         unvisited free side; at the end, return to the parent unless its entry
                         sub-cell is marked;
     explore_perm, explore_nodup, explore_subX, side_closes, dfs_closes, explore_closed,
     explore_reach       the explored cells are distinct, free, closed under free neighbours and
                         reachable;
     dfs_exists, side_exists, root_exists   the exploration exists for every finite map;
     simulation          (the heart) from the state where the robot has just entered cell c with
                         marks satisfying the invariant (unvisited cells unmarked, visited cells
                         marked), the world's steps enter exactly the positions of `tour c p t`, end
                         in sub-cell p with c's other three sub-cells marked, change no marks of
                         cells visited before (so the parent's entry sub-cell stays unmarked: the
                         return is open) and leave every newly visited cell fully marked; for a
                         side, the same including the crossing and the return;
     root_run            from the start state the run enters exactly `stc_tour c0 q0 t` and then
                         decides Stop (the start sub-cell is marked, which closes the tour);
     ant_run_is_stc_tour for every map X and start (c0 in X, any q0) there is a tree t whose cells
                         are distinct and are exactly the component of c0 (`reach`), and every run
                         with fuel >= 4 |cells| returns the trace of stc_tour c0 q0 t and Stopped;
     ant_stc_covers_every_map   the main theorem, with stc_tour_theorem (reused): for every
                         map X (no NoDup needed) and start c0 in X, q0, the component K of c0 is
                         distinct, free and closed, and every run with fuel >= 4 |K| (drive_tour's
                         max_moves >= 4 |K|) stops (Stopped) after exactly 4 |K| - 1 moves (4 |K|
                         positions); its positions are stc_tour c0 q0 t for a tree t spanning K, a
                         permutation of the sub-cells of K (each exactly once, NoDup), start at the
                         start sub-cell, consecutive positions are 4-adjacent, the last is
                         4-adjacent to the first, every position lies in a cell of K (so never in a
                         cell that is not free, nor in another component), and after every move the
                         controller's q is the quadrant of its position.
   ant-edge (AntEdgeStc: the same decide over covered_from_edges of the lit edges), in its own
   world `erun`: Floor::observe_edges (every neighbour's 12 edges are read, free or not) and
   Floor::apply with Marker::Edge (light_edge of the edge behind the robot, opposite the move):
     decide_ext          decide reads a neighbour's marks only when the neighbour is free;
     decide_shape        every Go of decide crosses side q or walks on to q + 1;
     covered_light       leaving sub-cell e by such a move lights exactly what makes
                         covered_from_edges report e (a cross box or a turn box of its own cell;
                         the edge it lights in a neighbour is one of bits 8..11, never read);
     erun_run            so from related states (same position and q, q the position's quadrant,
                         covered_from_edges = the marks) the edge world runs exactly as the marks
                         world, for any map and any fuel;
     ant_edge_run_is_ant_run   ant_edge_run X c0 q0 fuel = ant_run X c0 q0 fuel, always;
     ant_edge_stc_covers_every_map   hence the main theorem for ant-edge, word for word.
   Golden vectors (proofs/golden/AntStcWorld.out): the positions of the run (sub-cell coordinates,
   start first) and its outcome on an L, a 2 x 3 block, a 3 x 3 ring (a hole in the middle) and a
   map of two components, for ant then for ant-edge (the same vectors, as proved); maps and starts
   are in the comments before each Compute.
   Not modelled: marker noise (ppm = 0), C++ integer bounds (Z here), the map's bounding box (the
   plane of cells is unbounded: Floor keeps marks and edges only for in-bounds cells, and lights
   an edge of an out-of-bounds cell nowhere; here such a cell, never free, may get a lit edge that
   nothing reads), a free sub-cell in a cell that is not free (treated as blocked, see above), the
   entered/covered counters and the trace hash. *)

From Coq Require Import ZArith Bool List Lia Permutation.
Import ListNotations.
Require Import StcTour.
Require Import AntDecide.
Open Scope Z_scope.

(* ---- cells, sets of cells, marks ---- *)
Definition cell_eqb (a b : cell) : bool := Z.eqb (fst a) (fst b) && Z.eqb (snd a) (snd b).

Lemma cell_eqb_eq : forall a b, cell_eqb a b = true <-> a = b.
Proof.
  intros [x y] [x' y']; unfold cell_eqb; simpl. rewrite andb_true_iff, !Z.eqb_eq.
  split; [intros [-> ->]; reflexivity | intros H; inversion H; auto].
Qed.

Lemma cell_eqb_refl : forall a, cell_eqb a a = true.
Proof. intros a; apply cell_eqb_eq; reflexivity. Qed.

Lemma cell_eqb_neq : forall a b, a <> b -> cell_eqb a b = false.
Proof. intros a b H. destruct (cell_eqb a b) eqn:E; auto. apply cell_eqb_eq in E; congruence. Qed.

Definition cell_eq_dec (a b : cell) : {a = b} + {a <> b}.
Proof. destruct (cell_eqb a b) eqn:E; [left; apply cell_eqb_eq; exact E|right].
  intros H; apply cell_eqb_eq in H; congruence. Defined.

(* membership in a list of cells *)
Definition memb (x : cell) (l : list cell) : bool := existsb (cell_eqb x) l.

Lemma memb_In : forall x l, memb x l = true <-> In x l.
Proof.
  intros x l; unfold memb; rewrite existsb_exists; split.
  - intros [y [Hy E]]. apply cell_eqb_eq in E; subst; auto.
  - intros H; exists x; split; auto; apply cell_eqb_refl.
Qed.

Lemma memb_notIn : forall x l, memb x l = false <-> ~ In x l.
Proof.
  intros x l; rewrite <- memb_In; destruct (memb x l); split; intros H; auto; try congruence.
Qed.

(* ---- sub-cell coordinates, as subcell.hpp: cell_of s = (s.x >> 1, s.y >> 1),
        quadrant_of from the parities ---- *)
Definition cell_of (s : cell) : cell := (Z.div (fst s) 2, Z.div (snd s) 2).
Definition quadrant_of (s : cell) : dir :=
  match Z.odd (fst s), Z.odd (snd s) with
  | true, true => E | true, false => N | false, false => W | false, true => S
  end.

Definition marks := cell -> dir -> bool.
Definition no_marks : marks := fun _ _ => false.
(* apply(Go d): bit quadrant_of(position) of the robot's cell is set *)
Definition mark (M : marks) (c : cell) (q : dir) : marks :=
  fun x e => M x e || (cell_eqb x c && dir_eqb e q).

(* ---- the world (floor.hpp, Floor::observe_marks / apply, drive_tour) ---- *)
Record state := St { pos : cell; qd : dir; dn : bool; mks : marks }.

(* Observation in cell c: free mask, neighbour marks (none when not free). *)
Definition fr (X : list cell) (c : cell) : mask := fun d => memb (step c d) X.
Definition nbm (X : list cell) (M : marks) (c : cell) : dir -> mask :=
  fun d => if memb (step c d) X then M (step c d) else fun _ => false.

Inductive outcome := Stopped | Refused | OutOfFuel.

Definition prepend {A} (l : list A) (r : list A * outcome) : list A * outcome := (l ++ fst r, snd r).

(* One decision per unit of fuel. The trace lists (position, controller quadrant) after each move. *)
Fixpoint run (X : list cell) (fuel : nat) (st : state) : list (cell * dir) * outcome :=
  match fuel with
  | O => ([], OutOfFuel)
  | Datatypes.S n =>
      let c := cell_of (pos st) in
      match decide (dn st) (qd st) (fr X c) (mks st c) (nbm X (mks st) c) with
      | Stop => ([], Stopped)
      | Go m q' =>
          let target := step (pos st) m in
          if memb (cell_of target) X then
            prepend [(target, q')]
              (run X n (St target q' (dn st) (mark (mks st) c (quadrant_of (pos st)))))
          else ([], Refused)
      end
  end.

Definition start (c0 : cell) (q0 : dir) : state := St (sub c0 q0) q0 false no_marks.

Definition ant_run (X : list cell) (c0 : cell) (q0 : dir) (fuel : nat) : list (cell * dir) * outcome :=
  prepend [(sub c0 q0, q0)] (run X fuel (start c0 q0)).

Definition positions (r : list (cell * dir) * outcome) : list cell * outcome := (map fst (fst r), snd r).

Definition withq (s : cell) : cell * dir := (s, quadrant_of s).

(* ---- geometry ---- *)
Lemma cell_of_sub : forall c q, cell_of (sub c q) = c.
Proof.
  intros [x y] q; destruct q; unfold cell_of; cbn [sub fst snd]; f_equal;
    Z.div_mod_to_equations; lia.
Qed.

Lemma quad_sub : forall c q, quadrant_of (sub c q) = q.
Proof.
  intros [x y] q; destruct q; unfold quadrant_of; cbn [sub fst snd];
    rewrite ?Z.odd_add, ?Z.odd_mul; reflexivity.
Qed.

Lemma walk_step : forall c d, step (sub c d) (succ d) = sub c (succ d).
Proof. intros [x y] d; destruct d; geo; f_equal; lia. Qed.

Lemma cross_step : forall c d, step (sub c d) d = sub (step c d) (pred d).
Proof. intros [x y] d; destruct d; geo; f_equal; lia. Qed.

Lemma step_opp : forall c d, step (step c d) (opp d) = c.
Proof. intros [x y] d; destruct d; geo; f_equal; lia. Qed.

Lemma step_neq : forall c d, step c d <> c.
Proof. intros [x y] d H; destruct d; geo; inversion H; lia. Qed.

Lemma dir_eqb_refl : forall d, dir_eqb d d = true. Proof. destruct d; reflexivity. Qed.
Lemma succ_pred : forall d, succ (pred d) = d. Proof. destruct d; reflexivity. Qed.
Lemma pred_opp : forall d, pred (opp d) = succ d. Proof. destruct d; reflexivity. Qed.
Lemma succ_opp : forall d, succ (opp d) = pred d. Proof. destruct d; reflexivity. Qed.
Lemma quad_withq : forall c q, withq (sub c q) = (sub c q, q).
Proof. intros; unfold withq; rewrite quad_sub; reflexivity. Qed.

(* ---- runs: goes X s l s' says the world, from s, enters the positions l (with the controller's
   quadrant) and is then in state s' ---- *)
Definition goes (X : list cell) (s1 : state) (l : list (cell * dir)) (s2 : state) : Prop :=
  forall n, run X (length l + n) s1 = prepend l (run X n s2).

Lemma prepend_app : forall {A} (l1 l2 : list A) r, prepend l1 (prepend l2 r) = prepend (l1 ++ l2) r.
Proof. intros; unfold prepend; simpl; rewrite app_assoc; reflexivity. Qed.

Lemma goes_trans : forall X s1 l1 s2 l2 s3,
  goes X s1 l1 s2 -> goes X s2 l2 s3 -> goes X s1 (l1 ++ l2) s3.
Proof.
  intros X s1 l1 s2 l2 s3 H1 H2 n. rewrite app_length, <- Nat.add_assoc, H1, H2.
  apply prepend_app.
Qed.

Lemma goes_go : forall X c d M m q',
  decide false d (fr X c) (M c) (nbm X M c) = Go m q' ->
  memb (cell_of (step (sub c d) m)) X = true ->
  goes X (St (sub c d) d false M) [(step (sub c d) m, q')]
         (St (step (sub c d) m) q' false (mark M c d)).
Proof.
  intros X c d M m q' H H0 n. change (length [(step (sub c d) m, q')] + n)%nat with (Datatypes.S n).
  cbn [run pos qd dn mks]. rewrite cell_of_sub, H, H0, quad_sub. reflexivity.
Qed.

Lemma run_stop : forall X c d M n,
  decide false d (fr X c) (M c) (nbm X M c) = Stop ->
  run X (Datatypes.S n) (St (sub c d) d false M) = ([], Stopped).
Proof. intros X c d M n H. cbn [run pos qd dn mks]. rewrite cell_of_sub, H. reflexivity. Qed.

(* ---- the decision, at each moment of a pass through a cell (finite case analyses) ---- *)
Definition isn (X : list cell) (M : marks) (c : cell) : mask :=
  fun e => fr X c e && empty (nbm X M c e).

Lemma decide_world : forall X M c d,
  decide false d (fr X c) (M c) (nbm X M c) =
  decide_view false d (fr X c) (M c) (isn X M c) (nbm X M c d (pred d)).
Proof. reflexivity. Qed.

Lemma isn_eq : forall X M c e, isn X M c e = memb (step c e) X && empty (M (step c e)).
Proof. intros; unfold isn, fr, nbm; destruct (memb (step c e) X); reflexivity. Qed.

Ltac dvtac :=
  let p := fresh "p" in let f := fresh "f" in let h := fresh "h" in let i := fresh "i" in
  let e := fresh "e" in
  intros p f h i e; destruct p; intros;
  unfold decide_view, parent_dir, first_new, covered; cbn in *;
  destruct (h E), (h N), (h W), (h S); try discriminate; cbn;
  destruct (i E), (i N), (i W), (i S); try discriminate; cbn;
  try reflexivity; destruct e; cbn; try reflexivity; destruct (f _); reflexivity.

(* first decision (sub-cell p + 1, nothing of the cell marked) *)
Lemma dv1 : forall p f here i e, here p = false ->
  decide_view false (succ p) f here i e =
  if i (succ p) then Go (succ p) (pred (succ p)) else Go (succ (succ p)) (succ (succ p)).
Proof. dvtac. Qed.

(* second decision (sub-cell p + 2; p + 1 marked, its side done) *)
Lemma dv2 : forall p f here i e, here p = false -> here (succ p) = true -> i (succ p) = false ->
  decide_view false (succ (succ p)) f here i e =
  if i (succ (succ p)) then Go (succ (succ p)) (pred (succ (succ p)))
  else Go (succ (succ (succ p))) (succ (succ (succ p))).
Proof. dvtac. Qed.

(* third decision (sub-cell p + 3) *)
Lemma dv3 : forall p f here i e, here p = false -> here (succ p) = true ->
  here (succ (succ p)) = true -> i (succ p) = false -> i (succ (succ p)) = false ->
  decide_view false (pred p) f here i e =
  if i (pred p) then Go (pred p) (pred (pred p)) else Go (succ (pred p)) (succ (pred p)).
Proof. dvtac. Qed.

(* last decision (sub-cell p, the three other sides done) *)
Lemma dv4 : forall p f here i e, here (succ p) = true -> here (succ (succ p)) = true ->
  here (pred p) = true ->
  i (succ p) = false -> i (succ (succ p)) = false -> i (pred p) = false ->
  decide_view false p f here i e =
  if i p then Go p (pred p) else if f p && negb e then Go p (pred p) else Stop.
Proof. dvtac. Qed.

(* ---- the depth-first exploration the marks drive ---- *)
(* The tree with children k1, k2, k3 on the sides p + 1, p + 2, p + 3 and k0 in slot p. *)
Definition mkt (p : dir) (k1 k2 k3 k0 : tree) : tree :=
  match p with
  | E => Node k0 k1 k2 k3 | N => Node k3 k0 k1 k2 | W => Node k2 k3 k0 k1 | S => Node k1 k2 k3 k0
  end.

Lemma tour_mk : forall c p k1 k2 k3 k0,
  tour c p (mkt p k1 k2 k3 k0) =
  sub c (succ p)
    :: (tour (step c (succ p)) (opp (succ p)) k1 ++ [sub c (succ (succ p))])
    ++ (tour (step c (succ (succ p))) (opp (succ (succ p))) k2 ++ [sub c (pred p)])
    ++ (tour (step c (pred p)) (opp (pred p)) k3 ++ [sub c p]).
Proof. intros; destruct p; reflexivity. Qed.

Lemma cells_mk : forall c p k1 k2 k3 k0,
  cells c p (mkt p k1 k2 k3 k0) =
  c :: cells (step c (succ p)) (opp (succ p)) k1
    ++ cells (step c (succ (succ p))) (opp (succ (succ p))) k2
    ++ cells (step c (pred p)) (opp (pred p)) k3.
Proof. intros; destruct p; reflexivity. Qed.

Lemma kid_mk : forall p k1 k2 k3 k0, kid (mkt p k1 k2 k3 k0) p = k0.
Proof. intros; destruct p; reflexivity. Qed.

Lemma perm3 : forall {T} (A B C V : list T) c,
  Permutation (C ++ B ++ A ++ c :: V) (c :: A ++ B ++ C ++ V).
Proof.
  intros T A B C V c.
  rewrite (app_assoc B), (app_assoc C).
  rewrite <- Permutation_middle. apply perm_skip.
  rewrite !app_assoc.
  apply Permutation_app_tail.
  rewrite <- app_assoc, Permutation_app_comm. apply Permutation_app_tail. apply Permutation_app_comm.
Qed.

Section Explore.
Variable X : list cell.

(* dfs V c p t V': entering c (not yet visited, V the visited cells) from its parent in direction
   p, the exploration visits the subtree t and leaves V' visited. side V c d k V': side d of the
   cell c, with k the child there (Nil when the neighbour is not free or already visited). *)
Inductive dfs : list cell -> cell -> dir -> tree -> list cell -> Prop :=
  | dfs_node : forall V c p k1 k2 k3 V1 V2 V3,
      side (c :: V) c (succ p) k1 V1 ->
      side V1 c (succ (succ p)) k2 V2 ->
      side V2 c (pred p) k3 V3 ->
      dfs V c p (mkt p k1 k2 k3 Nil) V3
with side : list cell -> cell -> dir -> tree -> list cell -> Prop :=
  | side_skip : forall V c d,
      memb (step c d) X && negb (memb (step c d) V) = false -> side V c d Nil V
  | side_child : forall V c d k V',
      memb (step c d) X = true -> memb (step c d) V = false ->
      dfs V (step c d) (opp d) k V' -> side V c d k V'.

Scheme dfs_mut := Induction for dfs Sort Prop
  with side_mut := Induction for side Sort Prop.
Combined Scheme dfs_side_mut from dfs_mut, side_mut.

(* The root: all four sides, the virtual parent's side p = q0 - 1 last. *)
Inductive root : cell -> dir -> tree -> list cell -> Prop :=
  | root_intro : forall c0 p k1 k2 k3 k0 V1 V2 V3 V4,
      side [c0] c0 (succ p) k1 V1 ->
      side V1 c0 (succ (succ p)) k2 V2 ->
      side V2 c0 (pred p) k3 V3 ->
      side V3 c0 p k0 V4 ->
      root c0 (succ p) (mkt p k1 k2 k3 k0) V4.

Definition subX (V : list cell) : Prop := forall x, In x V -> In x X.

(* ---- structural facts ---- *)
Lemma explore_perm :
  (forall V c p t V', dfs V c p t V' -> Permutation V' (cells c p t ++ V)) /\
  (forall V c d k V', side V c d k V' -> Permutation V' (cells (step c d) (opp d) k ++ V)).
Proof.
  apply dfs_side_mut.
  - intros V c p k1 k2 k3 V1 V2 V3 _ H1 _ H2 _ H3. rewrite cells_mk.
    rewrite H3, H2, H1. simpl. rewrite <- !app_assoc. apply perm3.
  - intros; reflexivity.
  - intros; assumption.
Qed.

Lemma dfs_incl : forall V c p t V', dfs V c p t V' -> forall y, In y V -> In y V'.
Proof.
  intros V c p t V' H y Hy. rewrite ((proj1 explore_perm) _ _ _ _ _ H). apply in_or_app; auto.
Qed.

Lemma side_incl : forall V c d k V', side V c d k V' -> forall y, In y V -> In y V'.
Proof.
  intros V c d k V' H y Hy. rewrite ((proj2 explore_perm) _ _ _ _ _ H). apply in_or_app; auto.
Qed.

Lemma dfs_in : forall V c p t V', dfs V c p t V' -> In c V'.
Proof.
  intros V c p t V' H. rewrite ((proj1 explore_perm) _ _ _ _ _ H).
  destruct H. rewrite cells_mk. left; reflexivity.
Qed.

Lemma explore_nodup :
  (forall V c p t V', dfs V c p t V' -> NoDup V -> ~ In c V -> NoDup V') /\
  (forall V c d k V', side V c d k V' -> NoDup V -> NoDup V').
Proof.
  apply dfs_side_mut.
  - intros V c p k1 k2 k3 V1 V2 V3 _ H1 _ H2 _ H3 N Hc. auto using NoDup_cons.
  - intros; assumption.
  - intros V c d k V' Hx Hv _ H N. apply H; auto. apply memb_notIn; auto.
Qed.

Lemma explore_subX :
  (forall V c p t V', dfs V c p t V' -> In c X -> subX V -> subX V') /\
  (forall V c d k V', side V c d k V' -> subX V -> subX V').
Proof.
  apply dfs_side_mut.
  - intros V c p k1 k2 k3 V1 V2 V3 _ H1 _ H2 _ H3 Hc HV. apply H3, H2, H1.
    intros x [<-|Hx]; auto.
  - intros; assumption.
  - intros V c d k V' Hx Hv _ H HV. apply H; auto. apply memb_In; auto.
Qed.

(* A side leaves its neighbour visited when it is free. *)
Lemma side_closes : forall V c d k V', side V c d k V' -> In (step c d) X -> In (step c d) V'.
Proof.
  intros V c d k V' H Hx. destruct H as [V c d Hs|V c d k V' _ _ Hd].
  - apply memb_In in Hx. rewrite Hx in Hs. apply memb_In. destruct (memb (step c d) V); auto.
  - exact (dfs_in _ _ _ _ _ Hd).
Qed.

Lemma dfs_closes : forall V c p t V', dfs V c p t V' ->
  forall d, d <> p -> In (step c d) X -> In (step c d) V'.
Proof.
  intros V c p t V' H d Hd Hx. destruct H as [V c p k1 k2 k3 V1 V2 V3 H1 H2 H3].
  assert (d = succ p \/ d = succ (succ p) \/ d = pred p) as [-> | [-> | ->]]
    by (destruct p, d; cbn; auto; congruence).
  - apply (side_incl _ _ _ _ _ H3), (side_incl _ _ _ _ _ H2), (side_closes _ _ _ _ _ H1 Hx).
  - apply (side_incl _ _ _ _ _ H3), (side_closes _ _ _ _ _ H2 Hx).
  - apply (side_closes _ _ _ _ _ H3 Hx).
Qed.

(* Every cell the exploration visits has all its free neighbours visited at the end. *)
Lemma explore_closed :
  (forall V c p t V', dfs V c p t V' -> In (step c p) V ->
     forall y, In y V' -> ~ In y V -> forall e, In (step y e) X -> In (step y e) V') /\
  (forall V c d k V', side V c d k V' -> In c V ->
     forall y, In y V' -> ~ In y V -> forall e, In (step y e) X -> In (step y e) V').
Proof.
  apply dfs_side_mut.
  - intros V c p k1 k2 k3 V1 V2 V3 s1 H1 s2 H2 s3 H3 Hp y Hy HyV e He.
    assert (Hc1 : In c V1) by (apply (side_incl _ _ _ _ _ s1); left; auto).
    assert (Hc2 : In c V2) by (apply (side_incl _ _ _ _ _ s2); auto).
    destruct (in_dec cell_eq_dec y V2) as [Y2|Y2].
    + destruct (in_dec cell_eq_dec y V1) as [Y1|Y1].
      * destruct (cell_eq_dec y c) as [->|Yc].
        -- assert (Hd : e = p \/ e = succ p \/ e = succ (succ p) \/ e = pred p)
             by (destruct p, e; cbn; auto).
           destruct Hd as [-> | [-> | [-> | ->]]].
           ++ apply (side_incl _ _ _ _ _ s3), (side_incl _ _ _ _ _ s2),
                (side_incl _ _ _ _ _ s1); right; auto.
           ++ apply (side_incl _ _ _ _ _ s3), (side_incl _ _ _ _ _ s2),
                (side_closes _ _ _ _ _ s1 He).
           ++ apply (side_incl _ _ _ _ _ s3), (side_closes _ _ _ _ _ s2 He).
           ++ apply (side_closes _ _ _ _ _ s3 He).
        -- apply (side_incl _ _ _ _ _ s3), (side_incl _ _ _ _ _ s2).
           apply (H1 (or_introl eq_refl) y Y1); auto. intros [->|Hy']; auto.
      * apply (side_incl _ _ _ _ _ s3). apply (H2 Hc1 y Y2 Y1 e He).
    + apply (H3 Hc2 y Hy Y2 e He).
  - intros V c d Hs _ y Hy HyV; contradiction.
  - intros V c d k V' Hx Hv Hd H Hc. apply H. rewrite step_opp; auto.
Qed.

(* Reachability inside X (4-connectivity). *)
Inductive reach (c0 : cell) : cell -> Prop :=
  | reach_refl : In c0 X -> reach c0 c0
  | reach_step : forall x d, reach c0 x -> In (step x d) X -> reach c0 (step x d).

Lemma explore_reach : forall c0,
  (forall V c p t V', dfs V c p t V' -> reach c0 c ->
     forall y, In y V' -> ~ In y V -> reach c0 y) /\
  (forall V c d k V', side V c d k V' -> reach c0 c ->
     forall y, In y V' -> ~ In y V -> reach c0 y).
Proof.
  intros c0. apply dfs_side_mut.
  - intros V c p k1 k2 k3 V1 V2 V3 s1 H1 s2 H2 s3 H3 Hc y Hy HyV.
    destruct (in_dec cell_eq_dec y V2) as [Y2|Y2]; [|apply (H3 Hc y Hy Y2)].
    destruct (in_dec cell_eq_dec y V1) as [Y1|Y1]; [|apply (H2 Hc y Y2 Y1)].
    destruct (cell_eq_dec y c) as [->|Yc]; auto.
    apply (H1 Hc y Y1). intros [->|Hy']; auto.
  - intros V c d Hs _ y Hy HyV; contradiction.
  - intros V c d k V' Hx Hv Hd H Hc. apply H. apply reach_step; auto. apply memb_In; auto.
Qed.

(* ---- every exploration exists (X is finite) ---- *)
Definition measure (V : list cell) : nat := length (filter (fun x => negb (memb x V)) X).

Lemma filter_le : forall (f g : cell -> bool) l,
  (forall x, In x l -> f x = true -> g x = true) -> (length (filter f l) <= length (filter g l))%nat.
Proof.
  intros f g l; induction l as [|a l IH]; intros H; simpl; auto.
  assert (IH' : (length (filter f l) <= length (filter g l))%nat) by (apply IH; intros; apply H; simpl; auto).
  destruct (f a) eqn:Fa; [rewrite (H a (or_introl eq_refl) Fa); simpl; lia|].
  destruct (g a); simpl; lia.
Qed.

Lemma filter_lt : forall (f g : cell -> bool) l,
  (forall x, In x l -> f x = true -> g x = true) ->
  (exists x, In x l /\ g x = true /\ f x = false) ->
  (length (filter f l) < length (filter g l))%nat.
Proof.
  intros f g l; induction l as [|a l IH]; intros H [x [Hx [Gx Fx]]]; [destruct Hx|].
  assert (Hl : forall y, In y l -> f y = true -> g y = true) by (intros; apply H; simpl; auto).
  destruct Hx as [<-|Hx].
  - simpl. rewrite Gx, Fx. simpl. pose proof (filter_le f g l Hl). lia.
  - simpl. assert (IH' := IH Hl (ex_intro _ x (conj Hx (conj Gx Fx)))).
    destruct (f a) eqn:Fa; [rewrite (H a (or_introl eq_refl) Fa); simpl; lia|].
    destruct (g a); simpl; lia.
Qed.

Lemma measure_incl : forall V W, (forall y, In y V -> In y W) -> (measure W <= measure V)%nat.
Proof.
  intros V W H. apply filter_le. intros x _ Hx.
  apply negb_true_iff, memb_notIn in Hx. apply negb_true_iff, memb_notIn. auto.
Qed.

Lemma measure_cons : forall c V, In c X -> ~ In c V -> (measure (c :: V) < measure V)%nat.
Proof.
  intros c V Hc HV. apply filter_lt.
  - intros x _ Hx. apply negb_true_iff, memb_notIn in Hx. apply negb_true_iff, memb_notIn.
    intros H; apply Hx; right; auto.
  - exists c. split; auto. split.
    + apply negb_true_iff, memb_notIn; auto.
    + apply negb_false_iff, memb_In; left; auto.
Qed.

Lemma dfs_exists : forall n V, (measure V <= n)%nat ->
  forall c p, In c X -> ~ In c V -> exists t V', dfs V c p t V'.
Proof.
  induction n as [|n IH]; intros V Hm c p Hc HV.
  - pose proof (measure_cons c V Hc HV); lia.
  - pose proof (measure_cons c V Hc HV) as Hlt.
    assert (Side : forall W d, (forall y, In y (c :: V) -> In y W) ->
              exists k W', side W c d k W' /\ (forall y, In y W -> In y W')).
    { intros W d HW.
      destruct (memb (step c d) X && negb (memb (step c d) W)) eqn:Ed.
      - apply andb_true_iff in Ed. destruct Ed as [E1 E2]. apply negb_true_iff in E2.
        destruct (IH W ltac:(pose proof (measure_incl _ _ HW); lia) (step c d) (opp d))
          as [t [W' Ht]]; [apply memb_In; auto | apply memb_notIn; auto|].
        exists t, W'. split; [apply side_child; auto|]. apply (dfs_incl _ _ _ _ _ Ht).
      - exists Nil, W. split; auto. apply side_skip; auto. }
    destruct (Side (c :: V) (succ p)) as [k1 [V1 [S1 I1]]]; auto.
    destruct (Side V1 (succ (succ p))) as [k2 [V2 [S2 I2]]]; auto.
    destruct (Side V2 (pred p)) as [k3 [V3 [S3 I3]]]; auto.
    exists (mkt p k1 k2 k3 Nil), V3. exact (dfs_node V c p k1 k2 k3 V1 V2 V3 S1 S2 S3).
Qed.

Lemma side_exists : forall V c d, exists k V', side V c d k V'.
Proof.
  intros V c d. destruct (memb (step c d) X && negb (memb (step c d) V)) eqn:Ed.
  - apply andb_true_iff in Ed. destruct Ed as [E1 E2]. apply negb_true_iff in E2.
    destruct (dfs_exists (measure V) V (le_n _) (step c d) (opp d)) as [t [V' Ht]];
      [apply memb_In; auto | apply memb_notIn; auto|].
    exists t, V'. apply side_child; auto.
  - exists Nil, V. apply side_skip; auto.
Qed.


Lemma root_exists : forall c0 q0, exists t V, root c0 q0 t V.
Proof.
  intros c0 q0. rewrite <- (succ_pred q0). set (p := pred q0).
  destruct (side_exists [c0] c0 (succ p)) as [k1 [V1 S1]].
  destruct (side_exists V1 c0 (succ (succ p))) as [k2 [V2 S2]].
  destruct (side_exists V2 c0 (pred p)) as [k3 [V3 S3]].
  destruct (side_exists V3 c0 p) as [k0 [V4 S4]].
  exists (mkt p k1 k2 k3 k0), V4. exact (root_intro c0 p k1 k2 k3 k0 V1 V2 V3 V4 S1 S2 S3 S4).
Qed.

(* ---- the marks ---- *)
Definition clean (V : list cell) (M : marks) : Prop := forall x, ~ In x V -> forall e, M x e = false.
Definition vis (V : list cell) (M : marks) (c : cell) : Prop :=
  forall x, In x V -> x <> c -> empty (M x) = false.

Lemma mark_same : forall M c d e, mark M c d c e = M c e || dir_eqb e d.
Proof. intros; unfold mark; rewrite cell_eqb_refl; reflexivity. Qed.

Lemma mark_other : forall M c d x e, x <> c -> mark M c d x e = M x e.
Proof. intros; unfold mark; rewrite cell_eqb_neq; auto; apply orb_false_r. Qed.

Lemma empty_marked : forall (m : mask) e, m e = true -> empty m = false.
Proof. intros m e H; destruct e; unfold empty; rewrite H; rewrite ?orb_true_r; reflexivity. Qed.

Lemma empty_clean : forall (m : mask), (forall e, m e = false) -> empty m = true.
Proof. intros m H; unfold empty; rewrite !H; reflexivity. Qed.

Lemma isn_new : forall V M c x, clean V M -> vis V M c -> x <> c ->
  memb x X && empty (M x) = memb x X && negb (memb x V).
Proof.
  intros V M c x Hc Hv Hx. destruct (memb x V) eqn:E.
  - apply memb_In in E. rewrite (Hv x E Hx). reflexivity.
  - apply memb_notIn in E. rewrite empty_clean; auto.
Qed.

Lemma isn_old : forall V M c x, vis V M c -> x <> c -> (In x X -> In x V) ->
  memb x X && empty (M x) = false.
Proof.
  intros V M c x Hv Hx H. destruct (memb x X) eqn:E; auto.
  apply memb_In in E. rewrite (Hv x (H E) Hx). reflexivity.
Qed.

Lemma vis_step : forall W W' M M' c, vis W M c ->
  (forall x, In x W -> x <> c -> forall e, M' x e = M x e) ->
  (forall x, In x W' -> ~ In x W -> x <> c -> forall e, M' x e = true) ->
  vis W' M' c.
Proof.
  intros W W' M M' c Hv F N x Hx Hxc. destruct (in_dec cell_eq_dec x W) as [H|H].
  - unfold empty. rewrite !(F x H Hxc). apply (Hv x H Hxc).
  - apply (empty_marked _ E). apply N; auto.
Qed.

(* The robot back in sub-cell p of c after the three sides, c's three other sub-cells marked. *)
Lemma last_dec : forall V V' c p t M, dfs V c p t V' -> vis V' M c ->
  (forall e, M c e = negb (dir_eqb e p)) ->
  decide false p (fr X c) (M c) (nbm X M c) =
  if isn X M c p then Go p (pred p)
  else if memb (step c p) X && negb (M (step c p) (pred p)) then Go p (pred p) else Stop.
Proof.
  intros V V' c p t M Hd Hv HM. rewrite decide_world.
  assert (Hi : forall e, e <> p -> isn X M c e = false).
  { intros e He. rewrite isn_eq. apply (isn_old V' M c); [auto|apply step_neq|].
    apply (dfs_closes _ _ _ _ _ Hd e He). }
  rewrite dv4; try (rewrite HM; destruct p; reflexivity);
    try (apply Hi; destruct p; discriminate).
  unfold fr, nbm. destruct (memb (step c p) X); reflexivity.
Qed.

(* ---- the simulation: the world's steps follow the tour of the explored tree ---- *)
Definition DL (V : list cell) (c : cell) (p : dir) (t : tree) (V' : list cell) : Prop :=
  forall M, ~ In c V -> In c X -> subX V -> clean V M -> (forall x, In x V -> empty (M x) = false) ->
  exists M' l, tour c p t = sub c (succ p) :: l /\
    goes X (St (sub c (succ p)) (succ p) false M) (map withq l) (St (sub c p) p false M') /\
    (forall e, M' c e = negb (dir_eqb e p)) /\
    (forall x, In x V -> forall e, M' x e = M x e) /\
    (forall x, In x V' -> ~ In x V -> x <> c -> forall e, M' x e = true) /\
    clean V' M'.

Definition SL (V : list cell) (c : cell) (d : dir) (k : tree) (V' : list cell) : Prop :=
  forall M, In c V -> subX V -> clean V M -> vis V M c -> M c (succ d) = false ->
  decide false d (fr X c) (M c) (nbm X M c) =
    (if memb (step c d) X && negb (memb (step c d) V) then Go d (pred d) else Go (succ d) (succ d)) ->
  exists M',
    goes X (St (sub c d) d false M) (map withq (tour (step c d) (opp d) k ++ [sub c (succ d)]))
           (St (sub c (succ d)) (succ d) false M') /\
    (forall e, M' c e = M c e || dir_eqb e d) /\
    (forall x, In x V -> x <> c -> forall e, M' x e = M x e) /\
    (forall x, In x V' -> ~ In x V -> forall e, M' x e = true) /\
    clean V' M'.

Lemma simulation :
  (forall V c p t V', dfs V c p t V' -> DL V c p t V') /\
  (forall V c d k V', side V c d k V' -> SL V c d k V').
Proof.
  apply dfs_side_mut.
  - (* a cell: its three sides *)
    intros V c p k1 k2 k3 V1 V2 V3 s1 IH1 s2 IH2 s3 IH3 M Hc HcX HsubX Hclean Hvis.
    assert (HM0 : forall e, M c e = false) by (apply Hclean; auto).
    assert (Hcl0 : clean (c :: V) M) by (intros x Hx; apply Hclean; intros H; apply Hx; right; auto).
    assert (Hvis0 : vis (c :: V) M c) by (intros x [->|Hx] Hxc; [contradiction|auto]).
    assert (Hsub0 : subX (c :: V)) by (intros x [<-|Hx]; auto).
    assert (D1 : decide false (succ p) (fr X c) (M c) (nbm X M c) =
      (if memb (step c (succ p)) X && negb (memb (step c (succ p)) (c :: V))
       then Go (succ p) (pred (succ p)) else Go (succ (succ p)) (succ (succ p)))).
    { rewrite decide_world, dv1 by apply HM0. rewrite isn_eq, (isn_new (c :: V) M c); auto.
      apply step_neq. }
    destruct (IH1 M (or_introl eq_refl) Hsub0 Hcl0 Hvis0 (HM0 _) D1)
      as [M1 [G1 [E1 [F1 [N1 C1]]]]].
    assert (I1 : forall y, In y (c :: V) -> In y V1) by apply (side_incl _ _ _ _ _ s1).
    assert (Hvis1 : vis V1 M1 c) by (apply (vis_step (c :: V) V1 M M1 c); auto).
    assert (Hsub1 : subX V1) by (apply ((proj2 explore_subX) _ _ _ _ _ s1); auto).
    assert (D2 : decide false (succ (succ p)) (fr X c) (M1 c) (nbm X M1 c) =
      (if memb (step c (succ (succ p))) X && negb (memb (step c (succ (succ p))) V1)
       then Go (succ (succ p)) (pred (succ (succ p)))
       else Go (succ (succ (succ p))) (succ (succ (succ p))))).
    { rewrite decide_world, dv2; try (rewrite E1, HM0; destruct p; reflexivity).
      - rewrite isn_eq, (isn_new V1 M1 c); auto. apply step_neq.
      - rewrite isn_eq. apply (isn_old V1 M1 c); auto. apply step_neq.
        apply (side_closes _ _ _ _ _ s1). }
    assert (Hc1 : In c V1) by (apply I1; left; auto).
    assert (Z1 : M1 c (succ (succ (succ p))) = false) by (rewrite E1, HM0; destruct p; reflexivity).
    destruct (IH2 M1 Hc1 Hsub1 C1 Hvis1 Z1 D2) as [M2 [G2 [E2 [F2 [N2 C2]]]]].
    assert (I2 : forall y, In y V1 -> In y V2) by apply (side_incl _ _ _ _ _ s2).
    assert (Hvis2 : vis V2 M2 c).
    { apply (vis_step V1 V2 M1 M2 c); auto. }
    assert (Hsub2 : subX V2) by (apply ((proj2 explore_subX) _ _ _ _ _ s2); auto).
    assert (Hc2 : In c V2) by (apply I2, I1; left; auto).
    assert (Z2 : M2 c (succ (pred p)) = false) by (rewrite E2, E1, HM0; destruct p; reflexivity).
    assert (D3 : decide false (pred p) (fr X c) (M2 c) (nbm X M2 c) =
      (if memb (step c (pred p)) X && negb (memb (step c (pred p)) V2)
       then Go (pred p) (pred (pred p)) else Go (succ (pred p)) (succ (pred p)))).
    { rewrite decide_world, dv3; try (rewrite ?E2, E1, HM0; destruct p; reflexivity).
      - rewrite isn_eq, (isn_new V2 M2 c); auto. apply step_neq.
      - rewrite isn_eq. apply (isn_old V2 M2 c); auto. apply step_neq.
        intros H. apply I2, (side_closes _ _ _ _ _ s1 H).
      - rewrite isn_eq. apply (isn_old V2 M2 c); auto. apply step_neq.
        apply (side_closes _ _ _ _ _ s2). }
    destruct (IH3 M2 Hc2 Hsub2 C2 Hvis2 Z2 D3) as [M3 [G3 [E3 [F3 [N3 C3]]]]].
    rewrite succ_pred in G3.
    exists M3. eexists. split; [rewrite tour_mk; reflexivity|]. split.
    { rewrite map_app. apply (goes_trans _ _ _ _ _ _ G1).
      rewrite map_app. apply (goes_trans _ _ _ _ _ _ G2), G3. }
    split; [intros e; rewrite E3, E2, E1, HM0; destruct e, p; reflexivity|].
    split.
    { intros x Hx e. assert (Hxc : x <> c) by (intros ->; contradiction).
      rewrite F3, F2, F1; auto. right; auto. apply I1; right; auto. apply I2, I1; right; auto. }
    split; auto.
    intros x Hx HxV Hxc e.
    destruct (in_dec cell_eq_dec x V2) as [Y2|Y2]; [|apply N3; auto].
    rewrite F3; auto.
    destruct (in_dec cell_eq_dec x V1) as [Y1|Y1]; [|apply N2; auto].
    rewrite F2; auto. apply N1; auto. intros [->|H]; auto.
  - (* a side with no child: walk on around the cell *)
    intros V c d Hs M Hc HsubX Hclean Hvis Hsucc Hdec. rewrite Hs in Hdec.
    exists (mark M c d). split.
    { cbn [tour app map]. rewrite quad_withq.
      pose proof (goes_go X c d M (succ d) (succ d) Hdec) as G.
      rewrite walk_step in G. apply G. rewrite cell_of_sub. apply memb_In; auto. }
    split; [intros e; apply mark_same|].
    split; [intros x _ Hx e; apply mark_other; auto|].
    split; [intros x Hx Hx'; contradiction|].
    intros x Hx e. rewrite mark_other; [apply Hclean; auto|]. intros ->; contradiction.
  - (* a side with a child: cross, the child's subtree, return *)
    intros V c d k V' Hx Hv Hd IH M Hc HsubX Hclean Hvis Hsucc Hdec.
    rewrite Hx, Hv in Hdec. cbn in Hdec.
    set (x := step c d) in *.
    assert (Hxc : x <> c) by apply step_neq.
    assert (HxV : ~ In x V) by (apply memb_notIn; auto).
    pose proof (goes_go X c d M d (pred d) Hdec) as G1.
    rewrite cross_step, <- succ_opp in G1. fold x in G1.
    specialize (G1 ltac:(rewrite cell_of_sub; auto)).
    destruct (IH (mark M c d)) as [M2 [l [Ht [G2 [E2 [F2 [N2 C2]]]]]]]; auto.
    { apply memb_In; auto. }
    { intros y Hy e. rewrite mark_other; [apply Hclean; auto|]. intros ->; contradiction. }
    { intros y Hy. destruct (cell_eq_dec y c) as [->|Hyc].
      - apply (empty_marked _ d). rewrite mark_same, dir_eqb_refl, orb_true_r; reflexivity.
      - unfold empty. rewrite !mark_other by auto. apply Hvis; auto. }
    assert (Hvis2 : vis V' M2 x).
    { apply (vis_step V V' (mark M c d) M2 x); auto.
      intros y Hy Hyx. destruct (cell_eq_dec y c) as [->|Hyc].
      - apply (empty_marked _ d). rewrite mark_same, dir_eqb_refl, orb_true_r; reflexivity.
      - unfold empty. rewrite !mark_other by auto. apply Hvis; auto. }
    assert (HcV' : In c V') by apply (dfs_incl _ _ _ _ _ Hd c Hc).
    pose proof (last_dec V V' x (opp d) k M2 Hd Hvis2 E2) as D3.
    assert (Hxo : step x (opp d) = c) by apply step_opp.
    rewrite isn_eq, Hxo in D3.
    rewrite (isn_old V' M2 x c) in D3; auto.
    assert (HcX : memb c X = true) by (apply memb_In; auto).
    rewrite F2, mark_same, HcX in D3 by auto.
    replace (M c (pred (opp d)) || dir_eqb (pred (opp d)) d) with false in D3
      by (rewrite pred_opp, Hsucc; destruct d; reflexivity).
    cbn [andb negb] in D3.
    pose proof (goes_go X x (opp d) M2 (opp d) (pred (opp d)) D3) as G3.
    rewrite cross_step, Hxo, pred_opp in G3.
    specialize (G3 ltac:(rewrite cell_of_sub; auto)).
    exists (mark M2 x (opp d)). split.
    { rewrite Ht. cbn [app map]. rewrite quad_withq, map_app. cbn [map]. rewrite quad_withq.
      change ((sub x (succ (opp d)), succ (opp d)) :: map withq l ++ [(sub c (succ d), succ d)])
        with ([(sub x (succ (opp d)), succ (opp d))] ++ map withq l ++ [(sub c (succ d), succ d)]).
      apply (goes_trans _ _ _ _ _ _ G1), (goes_trans _ _ _ _ _ _ G2), G3. }
    split; [intros e; rewrite mark_other, F2, mark_same by auto; reflexivity|].
    split; [intros y Hy Hyc e; rewrite mark_other, F2, mark_other; auto; intros ->; contradiction|].
    split.
    { intros y Hy HyV e. destruct (cell_eq_dec y x) as [->|Hyx].
      - rewrite mark_same, E2. destruct e, d; reflexivity.
      - rewrite mark_other by auto. apply N2; auto. }
    intros y Hy e. rewrite mark_other; [apply C2; auto|].
    intros ->. apply Hy. apply (dfs_in _ _ _ _ _ Hd).
Qed.

Lemma pred_succ_eq : forall d, pred (succ d) = d. Proof. destruct d; reflexivity. Qed.

Lemma tour_mk_kid : forall c p k1 k2 k3 k0,
  tour c p (mkt p k1 k2 k3 k0) = tour c p (mkt p k1 k2 k3 Nil).
Proof. intros; rewrite !tour_mk; reflexivity. Qed.

Lemma cells_mk_kid : forall c p k1 k2 k3 k0,
  cells c p (mkt p k1 k2 k3 k0) = cells c p (mkt p k1 k2 k3 Nil).
Proof. intros; rewrite !cells_mk; reflexivity. Qed.

(* The run from the start: the root's tour, then Stop. *)
Lemma root_run : forall c0 q0 t V4, root c0 q0 t V4 -> In c0 X ->
  exists l, stc_tour c0 q0 t = sub c0 q0 :: l /\
    forall n, run X (length l + Datatypes.S n) (start c0 q0) = (map withq l, Stopped).
Proof.
  intros c0 q0 t V4 Hr Hc0. destruct Hr as [c0 p k1 k2 k3 k0 V1 V2 V3 V4 s1 s2 s3 s4].
  pose proof (dfs_node [] c0 p k1 k2 k3 V1 V2 V3 s1 s2 s3) as Hd.
  assert (HM0 : clean [] no_marks) by (intros x _ e; reflexivity).
  destruct ((proj1 simulation) _ _ _ _ _ Hd no_marks (fun H => H) Hc0 (fun x H => match H with end)
              HM0 (fun x H => match H with end))
    as [M3 [l3 [Ht3 [G3 [E3 [_ [N3 C3]]]]]]].
  assert (Hvis3 : vis V3 M3 c0) by (intros x Hx Hxc; apply (empty_marked _ E); apply N3; auto).
  assert (Hsub3 : subX V3)
    by (apply ((proj1 explore_subX) _ _ _ _ _ Hd); auto; intros x []).
  pose proof (last_dec [] V3 c0 p _ M3 Hd Hvis3 E3) as D.
  unfold stc_tour. rewrite pred_succ_eq, kid_mk, tour_mk_kid, Ht3.
  assert (Hxc : step c0 p <> c0) by apply step_neq.
  rewrite isn_eq, (isn_new V3 M3 c0) in D by auto.
  inversion s4 as [V c d Hs | V c d k V' Hx Hv Hd4]; subst.
  - (* no child on the last side: Stop at once *)
    rewrite Hs in D.
    replace (memb (step c0 p) X && negb (M3 (step c0 p) (pred p))) with false in D.
    2:{ destruct (memb (step c0 p) X) eqn:Ex; [|reflexivity].
        try rewrite Ex in Hs. cbn in Hs. apply negb_false_iff, memb_In in Hs.
        rewrite N3; auto. }
    exists (l3 ++ []). split; [reflexivity|]. intros n. rewrite app_nil_r.
    unfold start. rewrite <- (map_length withq l3), G3, run_stop by exact D.
    unfold prepend; cbn. rewrite app_nil_r; reflexivity.
  - (* a child on the last side: its subtree, then Stop on the way back *)
    set (x := step c0 p) in *.
    rewrite Hx, Hv in D. cbn in D.
    pose proof (goes_go X c0 p M3 p (pred p) D) as G4.
    rewrite cross_step, <- succ_opp in G4. fold x in G4.
    specialize (G4 ltac:(rewrite cell_of_sub; auto)).
    assert (HxV : ~ In x V3) by (apply memb_notIn; auto).
    assert (Hm4 : forall y, In y V3 -> empty (mark M3 c0 p y) = false).
    { intros y Hy. destruct (cell_eq_dec y c0) as [->|Hyc].
      - apply (empty_marked _ p). rewrite mark_same, dir_eqb_refl, orb_true_r; reflexivity.
      - apply (empty_marked _ E). rewrite mark_other by auto. apply N3; auto. }
    destruct ((proj1 simulation) _ _ _ _ _ Hd4 (mark M3 c0 p) HxV ltac:(apply memb_In; auto)
                Hsub3 ltac:(intros y Hy e; rewrite mark_other by (intros ->; apply Hy;
                   apply (dfs_in _ _ _ _ _ Hd)); apply C3; auto) Hm4)
      as [M5 [l5 [Ht5 [G5 [E5 [F5 [N5 C5]]]]]]].
    assert (Hvis5 : vis V4 M5 x).
    { apply (vis_step V3 V4 (mark M3 c0 p) M5 x); auto. intros y Hy _; apply Hm4; auto. }
    pose proof (last_dec V3 V4 x (opp p) k0 M5 Hd4 Hvis5 E5) as D5.
    assert (Hxo : step x (opp p) = c0) by apply step_opp.
    assert (Hc0V : In c0 V3) by apply (dfs_in _ _ _ _ _ Hd).
    assert (Em : empty (M5 c0) = false).
    { apply (empty_marked _ p). rewrite F5 by auto. rewrite mark_same, dir_eqb_refl, orb_true_r.
      reflexivity. }
    rewrite isn_eq, Hxo, Em, andb_false_r in D5.
    rewrite F5, mark_same, pred_opp, E3 in D5 by auto.
    replace (negb (dir_eqb (succ p) p) || dir_eqb (succ p) p) with true in D5
      by (destruct p; reflexivity).
    rewrite andb_false_r in D5. cbn in D5.
    exists (l3 ++ sub x (succ (opp p)) :: l5). split; [rewrite Ht5; reflexivity|]. intros n.
    replace (length (l3 ++ sub x (succ (opp p)) :: l5) + Datatypes.S n)%nat with
      (length (map withq l3) + (length [(sub x (succ (opp p)), succ (opp p))] +
         (length (map withq l5) + Datatypes.S n)))%nat
      by (rewrite !map_length, app_length; cbn; lia).
    unfold start. rewrite G3, G4, G5, run_stop by exact D5.
    unfold prepend; cbn. rewrite !app_nil_r, map_app. cbn. rewrite quad_withq. reflexivity.
Qed.

(* ---- the explored cells are the component of the start ---- *)
Lemma root_perm : forall c0 q0 t V4, root c0 q0 t V4 -> Permutation V4 (tree_cells c0 q0 t).
Proof.
  intros c0 q0 t V4 Hr. destruct Hr as [c0 p k1 k2 k3 k0 V1 V2 V3 V4 s1 s2 s3 s4].
  pose proof (dfs_node [] c0 p k1 k2 k3 V1 V2 V3 s1 s2 s3) as Hd.
  unfold tree_cells. rewrite pred_succ_eq, kid_mk, cells_mk_kid.
  rewrite ((proj2 explore_perm) _ _ _ _ _ s4), ((proj1 explore_perm) _ _ _ _ _ Hd), app_nil_r.
  apply Permutation_app_comm.
Qed.

Lemma root_nodup : forall c0 q0 t V4, root c0 q0 t V4 -> NoDup V4.
Proof.
  intros c0 q0 t V4 Hr. destruct Hr as [c0 p k1 k2 k3 k0 V1 V2 V3 V4 s1 s2 s3 s4].
  pose proof (dfs_node [] c0 p k1 k2 k3 V1 V2 V3 s1 s2 s3) as Hd.
  apply ((proj2 explore_nodup) _ _ _ _ _ s4). apply ((proj1 explore_nodup) _ _ _ _ _ Hd).
  constructor. intros [].
Qed.

(* The four sides of the root, and membership in what each of them adds. *)
Lemma root_cases : forall c0 q0 t V4, root c0 q0 t V4 -> forall y, In y V4 ->
  y = c0 \/
  exists V d k V', side V c0 d k V' /\ In c0 V /\ In y V' /\ ~ In y V /\
    (forall z, In z V' -> In z V4).
Proof.
  intros c0 q0 t V4 Hr y Hy. destruct Hr as [c0 p k1 k2 k3 k0 V1 V2 V3 V4 s1 s2 s3 s4].
  pose proof (side_incl _ _ _ _ _ s1) as I1. pose proof (side_incl _ _ _ _ _ s2) as I2.
  pose proof (side_incl _ _ _ _ _ s3) as I3. pose proof (side_incl _ _ _ _ _ s4) as I4.
  destruct (cell_eq_dec y c0) as [->|Hyc]; [left; auto|right].
  destruct (in_dec cell_eq_dec y V3) as [Y3|Y3];
    [|exists V3, p, k0, V4; repeat split; auto; apply I3, I2, I1; left; auto].
  destruct (in_dec cell_eq_dec y V2) as [Y2|Y2];
    [|exists V2, (pred p), k3, V3; repeat split; auto; apply I2, I1; left; auto].
  destruct (in_dec cell_eq_dec y V1) as [Y1|Y1];
    [|exists V1, (succ (succ p)), k2, V2; repeat split; auto; apply I1; left; auto].
  exists [c0], (succ p), k1, V1. repeat split; auto; [left; auto|]. intros [->|[]]; auto.
Qed.

Lemma root_in : forall c0 q0 t V4, root c0 q0 t V4 -> In c0 V4.
Proof.
  intros c0 q0 t V4 Hr. destruct Hr as [c0 p k1 k2 k3 k0 V1 V2 V3 V4 s1 s2 s3 s4].
  apply (side_incl _ _ _ _ _ s4), (side_incl _ _ _ _ _ s3), (side_incl _ _ _ _ _ s2),
    (side_incl _ _ _ _ _ s1). left; auto.
Qed.

Lemma root_closed : forall c0 q0 t V4, root c0 q0 t V4 ->
  forall y e, In y V4 -> In (step y e) X -> In (step y e) V4.
Proof.
  intros c0 q0 t V4 Hr y e Hy He.
  destruct (root_cases c0 q0 t V4 Hr y Hy) as [->|[V [d [k [V' [Hs [Hc [Y1 [Y2 I]]]]]]]]].
  - destruct Hr as [c0 p k1 k2 k3 k0 V1 V2 V3 V4 s1 s2 s3 s4].
    pose proof (side_incl _ _ _ _ _ s2) as I2.
    pose proof (side_incl _ _ _ _ _ s3) as I3. pose proof (side_incl _ _ _ _ _ s4) as I4.
    assert (Hd : e = p \/ e = succ p \/ e = succ (succ p) \/ e = pred p)
      by (destruct p, e; cbn; auto).
    destruct Hd as [-> | [-> | [-> | ->]]].
    + apply (side_closes _ _ _ _ _ s4 He).
    + apply I4, I3, I2, (side_closes _ _ _ _ _ s1 He).
    + apply I4, I3, (side_closes _ _ _ _ _ s2 He).
    + apply I4, (side_closes _ _ _ _ _ s3 He).
  - apply I. apply ((proj2 explore_closed) _ _ _ _ _ Hs Hc y Y1 Y2 e He).
Qed.

Lemma root_reach : forall c0 q0 t V4, root c0 q0 t V4 -> In c0 X ->
  forall y, In y V4 -> reach c0 y.
Proof.
  intros c0 q0 t V4 Hr Hc0 y Hy.
  destruct (root_cases c0 q0 t V4 Hr y Hy) as [->|[V [d [k [V' [Hs [Hc [Y1 [Y2 I]]]]]]]]].
  - apply reach_refl; auto.
  - apply ((proj2 (explore_reach c0)) _ _ _ _ _ Hs (reach_refl _ Hc0) y Y1 Y2).
Qed.

End Explore.

(* ---- the theorem ---- *)
Theorem ant_run_is_stc_tour : forall X c0 q0, In c0 X ->
  exists t, t <> Nil /\ NoDup (tree_cells c0 q0 t) /\
    (forall y, In y (tree_cells c0 q0 t) <-> reach X c0 y) /\
    forall fuel, (4 * length (tree_cells c0 q0 t) <= fuel)%nat ->
      ant_run X c0 q0 fuel = (map withq (stc_tour c0 q0 t), Stopped).
Proof.
  intros X c0 q0 Hc0. destruct (root_exists X c0 q0) as [t [V4 Hr]].
  pose proof (root_perm X c0 q0 t V4 Hr) as HP.
  exists t. split; [destruct Hr; destruct p; discriminate|].
  split; [apply (Permutation_NoDup HP), (root_nodup X c0 q0 t V4 Hr)|].
  split.
  { intros y; split.
    - intros Hy. apply (root_reach X c0 q0 t V4 Hr Hc0).
      apply (Permutation_in y (Permutation_sym HP) Hy).
    - intros R. apply (Permutation_in y HP). induction R as [Hc|x d R IH Hx].
      + apply (root_in X c0 q0 t V4 Hr).
      + apply (root_closed X c0 q0 t V4 Hr x d IH Hx). }
  intros fuel Hf. destruct (root_run X c0 q0 t V4 Hr Hc0) as [l [Ht Hrun]].
  pose proof (invariant4_length c0 q0 t) as L. rewrite Ht in L. cbn [length] in L.
  replace fuel with (length l + Datatypes.S (fuel - length l - 1))%nat by lia.
  unfold ant_run. rewrite Hrun, Ht. unfold prepend. cbn [map fst snd app].
  rewrite quad_withq. reflexivity.
Qed.

Lemma reach_in : forall X c0 y, reach X c0 y -> In y X.
Proof. intros X c0 y R; induction R; auto. Qed.

Lemma map_fst_withq : forall l, map fst (map withq l) = l.
Proof. induction l as [|a l IH]; cbn; congruence. Qed.

(* The ant, run in its marks world from any start sub-cell of any map, covers the start's
   component K of the map: every sub-cell of K exactly once, in a closed walk of 4-adjacent
   sub-cells that never leaves K, and stops. *)
Theorem ant_stc_covers_every_map : forall (X : list cell) (c0 : cell) (q0 : dir), In c0 X ->
  exists K : list cell,
    NoDup K /\
    (forall y, In y K <-> reach X c0 y) /\
    (forall y, In y K -> In y X) /\
    (forall y d, In y K -> In (step y d) X -> In (step y d) K) /\
    forall fuel, (4 * length K <= fuel)%nat ->
      let r := ant_run X c0 q0 fuel in
      let P := map fst (fst r) in
      snd r = Stopped /\
      (exists t, P = stc_tour c0 q0 t /\ Permutation (tree_cells c0 q0 t) K) /\
      Permutation P (flat_map subs K) /\
      NoDup P /\
      length P = (4 * length K)%nat /\
      (exists rest, P = sub c0 q0 :: rest /\ linked (sub c0 q0) rest) /\
      adj (last P (sub c0 q0)) (sub c0 q0) /\
      (forall s, In s P -> In (cell_of s) K) /\
      Forall (fun sq => snd sq = quadrant_of (fst sq)) (fst r).
Proof.
  intros X c0 q0 Hc0.
  destruct (ant_run_is_stc_tour X c0 q0 Hc0) as [t [Hnil [ND [RE Hrun]]]].
  exists (tree_cells c0 q0 t). split; [exact ND|]. split; [exact RE|].
  split; [intros y Hy; apply (reach_in X c0), RE, Hy|].
  split.
  { intros y d Hy Hd. apply RE. apply reach_step; auto. apply RE; auto. }
  intros fuel Hf. cbv zeta. rewrite (Hrun fuel Hf). cbn [fst snd]. rewrite map_fst_withq.
  destruct (stc_tour_theorem (tree_cells c0 q0 t) c0 q0 t ND (Permutation_refl _) Hnil)
    as [P1 [P2 [P3 [P4 P5]]]].
  split; [reflexivity|].
  split; [exists t; split; [reflexivity | apply Permutation_refl]|].
  split; [exact P1|]. split; [exact P2|]. split; [exact P3|]. split; [exact P4|].
  split; [exact P5|]. split.
  - intros s Hs. apply (Permutation_in s P1), in_flat_map in Hs.
    destruct Hs as [y [Hy Hs]]. unfold subs in Hs.
    destruct Hs as [<-|[<-|[<-|[<-|[]]]]]; rewrite cell_of_sub; exact Hy.
  - apply Forall_forall. intros sq Hsq. apply in_map_iff in Hsq.
    destruct Hsq as [s [<- _]]. reflexivity.
Qed.


(* ---- ant-edge: the same decision over the sub-cells covered_from_edges reports ---- *)
(* The twelve edges of a cell (ant.hpp): bit e the cross box of sub-cell e, bit 4 + e its turn box,
   bit 8 + e its exterior edge in direction e (bit b of the cell's 12-bit mask, b a nat). *)
Definition edges := cell -> nat -> bool.

(* covered_from_edges: (edges | edges >> 4) & 0xF *)
Definition covered_e (Ed : edges) (c : cell) : mask :=
  fun e => Ed c (dir_num e) || Ed c (4 + dir_num e)%nat.

Definition light (Ed : edges) (c : cell) (b : nat) : edges :=
  fun x b' => Ed x b' || (cell_eqb x c && Nat.eqb b' b).

(* Floor::light_edge(s, d): the edge of sub-cell s in direction d. *)
Definition light_edge (Ed : edges) (s : cell) (d : dir) : edges :=
  let c := cell_of s in let e := quadrant_of s in
  if dir_eqb d (opp e) then light Ed c (dir_num e)
  else if dir_eqb d (succ e) then light Ed c (dir_num (succ e))
  else if dir_eqb d (pred e) then
    light (light Ed c (4 + dir_num e)%nat) (step c d) (8 + dir_num (succ e))%nat
  else light (light Ed c (8 + dir_num e)%nat) (step c d) (4 + dir_num (pred e))%nat.

Record estate := ESt { epos : cell; eqd : dir; edn : bool; eds : edges }.

(* The edge world: AntEdgeStc over Floor::observe_edges (every neighbour's edges are read, free
   or not) and Floor::apply with Marker::Edge (the edge behind the robot, opposite the move). *)
Fixpoint erun (X : list cell) (fuel : nat) (st : estate) : list (cell * dir) * outcome :=
  match fuel with
  | O => ([], OutOfFuel)
  | Datatypes.S n =>
      let c := cell_of (epos st) in
      match decide (edn st) (eqd st) (fr X c) (covered_e (eds st) c)
                   (fun d => covered_e (eds st) (step c d)) with
      | Stop => ([], Stopped)
      | Go m q' =>
          let target := step (epos st) m in
          if memb (cell_of target) X then
            prepend [(target, q')]
              (erun X n (ESt target q' (edn st) (light_edge (eds st) (epos st) (opp m))))
          else ([], Refused)
      end
  end.

Definition ant_edge_run (X : list cell) (c0 : cell) (q0 : dir) (fuel : nat) :=
  prepend [(sub c0 q0, q0)] (erun X fuel (ESt (sub c0 q0) q0 false (fun _ _ => false))).

(* decide reads a neighbour's marks only when the neighbour is free. *)
Lemma decide_ext : forall dn cur f h1 h2 nb1 nb2,
  (forall e, h1 e = h2 e) -> (forall d, f d = true -> forall e, nb1 d e = nb2 d e) ->
  decide dn cur f h1 nb1 = decide dn cur f h2 nb2.
Proof.
  intros dn cur f h1 h2 nb1 nb2 Hh Hn. unfold decide.
  rewrite (decide_view_ext dn cur f f h1 h2 (fun d => f d && empty (nb1 d))
             (fun d => f d && empty (nb2 d)) (nb1 cur (pred cur))); auto.
  - destruct (f cur) eqn:Fc.
    + rewrite (Hn cur Fc). reflexivity.
    + unfold decide_view. rewrite Fc. reflexivity.
  - intros d. destruct (f d) eqn:Fd; [|reflexivity]. cbn. unfold empty. rewrite !(Hn d Fd).
    reflexivity.
Qed.

(* Every move of ant_decide crosses side cur or walks on to cur + 1. *)
Lemma decide_shape : forall dn cur f h nb m q',
  decide dn cur f h nb = Go m q' -> (m = cur /\ q' = pred cur) \/ (m = succ cur /\ q' = succ cur).
Proof.
  intros dn cur f h nb m q' H. unfold decide, decide_view in H. destruct dn; [discriminate|].
  destruct (first_new _ _); cbn in H;
    repeat (match type of H with context [if ?b then _ else _] => destruct b end);
    inversion H; auto.
Qed.

Lemma sub_cell_quad : forall s, sub (cell_of s) (quadrant_of s) = s.
Proof.
  intros [x y]. unfold cell_of, quadrant_of. cbn [fst snd].
  pose proof (Z.div2_odd x) as Hx. pose proof (Z.div2_odd y) as Hy.
  rewrite Z.div2_div in Hx, Hy.
  destruct (Z.odd x), (Z.odd y); cbn [sub Z.b2z] in *; f_equal; lia.
Qed.

(* Leaving sub-cell s by a crossing or a walk lights exactly what marks s in covered_from_edges. *)
Lemma covered_light : forall Ed s m x e',
  m = quadrant_of s \/ m = succ (quadrant_of s) ->
  covered_e (light_edge Ed s (opp m)) x e' =
  covered_e Ed x e' || (cell_eqb x (cell_of s) && dir_eqb e' (quadrant_of s)).
Proof.
  intros Ed s m x e' Hm. unfold light_edge.
  destruct Hm as [->| ->]; destruct (quadrant_of s), e'; cbn;
    unfold covered_e, light; cbn;
    destruct (cell_eqb x (cell_of s)); cbn; rewrite ?andb_false_r, ?orb_false_r;
    repeat match goal with |- context [Ed ?a ?b] => destruct (Ed a b) end; reflexivity.
Qed.

(* The edge world runs exactly as the marks world, from related states. *)
Lemma erun_run : forall X fuel st est,
  epos est = pos st -> eqd est = qd st -> edn est = dn st -> qd st = quadrant_of (pos st) ->
  (forall x e, covered_e (eds est) x e = mks st x e) ->
  erun X fuel est = run X fuel st.
Proof.
  intros X fuel; induction fuel as [|n IH]; intros [p q d M] [p' q2 d' Ed];
    cbn [epos eqd edn eds pos qd dn mks]; intros -> -> -> Hq Hc; [reflexivity|].
  cbn [erun run epos eqd edn eds pos qd dn mks].
  rewrite (decide_ext d q (fr X (cell_of p)) (covered_e Ed (cell_of p)) (M (cell_of p))
             (fun d0 => covered_e Ed (step (cell_of p) d0)) (nbm X M (cell_of p))).
  2:{ intros e; apply Hc. }
  2:{ intros d0 Hf e. unfold nbm. unfold fr in Hf. rewrite Hf. apply Hc. }
  destruct (decide d q (fr X (cell_of p)) (M (cell_of p)) (nbm X M (cell_of p))) as [|m q'] eqn:D;
    [reflexivity|].
  destruct (memb (cell_of (step p m)) X); [|reflexivity].
  f_equal. apply IH; auto; cbn.
  - destruct (decide_shape _ _ _ _ _ _ _ D) as [[-> ->]|[-> ->]];
      rewrite <- (sub_cell_quad p), <- Hq.
    + rewrite cross_step, quad_sub; reflexivity.
    + rewrite walk_step, quad_sub; reflexivity.
  - intros x e. rewrite covered_light, Hc, <- Hq. reflexivity.
    destruct (decide_shape _ _ _ _ _ _ _ D) as [[-> _]|[-> _]]; rewrite <- Hq; auto.
Qed.

Theorem ant_edge_run_is_ant_run : forall X c0 q0 fuel, ant_edge_run X c0 q0 fuel = ant_run X c0 q0 fuel.
Proof.
  intros X c0 q0 fuel. unfold ant_edge_run, ant_run. f_equal. apply erun_run; cbn; auto.
  rewrite quad_sub; reflexivity.
Qed.

(* The edge world's ant covers every map just as the marks world's does. *)
Theorem ant_edge_stc_covers_every_map : forall (X : list cell) (c0 : cell) (q0 : dir), In c0 X ->
  exists K : list cell,
    NoDup K /\
    (forall y, In y K <-> reach X c0 y) /\
    (forall y, In y K -> In y X) /\
    (forall y d, In y K -> In (step y d) X -> In (step y d) K) /\
    forall fuel, (4 * length K <= fuel)%nat ->
      let r := ant_edge_run X c0 q0 fuel in
      let P := map fst (fst r) in
      snd r = Stopped /\
      (exists t, P = stc_tour c0 q0 t /\ Permutation (tree_cells c0 q0 t) K) /\
      Permutation P (flat_map subs K) /\
      NoDup P /\
      length P = (4 * length K)%nat /\
      (exists rest, P = sub c0 q0 :: rest /\ linked (sub c0 q0) rest) /\
      adj (last P (sub c0 q0)) (sub c0 q0) /\
      (forall s, In s P -> In (cell_of s) K) /\
      Forall (fun sq => snd sq = quadrant_of (fst sq)) (fst r).
Proof.
  intros X c0 q0 Hc0.
  destruct (ant_stc_covers_every_map X c0 q0 Hc0) as [K [H1 [H2 [H3 [H4 H5]]]]].
  exists K. split; [exact H1|]. split; [exact H2|]. split; [exact H3|]. split; [exact H4|].
  intros fuel Hf. rewrite ant_edge_run_is_ant_run. exact (H5 fuel Hf).
Qed.

(* ---- golden vectors: positions (sub-cell x, y; the start first) and outcome ---- *)
(* fuel 4 x |cells| (enough: the component has at most that many cells) *)
(* ant_l: cells [(0, 0); (0, 1); (0, 2); (1, 2)], start cell (0, 0), quadrant S *)
Definition ant_l : list cell := [(0, 0); (0, 1); (0, 2); (1, 2)].
Compute positions (ant_run ant_l (0, 0) S 16).
(* ant_block_2x3: cells [(0, 0); (1, 0); (0, 1); (1, 1); (0, 2); (1, 2)], start cell (0, 0), quadrant W *)
Definition ant_block_2x3 : list cell := [(0, 0); (1, 0); (0, 1); (1, 1); (0, 2); (1, 2)].
Compute positions (ant_run ant_block_2x3 (0, 0) W 24).
(* ant_ring: cells [(0, 0); (1, 0); (2, 0); (0, 1); (2, 1); (0, 2); (1, 2); (2, 2)], start cell (1, 2), quadrant N *)
Definition ant_ring : list cell := [(0, 0); (1, 0); (2, 0); (0, 1); (2, 1); (0, 2); (1, 2); (2, 2)].
Compute positions (ant_run ant_ring (1, 2) N 32).
(* ant_two: cells [(0, 0); (1, 0); (0, 1); (3, 0); (3, 1); (3, 2)], start cell (0, 1), quadrant E *)
Definition ant_two : list cell := [(0, 0); (1, 0); (0, 1); (3, 0); (3, 1); (3, 2)].
Compute positions (ant_run ant_two (0, 1) E 24).
(* ant-edge on the same maps and starts (equal to the above by ant_edge_run_is_ant_run) *)
Compute positions (ant_edge_run ant_l (0, 0) S 16).
Compute positions (ant_edge_run ant_block_2x3 (0, 0) W 24).
Compute positions (ant_edge_run ant_ring (1, 2) N 32).
Compute positions (ant_edge_run ant_two (0, 1) E 24).

Print Assumptions ant_run_is_stc_tour.
Print Assumptions ant_stc_covers_every_map.
Print Assumptions ant_edge_stc_covers_every_map.
