(* The decision of ant-like STC (paper 002), as a Coq function: a transcription of the shipped
   algorithms/stc/include/antkit/stc/ant.hpp `ant_decide`, line for line, over StcTour.v's
   directions (E = 0, N = 1, W = 2, S = 3; a quadrant is named by the same four values).

   This function is the one AntStcWorld.v proves things about (the robot that runs it covers every
   map), and the table at the end of this file is computed from it: proofs/tie/ant_stc_tie.cpp
   (ctest proof.tie.ant_decide) requires the shipped ant_decide to give the table's decision on
   every input of its domain (every quadrant, both values of `done`, every 4-bit free mask, here
   mask and neighbour masks: the observations a world can give), so the C++ cannot drift from what
   is proved.

   The table has 4 x 16 x 16 x 16 x 2 entries, not 4 x 2 x 16^6: `decide` reads a neighbour's mask
   only through "is it empty" and, for the neighbour across the robot's own side, one bit.
   `decide_reads_the_view` and `decide_view_ext` prove this, so the tie reduces each full input the
   same way and looks it up. `done` is not in the table: `decide` answers Stop whenever it is set (decide_done).

   Encoding (one character per entry): '.' is Stop; Go m q is the character 'a' + 4 m + q (m the
   direction of the move, q the quadrant the robot believes it enters). One string per current
   quadrant cur (E, N, W, S in that order); in each, the entry for (here, free, empty, entry) is at
   ((here * 16 + free) * 16 + empty) * 2 + entry, where bit d of here / free / empty is direction or
   quadrant d and entry is the neighbour-across-cur's mark on its sub-cell cur - 1. *)
From Coq Require Import Bool Arith List String Ascii.
Import ListNotations.
Require Import StcTour.

Definition dir_eqb (a b : dir) : bool :=
  match a, b with E, E | N, N | W, W | S, S => true | _, _ => false end.

Lemma dir_eqb_eq : forall a b, dir_eqb a b = true <-> a = b.
Proof. destruct a, b; simpl; split; congruence. Qed.

Inductive decision := Stop | Go (move : dir) (next_q : dir).

(* What the robot sees (ant.hpp MarkObservation): whether each neighbour cell is free, which
   sub-cells of its own cell are marked, and the marks of each neighbour cell (all unmarked when the
   neighbour is not free). *)
Definition mask := dir -> bool.

(* covered = here | (1 << cur): the robot's own sub-cell counts as covered. *)
Definition covered (here : mask) (cur s : dir) : bool := here s || dir_eqb s cur.

(* Step 1, w = Parent(x): walk back from the robot to the first uncovered sub-cell s, w = s; all
   covered: w = cur. *)
Definition parent_dir (cur : dir) (here : mask) : dir :=
  let s1 := pred cur in
  let s2 := pred s1 in
  let s3 := pred s2 in
  if negb (covered here cur s1) then s1
  else if negb (covered here cur s2) then s2
  else if negb (covered here cur s3) then s3
  else cur.

Definition empty (m : mask) : bool := negb (m E || m N || m W || m S).

(* Step 2, y = Neighbor(w, x): the first free neighbour with no mark, counter-clockwise after w,
   w itself last. `is_new d` is "free d && the neighbour's mask is 0". *)
Definition first_new (is_new : mask) (w : dir) : option dir :=
  let d1 := succ w in
  let d2 := succ d1 in
  let d3 := succ d2 in
  if is_new d1 then Some d1
  else if is_new d2 then Some d2
  else if is_new d3 then Some d3
  else if is_new w then Some w
  else None.

(* The decision in terms of what it reads: `is_new d` and the one mark bit `entry_marked` (the
   neighbour across side cur, its sub-cell cur - 1: the sub-cell a crossing would enter). *)
Definition decide_view (done : bool) (cur : dir) (free here is_new : mask)
    (entry_marked : bool) : decision :=
  if done then Stop
  else
    let w := parent_dir cur here in
    let '(target, child) :=
      match first_new is_new w with Some d => (d, true) | None => (w, false) end in
    if negb (dir_eqb target cur) then Go (succ cur) (succ cur) (* walk on around the cell *)
    else if child then Go cur (pred cur) (* cross into the child *)
    else if free cur && negb entry_marked then Go cur (pred cur) (* return to the parent *)
    else Stop. (* no parent to return to: the tour is closed *)

(* ant_decide(q, done, free_neighbours, here, neighbour): nb d is neighbour d's mask. *)
Definition decide (done : bool) (cur : dir) (free here : mask) (nb : dir -> mask) : decision :=
  decide_view done cur free here (fun d => free d && empty (nb d)) (nb cur (pred cur)).

Lemma decide_done : forall cur free here nb, decide true cur free here nb = Stop.
Proof. reflexivity. Qed.

(* The neighbours' masks matter only through "free and empty" and the one entry bit (by the
   definition of decide, stated), and decide_view only through the values of its masks: the
   reduction the C++ test applies before it looks an input up in the table. *)
Lemma decide_reads_the_view : forall done cur free here nb,
  decide done cur free here nb =
  decide_view done cur free here (fun d => free d && empty (nb d)) (nb cur (pred cur)).
Proof. reflexivity. Qed.

Lemma decide_view_ext : forall done cur free free' here here' is_new is_new' b,
  (forall d, free d = free' d) -> (forall d, here d = here' d) ->
  (forall d, is_new d = is_new' d) ->
  decide_view done cur free here is_new b = decide_view done cur free' here' is_new' b.
Proof.
  intros done cur free free' here here' is_new is_new' b Hf Hh Hn.
  unfold decide_view, parent_dir, covered, first_new. rewrite !Hh, !Hn, !Hf. reflexivity.
Qed.

(* ---- the table ---------------------------------------------------------------------------- *)
Definition dir_num (d : dir) : nat := match d with E => 0 | N => 1 | W => 2 | S => 3 end.
Definition of_bits (m : nat) : mask := fun d => Nat.testbit m (dir_num d).

Definition encode (x : decision) : ascii :=
  match x with
  | Stop => "."%char
  | Go m q => ascii_of_nat (97 + 4 * dir_num m + dir_num q)
  end.

Fixpoint string_of (l : list ascii) : string :=
  match l with [] => EmptyString | c :: r => String c (string_of r) end.

Definition range (n : nat) : list nat := seq 0 n.

Definition table (cur : dir) : string :=
  string_of (flat_map (fun here => flat_map (fun free => flat_map (fun is_new =>
    map (fun e => encode (decide_view false cur (of_bits free) (of_bits here) (of_bits is_new) e))
        [false; true]) (range 16)) (range 16)) (range 16)).

Print Assumptions decide_view_ext.

(* ---- golden: the decision table, one string per current quadrant E, N, W, S ----------------- *)
Compute table E.
Compute table N.
Compute table W.
Compute table S.
