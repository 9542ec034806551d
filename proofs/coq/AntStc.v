(* Ant-like STC (paper 002): the parent-from-marks rule and the edge-mark ("box") visited-inference
   rule, on a model of algorithms/stc (ant.hpp, ant.cpp, subcell.hpp).

   Numbering, as in subcell.hpp (everything is arithmetic mod 4):
     directions 0 = E, 1 = N, 2 = W, 3 = S (counter-clockwise); quadrant q of a cell is the sub-cell
     0 = SE, 1 = NE, 2 = NW, 3 = SW. Sub-cell q has its exterior edges in directions q and q - 1;
     the robot walks around its cell q -> q + 1 (one move in direction q + 1); it leaves towards the
     neighbour in direction d from sub-cell d, moving in direction d, and arrives there in sub-cell
     d - 1; coming back it arrives in sub-cell d + 1 of the cell it left.

   The tour through one cell (how the tour marks). A cell x whose parent lies in direction w is
   entered from the parent in sub-cell w + 1 (the parent left from its sub-cell w + 2, towards x).
   Then, for i = 1, 2, 3, 4, the robot stands on s = w + i and leaves it: across side s into the
   child in direction s (when there is one and i < 4; it comes back into s + 1), or on around the
   cell to s + 1 (i < 4), or, at i = 4 (s = w), back across side w to the parent. Every move out of
   a sub-cell marks it (Command.mark is always set), so the robot's i-th decision in x sees the
   marks of exactly s_1 .. s_(i-1), whichever children x has: the moments below are derived from
   `pass`, the list of moves, not assumed. The start cell is the same pass with w = q0 - 1 (the
   virtual parent ant.hpp documents), minus the last move (the robot stops instead), so its moments
   are among these.

   Proved (by exhaustive computation over the finite spaces, `vm_compute`: machine-checked):
     parent_from_marks_is_the_parent   at every moment of every pass (every w, every set of
                                       children), ant_decide's step 1 returns w;
     paper_transition_is_unique        at the moments i = 1..3 the paper's marked/unmarked
                                       transition in a counter-clockwise scan exists, is unique and
                                       is w; at i = 4 (all covered) there is none, and the code's
                                       rule falls back to w = q;
     edge_rule_over_every_pass         for every pass (w, children), every prefix of it (the
                                       robot may be anywhere in the tour when the cell is looked
                                       at) and every state of the four edges only neighbours can
                                       light (bits 8..11), covered_from_edges of the lit edges is
                                       exactly the set of sub-cells the pass has left;
     own_moves_light_only_boxes        a pass lights only bits 0..7 of its own cell's mask;
     paper_edge_rule_over_every_pass   the same with the paper's own rule over its five boxes,
                                       read from the entry sub-cell w + 1: it names exactly the
                                       relative sub-cells 1, 2, 3 the pass has left;
     neighbour_moves_light_only_high_bits  an exterior edge a pass lights (bits 4..7, turn boxes)
                                       is, in the neighbour cell across it, one of bits 8..11: so
                                       the neighbours' passes can light nothing but the bits the
                                       rule is proved to ignore.
   Golden vectors (proofs/golden/AntStc.out), compared with the shipped code by
   tests/proofs/test_ant_golden.cpp for every input: the parent rule's table (current quadrant
   0..3 x here-mask 0..15), covered_from_edges for every 12-bit edge mask, paper_rule for every
   box state and paper_boxes for every single edge and entry sub-cell. *)
From Coq Require Import Arith Bool List Lia.
Import ListNotations.

Definition dadd (d k : nat) : nat := (d + k) mod 4.
Definition bit (m q : nat) : bool := Nat.testbit m q.
Definition setbit (m q : nat) : nat := Nat.lor m (2 ^ q).

(* ---- (a) the parent-from-marks rule, as ant.cpp step 1 ----
   covered = here | (1 << cur); walk back from the robot (cur - 1, cur - 2, cur - 3) to the first
   uncovered sub-cell s: the parent is direction s. All covered: w = cur. *)
Definition parent_from_marks (cur here : nat) : nat :=
  let covered := setbit here cur in
  let s1 := dadd cur 3 in
  let s2 := dadd cur 2 in
  let s3 := dadd cur 1 in
  if negb (bit covered s1) then s1
  else if negb (bit covered s2) then s2
  else if negb (bit covered s3) then s3
  else cur.

(* ---- the pass of the tour through one cell ---- *)
(* A move out of sub-cell s: Walk s goes on around the cell (direction s + 1); Cross s leaves
   across side s (direction s), to a child or to the parent. *)
Inductive move := Walk (s : nat) | Cross (s : nat).
Definition left_of (m : move) : nat := match m with Walk s | Cross s => s end.
Definition direction (m : move) : nat := match m with Walk s => dadd s 1 | Cross s => s end.

