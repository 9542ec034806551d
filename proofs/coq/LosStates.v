(* Line-of-sight cell states (paper 001, Section III.B, Table 1) on a model of the update rules.

   States, in the order of antkit::los::CellState (their numbers are the golden file's):
     F = 0 "Fresh", S = 1 free by scanning, LOS = 2 free by line of sight only,
     S_LOS = 3 free by scanning and line of sight, NLOS = 4 potentially occupied, O = 5 occupied.
   Events on one cell:
     ScanFree      a robot scanned the cell and found it free (or found the partner robot there)
     ScanObstacle  a robot scanned the cell and found an obstacle
     Seen          the cell lies on the line between two robots that see each other
     NotSeen       the cell lies on that line and the robots do not see each other
   Rules (the paper's numbers):
     1 ScanFree: F, NLOS -> S        2 ScanFree: LOS -> S_LOS
     3.1 Seen: F, NLOS -> LOS        3.2 Seen: S -> S_LOS
     4 NotSeen: F -> NLOS            5 ScanObstacle: F, NLOS -> O
   Where the paper is silent (and as algorithms/los/src/exploration_map.cpp does): every other
   (state, event) pair leaves the state as it is; in particular an observation that contradicts
   what is known (a known-free cell scanned as an obstacle) is ignored. Rule 5 says O holds "until
   the end of the exploration", so O absorbs everything.

   Proved:
     transitions_are_monotone   every event moves a cell up the order F < NLOS < {S, LOS, O},
                                S < S_LOS, LOS < S_LOS (at_or_below), or leaves it;
     issue_chains_are_in_order  the issue's chains F->NLOS->LOS->S_LOS, F->S->S_LOS, F->O are
                                chains of that order, each step made by some event;
     marked_free_is_free        on a map, given sound sensing (a scan reports the truth, and two
                                robots see each other only if every cell on the line between them
                                is free), every cell marked S, LOS or S_LOS is free and every cell
                                marked O is occupied, after any sequence of scans and sweeps;
     rule6_explored_stays_explored  an explored cell stays explored.
   Golden vectors (proofs/golden/LosStates.out): the transition table (6 states x 4 events) and
   the order (6 x 6), compared with the shipped code by tests/proofs/test_los_golden.cpp. *)
From Coq Require Import Bool List Arith Lia.
Import ListNotations.

Inductive state := F | S | LOS | S_LOS | NLOS | O.
Inductive event := ScanFree | ScanObstacle | Seen | NotSeen.

Definition step (e : event) (s : state) : state :=
  match e, s with
  | ScanFree, (F | NLOS) => S
  | ScanFree, LOS => S_LOS
  | ScanObstacle, (F | NLOS) => O
  | Seen, (F | NLOS) => LOS
  | Seen, S => S_LOS
  | NotSeen, F => NLOS
  | _, s => s
  end.

(* The partial order, reflexive: F < NLOS < {S, LOS, O}, S < S_LOS, LOS < S_LOS. *)
Definition at_or_below (a b : state) : bool :=
  match a, b with
  | F, _ => true
  | NLOS, (NLOS | S | LOS | O | S_LOS) => true
  | S, (S | S_LOS) => true
  | LOS, (LOS | S_LOS) => true
  | S_LOS, S_LOS => true
  | O, O => true
  | _, _ => false
  end.

Definition known_free (s : state) : bool :=
  match s with S | LOS | S_LOS => true | _ => false end.
Definition explored (s : state) : bool :=
  match s with S | LOS | S_LOS | O => true | _ => false end.

Lemma at_or_below_refl : forall s, at_or_below s s = true.
Proof. destruct s; reflexivity. Qed.

Lemma at_or_below_trans : forall a b c,
  at_or_below a b = true -> at_or_below b c = true -> at_or_below a c = true.
Proof. destruct a, b, c; simpl; congruence. Qed.

Lemma at_or_below_antisym : forall a b,
  at_or_below a b = true -> at_or_below b a = true -> a = b.
Proof. destruct a, b; simpl; congruence. Qed.

Theorem transitions_are_monotone : forall e s, at_or_below s (step e s) = true.
Proof. destruct e, s; reflexivity. Qed.

Theorem issue_chains_are_in_order :
  step NotSeen F = NLOS /\ step Seen NLOS = LOS /\ step ScanFree LOS = S_LOS /\
  step ScanFree F = S /\ step Seen S = S_LOS /\ step ScanObstacle F = O.
Proof. repeat split. Qed.

Theorem rule6_explored_stays_explored : forall e s,
  explored s = true -> explored (step e s) = true.
Proof. destruct e, s; simpl; congruence. Qed.

(* ---- Maps and sound sensing ---- *)

Definition cell := (nat * nat)%type.
Definition cell_eqb (a b : cell) : bool := Nat.eqb (fst a) (fst b) && Nat.eqb (snd a) (snd b).
Definition grid := cell -> state.
Definition fresh_map : grid := fun _ => F.

(* What happens to a grid: a scan of one cell (obstacle or not), or a sweep of the line between
   two robots (the cells on it, and whether the robots saw each other). *)
Inductive action :=
  | Scan (c : cell) (obstacle : bool)
  | Sweep (line : list cell) (seen : bool).

Definition update (m : grid) (c : cell) (e : event) : grid :=
  fun d => if cell_eqb d c then step e (m d) else m d.

Definition apply (m : grid) (a : action) : grid :=
  match a with
  | Scan c obstacle => update m c (if obstacle then ScanObstacle else ScanFree)
  | Sweep line seen =>
      fun d => if existsb (cell_eqb d) line then step (if seen then Seen else NotSeen) (m d)
               else m d
  end.

Definition run (acts : list action) : grid := fold_left apply acts fresh_map.

Section Soundness.
  (* The world: which cells hold an obstacle. *)
  Variable occupied : cell -> bool.

  (* Sound sensing: a scan reports the truth; two robots see each other only when every cell on
     the line between them is free (the line-of-sight test never sees through an obstacle). *)
  Definition sound (a : action) : Prop :=
    match a with
    | Scan c obstacle => obstacle = occupied c
    | Sweep line seen => seen = true -> forall d, In d line -> occupied d = false
    end.

  Definition truthful (m : grid) : Prop :=
    forall d, (known_free (m d) = true -> occupied d = false) /\
              (m d = O -> occupied d = true).

  Lemma cell_eqb_true : forall a b, cell_eqb a b = true -> a = b.
  Proof.
    intros [a1 a2] [b1 b2]. unfold cell_eqb. simpl. rewrite andb_true_iff.
    intros [H1 H2]. apply Nat.eqb_eq in H1. apply Nat.eqb_eq in H2. subst. reflexivity.
  Qed.

  Lemma apply_truthful : forall m a, truthful m -> sound a -> truthful (apply m a).
  Proof.
    intros m a Hm Ha d. destruct a as [c obstacle | line seen]; simpl in *.
    - unfold update. destruct (cell_eqb d c) eqn:Hdc; [| apply Hm].
      apply cell_eqb_true in Hdc. subst d. destruct (Hm c) as [Hf Ho].
      destruct obstacle, (m c) eqn:Hs; simpl; split; intros H; try discriminate;
        auto; congruence.
    - destruct (existsb (cell_eqb d) line) eqn:Hin; [| apply Hm].
      destruct (Hm d) as [Hf Ho].
      assert (Hline : seen = true -> occupied d = false).
      { intros Hs. apply Ha; [exact Hs |].
        apply existsb_exists in Hin. destruct Hin as [x [Hx Hdx]].
        apply cell_eqb_true in Hdx. subst. exact Hx. }
      destruct seen, (m d) eqn:Hs; simpl; split; intros H; try discriminate; auto.
  Qed.

  Theorem marked_free_is_free : forall acts,
    Forall sound acts -> truthful (run acts).
  Proof.
    intros acts Hs. unfold run.
    assert (H0 : truthful fresh_map) by (intros d; split; discriminate).
    revert H0. generalize fresh_map. induction Hs as [| a acts Ha Hs IH]; intros m Hm.
    - exact Hm.
    - simpl. apply IH. apply apply_truthful; assumption.
  Qed.
End Soundness.

(* Every cell of a map moves up the order, whatever the action, sound or not. *)
Theorem map_transitions_are_monotone : forall m a d, at_or_below (m d) (apply m a d) = true.
Proof.
  intros m [c obstacle | line seen] d; simpl.
  - unfold update. destruct (cell_eqb d c); [apply transitions_are_monotone | apply at_or_below_refl].
  - destruct (existsb (cell_eqb d) line); [apply transitions_are_monotone | apply at_or_below_refl].
Qed.

(* ---- Golden vectors ---- *)
Definition code (s : state) : nat :=
  match s with F => 0 | S => 1 | LOS => 2 | S_LOS => 3 | NLOS => 4 | O => 5 end.
Definition all_states := [F; S; LOS; S_LOS; NLOS; O].
Definition all_events := [ScanFree; ScanObstacle; Seen; NotSeen].

(* Row per state (in code order), column per event (ScanFree, ScanObstacle, Seen, NotSeen). *)
Definition transition_table : list (list nat) :=
  map (fun s => map (fun e => code (step e s)) all_events) all_states.
(* Row a, column b: 1 when a is at or below b. *)
Definition order_table : list (list nat) :=
  map (fun a => map (fun b => if at_or_below a b then 1 else 0) all_states) all_states.

Compute transition_table.
Compute order_table.

Print Assumptions transitions_are_monotone.
Print Assumptions marked_free_is_free.
Print Assumptions map_transitions_are_monotone.