(* children: bit r - 1 set when the neighbour in direction w + r (r = 1, 2, 3) is a child. *)
Definition is_child (w children r : nat) : bool := bit children (r - 1).
Definition pass (w children : nat) : list move :=
  map (fun i => let s := dadd w i in
                if Nat.eqb i 4 then Cross s
                else if is_child w children i then Cross s else Walk s)
      [1; 2; 3; 4].

Definition marks (ms : list move) : nat := fold_left (fun m mv => setbit m (left_of mv)) ms 0.

(* The robot's i-th decision in the cell (i = 1..4): where it stands and the marks it sees. *)
Definition moment (w children i : nat) : nat * nat :=
  (left_of (nth (i - 1) (pass w children) (Walk 0)), marks (firstn (i - 1) (pass w children))).

Definition range (n : nat) : list nat := seq 0 n.
Definition all_passes (P : nat -> nat -> bool) : bool :=
  forallb (fun w => forallb (fun c => P w c) (range 8)) (range 4).

(* Each move starts where the previous one leaves the robot in this cell (s_i = w + i): the pass
   is the walk around the cell described above. *)
Lemma pass_walks_around_the_cell :
  all_passes (fun w c => forallb (fun i => Nat.eqb (fst (moment w c i)) (dadd w i)) [1; 2; 3; 4])
  = true.
Proof. vm_compute. reflexivity. Qed.

Theorem parent_from_marks_is_the_parent :
  forall w children i, w < 4 -> children < 8 -> 1 <= i <= 4 ->
    parent_from_marks (fst (moment w children i)) (snd (moment w children i)) = w.
Proof.
  assert (H : all_passes (fun w c => forallb (fun i =>
            Nat.eqb (parent_from_marks (fst (moment w c i)) (snd (moment w c i))) w)
            [1; 2; 3; 4]) = true) by (vm_compute; reflexivity).
  intros w c i Hw Hc Hi.
  unfold all_passes in H. rewrite forallb_forall in H.
  assert (Hw' : In w (range 4)) by (apply in_seq; lia).
  specialize (H w Hw'). rewrite forallb_forall in H.
  assert (Hc' : In c (range 8)) by (apply in_seq; lia).
  specialize (H c Hc'). rewrite forallb_forall in H.
  assert (Hi' : In i [1; 2; 3; 4]) by (simpl; lia).
  specialize (H i Hi'). apply Nat.eqb_eq in H. exact H.
Qed.

(* The paper's reading: scanning counter-clockwise, the sub-cells s with s unmarked and s + 1
   marked (the robot's own sub-cell counts as covered, as in ant.hpp). *)
Definition paper_transitions (cur here : nat) : list nat :=
  let covered := setbit here cur in
  filter (fun s => negb (bit covered s) && bit covered (dadd s 1)) (range 4).

Theorem paper_transition_is_unique :
  all_passes (fun w c =>
    forallb (fun i => match paper_transitions (fst (moment w c i)) (snd (moment w c i)) with
                      | [s] => Nat.eqb s w | _ => false end) [1; 2; 3] &&
    match paper_transitions (fst (moment w c 4)) (snd (moment w c 4)) with
    | [] => true | _ => false end) = true.
Proof. vm_compute. reflexivity. Qed.

(* ---- (b) the edge-mark ("box") rule ----
   The 12 edges of a cell's mask (ant.hpp): sub-cell e's edge in direction d is
     d = e + 2: the interior edge between e and e - 1, bit e (the cross box of e);
     d = e + 1: the interior edge between e and e + 1, bit e + 1 (the cross box of e + 1);
     d = e - 1: its exterior edge, bit 4 + e (the turn box of e);
     d = e:     its other exterior edge, bit 8 + e. *)
Definition edge_bit (e d : nat) : nat :=
  if Nat.eqb d (dadd e 2) then e
  else if Nat.eqb d (dadd e 1) then dadd e 1
  else if Nat.eqb d (dadd e 3) then 4 + e
  else 8 + e.

(* The interior edges are named the same from both sub-cells that share them. *)
Lemma interior_edges_agree :
  forallb (fun e => Nat.eqb (edge_bit e (dadd e 1)) (edge_bit (dadd e 1) (dadd (dadd e 1) 2)))
          (range 4) = true.
Proof. vm_compute. reflexivity. Qed.

(* The robot's back LEDs light the edge behind it: leaving s in direction d lights s's edge in
   direction d + 2. *)
Definition lit (mv : move) : nat := edge_bit (left_of mv) (dadd (direction mv) 2).
Definition lit_edges (ms : list move) : nat := fold_left (fun m mv => setbit m (lit mv)) ms 0.

(* As ant.hpp: covered_from_edges(edges) = (edges | edges >> 4) & 0xF. *)
Definition covered_from_edges (edges : nat) : nat :=
  Nat.land (Nat.lor edges (Nat.shiftr edges 4)) 15.

Theorem edge_rule_over_every_pass :
  all_passes (fun w c => forallb (fun n => forallb (fun nb =>
      let ms := firstn n (pass w c) in
      Nat.eqb (covered_from_edges (Nat.lor (lit_edges ms) (nb * 256))) (marks ms))
    (range 16)) (range 5)) = true.
Proof. vm_compute. reflexivity. Qed.

Theorem own_moves_light_only_boxes :
  all_passes (fun w c => forallb (fun mv => Nat.ltb (lit mv) 8) (pass w c)) = true.
Proof. vm_compute. reflexivity. Qed.

(* Across the exterior edge of sub-cell e in direction d (d = e or d = e - 1) lies the neighbour
   in direction d, whose sub-cell there is d - 1 when e = d and d - 2 when e = d + 1 (the crossing
   rule of subcell.hpp); that sub-cell sees the same edge in direction d + 2. *)
Definition across (e d : nat) : nat := if Nat.eqb e d then dadd d 3 else dadd d 2.

Theorem neighbour_moves_light_only_high_bits :
  forallb (fun e => forallb (fun d =>
      (* the exterior edges of e are d = e and d = e - 1 *)
      if Nat.eqb d e || Nat.eqb d (dadd e 3) then
        let here := edge_bit e d in
        let there := edge_bit (across e d) (dadd d 2) in
        (* one side is a turn box (4..7), the other one of bits 8..11 *)
        ((Nat.leb 4 here && Nat.ltb here 8 && Nat.leb 8 there) ||
         (Nat.leb 4 there && Nat.ltb there 8 && Nat.leb 8 here))
      else true) (range 4)) (range 4) = true.
Proof. vm_compute. reflexivity. Qed.

(* ---- the paper's five boxes ----
   As ant.hpp's paper_boxes / paper_rule: relative to the entry sub-cell `entry` (numbered 0, the
   sub-cells after it 1, 2, 3 counter-clockwise), box 1 = turn(1), box 2 = turn(2), box 3 =
   cross(2), box 4 = cross(3), box 5 = cross(1); the paper's rule reads "1 iff box 1 or 5; 2 iff
   box 2 or 3; 3 iff box 4". Bit k - 1 of the boxes is box k; bit r of the rule's answer is
   relative sub-cell r. *)
Definition paper_boxes (edges entry : nat) : nat :=
  let cross r := if bit edges (dadd entry r) then 1 else 0 in
  let turn r := if bit edges (4 + dadd entry r) then 1 else 0 in
  turn 1 + 2 * turn 2 + 4 * cross 2 + 8 * cross 3 + 16 * cross 1.
Definition paper_rule (boxes : nat) : nat :=
  (if bit boxes 0 || bit boxes 4 then 2 else 0) + (if bit boxes 1 || bit boxes 2 then 4 else 0) +
  (if bit boxes 3 then 8 else 0).

(* The covered sub-cells relative to the entry sub-cell w + 1 (bits 1..3; the entry sub-cell
   itself, bit 0, is what the rule does not answer). *)
Definition relative (m entry : nat) : nat :=
  (if bit m (dadd entry 1) then 2 else 0) + (if bit m (dadd entry 2) then 4 else 0) +
  (if bit m (dadd entry 3) then 8 else 0).

Theorem paper_edge_rule_over_every_pass :
  all_passes (fun w c => forallb (fun n => forallb (fun nb =>
      let ms := firstn n (pass w c) in
      let entry := dadd w 1 in
      Nat.eqb (paper_rule (paper_boxes (Nat.lor (lit_edges ms) (nb * 256)) entry))
              (relative (marks ms) entry))
    (range 16)) (range 5)) = true.
Proof. vm_compute. reflexivity. Qed.

Print Assumptions parent_from_marks_is_the_parent.
Print Assumptions paper_transition_is_unique.
Print Assumptions edge_rule_over_every_pass.
Print Assumptions neighbour_moves_light_only_high_bits.
Print Assumptions paper_edge_rule_over_every_pass.

(* ---- golden vectors ---- *)
(* 1. The parent rule's full table: entry 16 * cur + here. *)
Compute flat_map (fun cur => map (fun here => parent_from_marks cur here) (range 16)) (range 4).
(* 2. covered_from_edges for every 12-bit edge mask. *)
Compute map covered_from_edges (range 4096).
(* 3. The paper's rule over its five boxes, every box state 0..31. *)
Compute map paper_rule (range 32).
(* 4. paper_boxes of each single lit edge (bit b, b = 0..11) for each entry sub-cell: entry 12 *
   entry + b. paper_boxes is an OR of single-edge contributions, so these and that OR determine it
   on every mask (the C++ test checks the OR on every mask too). *)
Compute flat_map (fun entry => map (fun b => paper_boxes (2 ^ b) entry) (range 12)) (range 4).
