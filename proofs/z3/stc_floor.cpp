// Z3 proof: one step of the shipped STC floor (antkit::stc::BasicFloor, floor.hpp: the Floor that
// StcWorld, the C API and the Cortex-M image step), on EVERY map up to kMaxGridSide, does what the
// world step of proofs/coq/AntStcWorld.v does to the abstract state, and keeps the floor's
// representation invariant (issue 41).
//
// A proof about the shipped source: Floor is BasicFloor<FloorMachine>; here the very same template
// is instantiated as BasicFloor<FloorZ3>, with Z3 bit-vectors for its integers (int32 coordinates,
// size_t indices that wrap modulo 2^64, uint8/uint16 array words, int64 counts) and Z3 arrays for
// its memory (z3_memory.hpp: bytes or 16-bit words indexed by 64-bit words; every read and write
// the code makes records the obligation that its index is below the array's length, the length
// the shipped basic_floor_size gives). Its `if`s on symbolic values fork the run (for_each_path):
// every path of observe_marks / observe_edges + apply is checked.
//
// What is symbolic: the map's width and height in [0, kMaxGridSide] (any parity: an odd last row or
// column is outside the cell area), the whole contents of free_bits (so every map, partly free
// cells included), of entered_bits, marks and edges (any state satisfying the invariant below), the
// robot's position (any sub-cell of a free cell), the covered and repeat counts, and a probe cell,
// probe sub-cell and probe edge bit that stand for "every cell / sub-cell / bit" (a claim proved
// for a free probe holds for all of them). What is enumerated: the command (Stop, and each of the
// four moves with and without its mark: every Command there is) and the marker (sub-cell marks, lit
// edges). The decision itself is not here: it is proved equal to the Coq `decide` on its whole
// domain by proof.tie.ant_decide.
//
// The abstract state (AntStcWorld.v): the free cells (a cell is free iff its four sub-cells are),
// marks M(c, q) (`ant`) or lit edges Ed(c, b) (`ant-edge`, b < 12), the robot's sub-cell; and the
// floor's own sub-cells entered E(s) with the covered and repeat counts. The representation, with
// the documented layout (floor.hpp), written here independently of floor.hpp's private functions:
//   cells_x = width / 2, cells_y = height / 2; the cell arrays have a one-cell border:
//     idx(c)  = (c.y + 1) * (cells_x + 2) + (c.x + 1)    for c in [-1, cells_x] x [-1, cells_y]
//   sub-cell bits: k(s) = s.y * 2 cells_x + s.x, bit k & 7 of byte k >> 3, for s in the cell area
//   F(s)   = free_bits' bit k(s); cell_free(c) = c in the grid and F of its four sub-cells
//   M(c,q) = bit q of marks[idx(c)]; Ed(c,b) = bit b of edges[idx(c)]; E(s) = entered_bits' bit
//   k(s)
// The invariant Inv(c), for every c of the bordered grid:
//   in the grid: bit 7 of marks[idx(c)] is cell_free(c), bits 4-6 are 0, bits 0-3 are 0 unless c
//                is free (marks are left only in free cells); bit 15 of edges[idx(c)] is
//                cell_free(c), bits 12-14 are 0;
//   border:      marks[idx(c)] = edges[idx(c)] = 0.
// and the robot stands on a sub-cell of the cell area whose cell is free.
//
// Claims (each per command and per path; the probe makes each "for every cell / sub-cell"):
//   stc_floor.marks.observe / edges.observe   the observation is the model's: `here` is M(cur)
//       (Ed(cur)), free_neighbours bit d is cell_free(step(cur, d)) and no other bit, neighbour d
//       is M(n) when n is free and 0 otherwise (the model's `nbm`); for edges, neighbour d is
//       Ed(n) for a neighbour in the grid, 0 for a border one (the model reads any neighbour's
//       edges, and `decide` reads only free ones: decide_ext in AntStcWorld.v); every read in
//       bounds.
//   stc_floor.<marker>.<command>.path<k>: refusal / move   apply moves exactly when the target
//       sub-cell is in the cell area and free (so Stop, a move off the area and a move into a
//       blocked sub-cell are refused, and then nothing changes: position, counts, every array);
//       when the target's cell is free (the model moves) the floor moves; when the target sub-cell
//       is not free, the model refuses too.
//   ...: marks / edges   after a move, for every cell c: M'(c) = M(c) plus bit quadrant(pos) of the
//       robot's old cell when the command marks (Ed' = Ed plus what AntStcWorld.v's light_edge
//       lights, restricted to the grid: the floor never lights the border), and Inv'(c) holds;
//       free_bits is unchanged, and the other marker's array too.
//   ...: entered   E'(s) = E(s) or s = target for every sub-cell s of the area, covered' = covered
//       + 1 and repeats' = repeats if the target was not entered before, else repeats' = repeats +
//       1 (so, from reset's covered = 1, E = {start}, by induction covered = |E| and repeats =
//       moves
//       + 1 - |E|).
//   Every array index the code reads or writes on the path is below its array's length, and no
//   signed operation of the code overflows (z3_int.hpp's obligations).
// By induction over the moves (reset establishes the invariant: it is the loop in reset(); the
// tie checks it on small maps), every step of a run does what the model's step does, as long as
// the model moves; AntStcWorld.v proves the model never refuses. The one place the two differ: a
// move into a free sub-cell of a cell that is not free is refused by the model and made by the
// floor (stc_floor.teeth.partly_free_divergence shows it); the controller never asks for it
// (AntStcWorld.v: every run stops, never refused), so on runs they agree.
//
// How the step claims are decided (StepChecker below). The floor's indices are products of two
// unknowns (row times stride), 64-bit multipliers that the bit-vector solver cannot reason about
// in minutes. In the step claims every such product is replaced by mul[a][b], mul an unknown
// function: equal factors still give equal products, and nothing else is known of them but what
// the domain states. A claim so proved holds for every function mul, multiplication included: the
// abstraction only forgets. What the step needs of the products is stated in the domain as
// instances, at the cells and sub-cells the step touches and the probes, of these lemmas:
//   stc_floor.index.*_injective / *_bounded / cell_index_neighbours: distinct cells of the bordered
//       grid have distinct idx, below cells = (cells_x + 2)(cells_y + 2); the neighbours of a cell
//       are 1 and cells_x + 2 entries away; distinct sub-cells of the area have distinct k, below
//       4 cells_x cells_y (and 4 cells_x cells_y <= 8 bit_bytes, stc_floor.floor_size.*);
//       proved over Z3's mathematical integers (nonlinear arithmetic);
//   stc_floor.index.no_wrap: every product and sum of those bit-vector terms is exact (no wrap
//       modulo 2^64, no int32 overflow) for maps up to kMaxGridSide, so the bit-vector terms are
//       the integers of the lemmas. One step is on paper: a bit-vector term none of whose
//       operations wraps equals its integer;
//   stc_floor.cell_free_covers_its_sub_cells: a free cell's sub-cells are free (in the step
//       claims, cell freedom is an unknown predicate with this property; the definition, four
//       reads of free_bits, is used here).
// Not vacuous: stc_floor.context_is_satisfiable evaluates the whole domain (both markers'
// invariants, every target's lemma instances, the session's facts) in a concrete model, a 4 x 4
// map; each path's claims are checked only if the path can happen under the (abstracted) domain,
// the others are reported as skipped (an `if` on a constant also forks the run, so every apply
// has a few). Teeth: stc_floor.teeth.* are wrong claims Z3 must refute, and the source mutants of
// floor.hpp (ctest proof.teeth.floor_mutant.*, proofs/CMakeLists.txt) must make this proof fail.
// --first-failure stops at the first failed claim, and --marker marks|edges checks only that
// marker's step (the lemmas, the context and the teeth still run): both for the source mutants,
// so that a slip in one marker's code is found without proving the other's step first.
#include "prove.hpp"
#include "z3_memory.hpp"

#include <antkit/kernel/grid.hpp>
#include <antkit/stc/floor.hpp>
#include <array>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

using namespace antkit::proofs;
namespace stc = antkit::stc;
using antkit::kernel::kMaxGridSide;

namespace {

// --first-failure: stop at the first claim that fails (the source-mutant tests, which need one).
bool first_failure_ends = false;

struct ZSubCell {
  I32 x, y;
};
struct ZShape {
  I32 cells_x, cells_y;
};
struct ZStorage {
  MemoryRef<8> free_bits, entered_bits, marks;
  MemoryRef<16> edges;
};
struct ZMarkObservation {
  U8 free_neighbours;
  U8 here;
  std::array<U8, 4> neighbour;
};
struct ZEdgeObservation {
  U8 free_neighbours;
  U16 here;
  std::array<U16, 4> neighbour;
};

// The floor's policy over Z3 terms (floor.hpp, FloorMachine, lists what a policy gives).
struct FloorZ3 {
  using Bool = antkit::proofs::Bool;
  using Coord = I32;
  using Index = U64;
  using Byte = U8;
  using Word = U16;
  using Bits = U32;
  using Count = I64;
  using SubCell = ZSubCell;
  using Shape = ZShape;
  using Storage = ZStorage;
  using MarkObservation = ZMarkObservation;
  using EdgeObservation = ZEdgeObservation;
};
using ZFloor = stc::BasicFloor<FloorZ3>;

Bool implies(const Bool& a, const Bool& b) {
  return !a || b;
}
Bool same(const ZSubCell& a, const ZSubCell& b) {
  return a.x == b.x && a.y == b.y;
}
// One step in direction d (E, N = y - 1, W, S), built as floor.hpp builds it (the same terms).
ZSubCell step(const ZSubCell& c, int d) {
  static constexpr int dx[4] = {1, 0, -1, 0}, dy[4] = {0, -1, 0, 1};
  return {c.x + I32(dx[d]), c.y + I32(dy[d])};
}

// The documented layout and the abstraction of the module comment.
struct Layout {
  I32 cx, cy;    // cells_x, cells_y (basic_floor_size's terms)
  U64 cells;     // basic_floor_size's length of the cell arrays
  U64 bit_bytes; // and of the bit arrays
  U64 area_bits; // 4 cells_x cells_y, as basic_floor_size forms it
  Memory<8>* free_bits;
  z3::expr free_cells; // cell_free as an array (x, y) -> bit; see cell_free below

  Bool in_grid(const ZSubCell& c) const {
    return I32(0) <= c.x && c.x < cx && I32(0) <= c.y && c.y < cy;
  }
  Bool bordered(const ZSubCell& c) const {
    return I32(-1) <= c.x && c.x <= cx && I32(-1) <= c.y && c.y <= cy;
  }
  Bool in_area(const ZSubCell& s) const {
    return I32(0) <= s.x && s.x < I32(2) * cx && I32(0) <= s.y && s.y < I32(2) * cy;
  }
  U64 stride() const { return U64(cx) + 2; }
  U64 idx(const ZSubCell& c) const { return U64(c.y + 1) * stride() + U64(c.x + 1); }
  U64 k(const ZSubCell& s) const { return U64(s.y) * U64(I32(2) * cx) + U64(s.x); }
  Bool bit8(const Memory<8>& m, const ZSubCell& s) const {
    const U64 i = k(s);
    return ((m.peek(i >> 3) >> U8(i & U64(7))) & U8(1)) == U8(1);
  }
  Bool free_sub(const ZSubCell& s) const { return in_area(s) && bit8(*free_bits, s); }
  ZSubCell sub(const ZSubCell& c, int q) const {
    static constexpr int ox[4] = {1, 1, 0, 0}, oy[4] = {1, 0, 0, 1}; // SE, NE, NW, SW
    return {I32(2) * c.x + I32(ox[q]), I32(2) * c.y + I32(oy[q])};
  }
  // A cell is free when it is in the grid and its four sub-cells are free.
  Bool cell_free_by_definition(const ZSubCell& c) const {
    return in_grid(c) && free_sub(sub(c, 0)) && free_sub(sub(c, 1)) && free_sub(sub(c, 2)) &&
           free_sub(sub(c, 3));
  }
  // In the step claims the cells' freedom is an unknown predicate (an array of bits) on the grid,
  // constrained only by the instances of stc_floor.cell_free_covers_its_sub_cells they need: so
  // they are proved for every predicate with that property, the definition's included. (Reading
  // the definition costs each claim four more 64-bit multipliers per cell.)
  Bool cell_free(const ZSubCell& c) const {
    return in_grid(c) && Bool(z3::select(free_cells, z3::concat(c.x.expr(), c.y.expr())) ==
                              free_cells.ctx().bv_val(1, 1));
  }
  static ZSubCell cell_of(const ZSubCell& s) { return {s.x >> 1, s.y >> 1}; }
  // AntStcWorld.v's quadrant_of: odd x, odd y -> E (SE) 0; odd, even -> N (NE) 1; even, even ->
  // W (NW) 2; even, odd -> S (SW) 3.
  static Bool odd(const I32& v) { return (v & I32(1)) == I32(1); }
  static U8 quadrant_mask(const ZSubCell& s) {
    return select(odd(s.x), select(odd(s.y), U8(1), U8(2)), select(odd(s.y), U8(8), U8(4)));
  }
  static Bool quadrant_is(const ZSubCell& s, int q) {
    const Bool ox = odd(s.x), oy = odd(s.y);
    switch (q) {
    case 0:
      return ox && oy;
    case 1:
      return ox && !oy;
    case 2:
      return !ox && !oy;
    default:
      return !ox && oy;
    }
  }

  // Inv(c) for the marks array and for the edges array.
  Bool inv_marks(const Memory<8>& marks, const ZSubCell& c) const {
    const U8 v = marks.peek(idx(c));
    const Bool free = cell_free(c);
    return implies(in_grid(c), (((v >> 7) == U8(1)) == free) && (v & U8(0x70)) == U8(0) &&
                                   implies(!free, (v & U8(0x0F)) == U8(0))) &&
           implies(bordered(c) && !in_grid(c), v == U8(0));
  }
  Bool inv_edges(const Memory<16>& edges, const ZSubCell& c) const {
    const U16 v = edges.peek(idx(c));
    return implies(in_grid(c),
                   (((v >> 15) == U16(1)) == cell_free(c)) && (v & U16(0x7000)) == U16(0)) &&
           implies(bordered(c) && !in_grid(c), v == U16(0));
  }
  Bool entered(const Memory<8>& e, const ZSubCell& s) const { return bit8(e, s); }

  // The index facts (module comment), as implications whose hypotheses say where they hold.
  Bool idx_bounded(const ZSubCell& a) const { return implies(bordered(a), idx(a) < cells); }
  Bool idx_distinct(const ZSubCell& a, const ZSubCell& b) const {
    return implies(bordered(a) && bordered(b) && !same(a, b), idx(a) != idx(b));
  }
  // The neighbour of a grid cell in direction d is one entry (E, W) or one row of cells_x + 2
  // entries (N, S) away; stated without negative numbers: idx(E) = idx + 1, idx(N) + stride = idx,
  // idx(W) + 1 = idx, idx(S) = idx + stride.
  Bool idx_neighbour(const ZSubCell& c, int d) const {
    const U64 here = idx(c), there = idx(step(c, d));
    Bool rel(false);
    switch (d) {
    case 0:
      rel = there == here + U64(1);
      break;
    case 1:
      rel = there + stride() == here;
      break;
    case 2:
      rel = there + U64(1) == here;
      break;
    default:
      rel = there == here + stride();
      break;
    }
    return implies(in_grid(c), rel);
  }
  Bool k_bounded(const ZSubCell& s) const { return implies(in_area(s), k(s) < area_bits); }
  Bool k_distinct(const ZSubCell& s, const ZSubCell& t) const {
    return implies(in_area(s) && in_area(t) && !same(s, t), k(s) != k(t));
  }
  Bool free_cell_free_sub(const ZSubCell& t) const {
    return implies(in_area(t) && cell_free(cell_of(t)), free_sub(t));
  }
};

// ---- the step claims' checker -----------------------------------------------------------------
//
// Prover::claim (prove.hpp), with one change that makes the step's claims decidable in seconds:
// every product of two unknowns (a 64-bit multiplier: the rows of idx and k) is replaced by an
// unknown, the same unknown for the same term. A claim proved for every value of those unknowns,
// under the index facts the domain states about them (each an instance of a lemma proved above
// over the real products), holds in particular for the real products: the abstraction only
// forgets. Like Prover::claim, a claim is checked under the domain, the path condition and the
// session's facts, together with every obligation the code recorded since the last claim.
class StepChecker {
public:
  StepChecker(Session& s, const z3::expr& domain) : s_(s), domain_(domain) {}

  // Whether the path can happen (under the abstraction, which only makes more paths possible).
  bool feasible() {
    z3::solver solver(s_.ctx(), "QF_ABV");
    solver.add(abstract(context()));
    // Either answer may come from the proof cache (proof_cache.hpp): a path taken or pruned.
    return ProofCache::global().check(solver, "QF_ABV", ProofCache::Keep::Either) != z3::unsat;
  }

  bool claim(const std::string& name, const Bool& c) {
    const auto t0 = std::chrono::steady_clock::now();
    z3::expr all = s_.ctx().bool_val(true);
    const std::vector<Session::Obligation> obligations = s_.obligations();
    for (const auto& ob : obligations) all = all && ob.holds;
    s_.clear_obligations();
    bool cached = false;
    const z3::check_result r = check(all && c.expr(), &cached);
    const auto ms =
        std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - t0)
            .count();
    if (r == z3::unsat) {
      ++proved_;
      std::cout << "proved   " << name << " (and " << obligations.size()
                << " obligations of the code; " << ms << " ms" << (cached ? ", cached" : "") << ")"
                << std::endl;
      return true;
    }
    ++failures_;
    std::cout << (r == z3::unknown ? "UNKNOWN  " : "FAILED   ") << name << "\n";
    for (const auto& ob : obligations)
      if (check(ob.holds) != z3::unsat) std::cout << "  fails: the obligation " << ob.what << "\n";
    if (check(c.expr()) != z3::unsat) std::cout << "  fails: the claim itself\n";
    print_model();
    if (first_failure_ends) std::exit(1);
    return false;
  }

  void set_domain(const z3::expr& d) { domain_ = d; }

  // Each pending obligation of the code checked as a claim of its own.
  void obligations_one_by_one(const std::string& name) {
    const std::vector<Session::Obligation> obligations = s_.obligations();
    s_.clear_obligations();
    for (const auto& ob : obligations)
      claim(name + " [no undefined behaviour: " + ob.what + "]", Bool(ob.holds));
  }
  int proved() const { return proved_; }
  int failures() const { return failures_; }

private:
  z3::expr context() const {
    z3::expr f = domain_;
    for (const auto& p : s_.path()) f = f && p;
    for (const auto& x : s_.facts()) f = f && x;
    return f;
  }
  // A proved goal's answer may come from the proof cache (proof_cache.hpp); a failing one is
  // solved here.
  z3::check_result check(const z3::expr& goal, bool* cached = nullptr) {
    solver_.emplace(s_.ctx(), "QF_ABV");
    solver_->add(abstract(context() && !goal));
    // STC_FLOOR_DUMP=dir writes every query as SMT-LIB 2 (to study a slow claim elsewhere).
    if (const char* dir = std::getenv("STC_FLOOR_DUMP")) {
      std::ofstream out(std::string(dir) + "/q" + std::to_string(dumped_++) + ".smt2");
      out << solver_->to_smt2();
    }
    return ProofCache::global().check(*solver_, "QF_ABV", ProofCache::Keep::Unsat, cached);
  }
  int dumped_ = 0;
  void print_model() {
    if (!solver_ || solver_->check() != z3::sat) return;
    const z3::model m = solver_->get_model();
    std::cout << "  counterexample:";
    for (unsigned i = 0; i < m.size(); ++i) {
      const z3::func_decl d = m[i];
      if (d.arity() != 0 || !d.range().is_bv()) continue;
      const z3::expr v = m.get_const_interp(d);
      std::cout << " " << d.name().str() << "="
                << m.eval(z3::expr(s_.ctx(), Z3_mk_bv2int(s_.ctx(), v, true)), true);
    }
    std::cout << "\n";
  }

  // Each product of two non-constants a * b in e replaced by mul[a][b], mul an unknown function
  // (an array of arrays: the QF_ABV solver has no uninterpreted functions): equal factors still
  // give equal products, nothing else is known of them but the facts the domain states.
  z3::expr abstract(const z3::expr& e) {
    z3::expr_vector from(s_.ctx()), to(s_.ctx());
    std::unordered_set<unsigned> seen;
    std::vector<z3::expr> todo{e};
    while (!todo.empty()) {
      const z3::expr t = todo.back();
      todo.pop_back();
      if (!t.is_app() || !seen.insert(Z3_get_ast_id(s_.ctx(), t)).second) continue;
      if (t.decl().decl_kind() == Z3_OP_BMUL && t.num_args() == 2 && !constant(t.arg(0)) &&
          !constant(t.arg(1))) {
        if (first_product(t.arg(0)) || first_product(t.arg(1))) {
          std::cerr << "stc_floor: a product of products, which the abstraction does not handle\n";
          std::abort();
        }
        from.push_back(t);
        to.push_back(z3::select(z3::select(mul(t.get_sort().bv_size()), t.arg(0)), t.arg(1)));
        continue;
      }
      for (unsigned i = 0; i < t.num_args(); ++i) todo.push_back(t.arg(i));
    }
    z3::expr r = e;
    return from.empty() ? r : r.substitute(from, to);
  }
  // A factor that is a constant (a numeral, or a sign extension of one: z3_int.hpp's overflow
  // checks multiply those): a multiplication by a constant is left to the solver.
  static bool constant(const z3::expr& e) { return e.is_numeral() || e.simplify().is_numeral(); }
  z3::expr mul(unsigned bits) {
    auto it = mul_.find(bits);
    if (it == mul_.end()) {
      z3::context& c = s_.ctx();
      const z3::sort w = c.bv_sort(bits);
      it = mul_.emplace(bits, c.constant(("mul!" + std::to_string(bits)).c_str(),
                                         c.array_sort(w, c.array_sort(w, w))))
               .first;
    }
    return it->second;
  }

  Session& s_;
  z3::expr domain_;
  std::unordered_map<unsigned, z3::expr> mul_;
  std::optional<z3::solver> solver_;
  int proved_ = 0;
  int failures_ = 0;
};

// ---- the lemmas the step claims use ---------------------------------------------------------

z3::expr no_wrap_mul(const U64& a, const U64& b) {
  z3::context& c = a.expr().ctx();
  return z3::expr(c, Z3_mk_bvmul_no_overflow(c, a.expr(), b.expr(), false));
}
z3::expr no_wrap_add(const U64& a, const U64& b) {
  z3::context& c = a.expr().ctx();
  return z3::expr(c, Z3_mk_bvadd_no_overflow(c, a.expr(), b.expr(), false));
}

// Over the integers: for cx, cy >= 0 and S = cx + 2, idx(x, y) = (y + 1) S + (x + 1) is
// injective and in [0, S (cy + 2)) on [-1, cx] x [-1, cy], and its neighbours are 1 and S away;
// k(x, y) = y (2 cx) + x is injective and in [0, 4 cx cy) on [0, 2 cx) x [0, 2 cy).
void index_lemmas_over_integers(Prover& p, z3::context& c) {
  const z3::expr cx = c.int_const("icx"), cy = c.int_const("icy");
  const z3::expr ax = c.int_const("iax"), ay = c.int_const("iay"), bx = c.int_const("ibx"),
                 by = c.int_const("iby");
  const z3::expr S = cx + 2;
  const z3::expr grid = cx >= 0 && cy >= 0;
  const auto bordered = [&](const z3::expr& x, const z3::expr& y) {
    return -1 <= x && x <= cx && -1 <= y && y <= cy;
  };
  const auto area = [&](const z3::expr& x, const z3::expr& y) {
    return 0 <= x && x < 2 * cx && 0 <= y && y < 2 * cy;
  };
  const auto idx = [&](const z3::expr& x, const z3::expr& y) { return (y + 1) * S + (x + 1); };
  const auto k = [&](const z3::expr& x, const z3::expr& y) { return y * (2 * cx) + x; };
  p.claim_over_integers(
      "stc_floor.index.cell_index_injective (over the integers)",
      z3::implies(grid && bordered(ax, ay) && bordered(bx, by) && idx(ax, ay) == idx(bx, by),
                  ax == bx && ay == by));
  p.claim_over_integers(
      "stc_floor.index.cell_index_bounded (over the integers)",
      z3::implies(grid && bordered(ax, ay), 0 <= idx(ax, ay) && idx(ax, ay) < S * (cy + 2)));
  p.claim_over_integers("stc_floor.index.cell_index_neighbours (over the integers)",
                        idx(ax + 1, ay) == idx(ax, ay) + 1 && idx(ax, ay - 1) + S == idx(ax, ay) &&
                            idx(ax - 1, ay) + 1 == idx(ax, ay) &&
                            idx(ax, ay + 1) == idx(ax, ay) + S);
  p.claim_over_integers("stc_floor.index.bit_index_injective (over the integers)",
                        z3::implies(grid && area(ax, ay) && area(bx, by) && k(ax, ay) == k(bx, by),
                                    ax == bx && ay == by));
  p.claim_over_integers(
      "stc_floor.index.bit_index_bounded (over the integers)",
      z3::implies(grid && area(ax, ay), 0 <= k(ax, ay) && k(ax, ay) < (4 * cx) * cy));
}

std::string command_name(const stc::Command& c) {
  static const char* names[5] = {"east", "north", "west", "south", "stop"};
  return std::string(names[static_cast<int>(c.move)]) + (c.mark ? "+mark" : "");
}

} // namespace

int main(int argc, char** argv) {
  std::optional<stc::Marker> only_marker;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i], value = i + 1 < argc ? argv[i + 1] : "";
    if (arg == "--first-failure") {
      first_failure_ends = true;
    } else if (arg == "--marker" && (value == "marks" || value == "edges")) {
      only_marker = value == "edges" ? stc::Marker::Edge : stc::Marker::WholeSubCell;
      ++i;
    } else {
      std::cerr << "usage: " << argv[0] << " [--first-failure] [--marker marks|edges]\n";
      return 2;
    }
  }
  Session s;
  Prover p(s);
  z3::context& ctx = s.ctx();

  const I32 W = I32::var("width"), H = I32::var("height");
  const Bool sizes = I32(0) <= W && W <= I32(kMaxGridSide) && I32(0) <= H && H <= I32(kMaxGridSide);
  p.assume(sizes);

  // The shipped lengths (basic_floor_size over Z3 words): the arrays' sizes.
  const stc::BasicFloorSize<FloorZ3> size = stc::basic_floor_size<FloorZ3>(W, H);
  Memory<8> free_bits("free_bits", size.bit_bytes), entered("entered_bits", size.bit_bytes),
      marks("marks", size.cells);
  Memory<16> edges("edges", size.cells);
  const U64 area_bits = U64(4) * U64(size.shape.cells_x) * U64(size.shape.cells_y);
  const z3::expr free_cells =
      ctx.constant("free_cells", ctx.array_sort(ctx.bv_sort(64), ctx.bv_sort(1)));
  const Layout L{size.shape.cells_x, size.shape.cells_y, size.cells, size.bit_bytes,
                 area_bits,          &free_bits,         free_cells};

  // ---- lemmas, each under its own domain ----
  int lemma_failures = 0;
  p.no_undefined_behaviour("stc_floor.floor_size (no int32 overflow, no division by zero)");
  p.claim("stc_floor.floor_size.cells (cells_x = width / 2, cells_y = height / 2, in [0, 2^19])",
          L.cx == W / I32(2) && L.cy == H / I32(2) && I32(0) <= L.cx &&
              L.cx <= I32(kMaxGridSide / 2) && I32(0) <= L.cy && L.cy <= I32(kMaxGridSide / 2));
  p.claim("stc_floor.floor_size.bit_bytes_hold_the_area (4 cells_x cells_y <= 8 bit_bytes)",
          area_bits <= size.bit_bytes * U64(8));
  p.claim("stc_floor.floor_size.cells_is_the_bordered_grid (cells = (cells_x + 2)(cells_y + 2))",
          size.cells == L.stride() * (U64(L.cy) + 2));
  index_lemmas_over_integers(p, ctx);
  {
    // No wrap: every operation of the layout's index terms is exact for maps up to kMaxGridSide,
    // so the bit-vector terms are the integers of the lemmas above.
    const ZSubCell a{I32::var("nw_ax"), I32::var("nw_ay")};
    p.assume(L.bordered(a));
    const U64 row = U64(a.y + 1), col = U64(a.x + 1), cy2 = U64(L.cy) + 2;
    const U64 i = row * L.stride() + col;
    p.claim("stc_floor.index.no_wrap (cell index, its neighbours' sums, cells)",
            I32(0) <= a.y + 1 && I32(0) <= a.x + 1 && Bool(no_wrap_add(U64(L.cx), U64(2))) &&
                Bool(no_wrap_mul(row, L.stride())) && Bool(no_wrap_add(row * L.stride(), col)) &&
                Bool(no_wrap_add(i, U64(1))) && Bool(no_wrap_add(i, L.stride())) &&
                Bool(no_wrap_add(U64(L.cy), U64(2))) && Bool(no_wrap_mul(L.stride(), cy2)));
    p.reset_domain();
    p.assume(sizes);
    const ZSubCell t{I32::var("nw_sx"), I32::var("nw_sy")};
    p.assume(L.in_area(t));
    const U64 srow = U64(t.y), sstride = U64(I32(2) * L.cx);
    p.claim("stc_floor.index.no_wrap (sub-cell bit index, 4 cells_x cells_y)",
            I32(0) <= t.y && I32(0) <= t.x && Bool(no_wrap_mul(srow, sstride)) &&
                Bool(no_wrap_add(srow * sstride, U64(t.x))) &&
                Bool(no_wrap_mul(U64(4), U64(L.cx))) &&
                Bool(no_wrap_mul(U64(4) * U64(L.cx), U64(L.cy))));
    // A free cell's sub-cells are free (the definition read at the sub-cell's own quadrant). Only
    // congruence is needed (the sub-cell of the cell at its own quadrant is the sub-cell itself,
    // so its k and its bit are the same): checked with the products abstracted.
    StepChecker lemma(s, sizes.expr() && L.in_area(t).expr());
    lemma.claim("stc_floor.cell_free_covers_its_sub_cells",
                implies(L.cell_free_by_definition(Layout::cell_of(t)), L.free_sub(t)));
    lemma_failures += lemma.failures();
    p.reset_domain();
  }

  // ---- the step: domain ----
  // The domain, kept here for the step checker (and given to Prover for the refutations).
  z3::expr domain = ctx.bool_val(true);
  auto assume = [&](const Bool& b) { domain = domain && b.expr(); };
  assume(sizes);
  // The state: the robot's sub-cell, the counts, the probes.
  const ZSubCell pos{I32::var("x"), I32::var("y")};
  const ZSubCell cur = Layout::cell_of(pos);
  const I64 covered = I64::var("covered"), repeats = I64::var("repeats");
  const ZSubCell probe{I32::var("probe_cx"), I32::var("probe_cy")};
  const ZSubCell probe_sub{I32::var("probe_sx"), I32::var("probe_sy")};
  const U16 probe_bit = U16::var("probe_bit");
  std::array<ZSubCell, 4> nb, target;
  for (int d = 0; d < 4; ++d) {
    nb[static_cast<std::size_t>(d)] = step(cur, d);
    target[static_cast<std::size_t>(d)] = step(pos, d);
  }
  assume(L.in_area(pos) && L.cell_free(cur));
  assume(I64(0) <= covered && covered < (I64(1) << 62) && I64(0) <= repeats &&
         repeats < (I64(1) << 62));
  assume(L.bordered(probe) && L.in_area(probe_sub) && probe_bit < U16(12));
  // Instances of the lemmas above.
  assume(area_bits <= size.bit_bytes * U64(8));
  assume(L.idx_bounded(cur) && L.idx_bounded(probe) && L.idx_distinct(probe, cur) &&
         L.k_bounded(probe_sub));
  for (int d = 0; d < 4; ++d) {
    const auto i = static_cast<std::size_t>(d);
    assume(L.idx_neighbour(cur, d) && L.idx_bounded(nb[i]) && L.idx_distinct(probe, nb[i]));
  }
  // Per marker: the invariant of its array where the step reads it and at the probe; per move:
  // the lemma instances at its target. (Each claim carries only the part of the domain its step
  // can touch: the rest is about other arrays or other targets, true but costly to carry.)
  auto invariant = [&](bool edge) {
    Bool b = edge ? L.inv_edges(edges, cur) && L.inv_edges(edges, probe)
                  : L.inv_marks(marks, cur) && L.inv_marks(marks, probe);
    for (const ZSubCell& n : nb) b = b && (edge ? L.inv_edges(edges, n) : L.inv_marks(marks, n));
    return b;
  };
  auto at_target = [&](int d) {
    const ZSubCell& t = target[static_cast<std::size_t>(d)];
    return L.k_bounded(t) && L.k_distinct(probe_sub, t) && L.free_cell_free_sub(t);
  };
  s.clear_obligations(); // the domain's own arithmetic is a statement, not code

  // Not vacuous: the whole domain (every marker's invariant, every target's facts) holds of a
  // concrete floor: a 4 x 4 map, all free, nothing marked or entered, the robot in the NW corner.
  {
    Bool all = invariant(false) && invariant(true);
    for (int d = 0; d < 4; ++d) all = all && at_target(d);
    const z3::sort bv64 = ctx.bv_sort(64);
    z3::expr mk = z3::const_array(bv64, ctx.bv_val(0, 8)),
             ed = z3::const_array(bv64, ctx.bv_val(0, 16));
    for (int i : {5, 6, 9, 10}) { // the four cells of the 2 x 2 grid, in the bordered 4 x 4 array
      mk = z3::store(mk, ctx.bv_val(i, 64), ctx.bv_val(0x80, 8));
      ed = z3::store(ed, ctx.bv_val(i, 64), ctx.bv_val(0x8000, 16));
    }
    // The witness as a model: every unknown of the domain and of the session's facts (the
    // division abstractions' quotients and remainders: 4 / 2 = 2 rem 0 for both sizes, bit_bytes
    // = 23 / 8 = 2 rem 7) given a value; the domain and the facts evaluate to true in it.
    z3::model m(ctx);
    auto set = [&](const z3::expr& var, const z3::expr& value) {
      z3::func_decl d = var.decl();
      z3::expr v = value;
      m.add_const_interp(d, v);
    };
    set(W.expr(), ctx.bv_val(4, 32));
    set(H.expr(), ctx.bv_val(4, 32));
    for (const I32* v : {&pos.x, &pos.y, &probe.x, &probe.y, &probe_sub.x, &probe_sub.y})
      set(v->expr(), ctx.bv_val(0, 32));
    set(covered.expr(), ctx.bv_val(0, 64));
    set(repeats.expr(), ctx.bv_val(0, 64));
    set(probe_bit.expr(), ctx.bv_val(0, 16));
    set(free_bits.array(), z3::const_array(bv64, ctx.bv_val(0xFF, 8)));
    set(entered.array(), z3::const_array(bv64, ctx.bv_val(0, 8)));
    set(marks.array(), mk);
    set(edges.array(), ed);
    set(free_cells, z3::const_array(bv64, ctx.bv_val(1, 1)));
    for (const auto& [key, kr] : s.signed_divisions()) {
      set(kr.first, ctx.bv_val(2, kr.first.get_sort().bv_size()));
      set(kr.second, ctx.bv_val(0, kr.second.get_sort().bv_size()));
    }
    for (const auto& [key, kr] : s.divisions()) {
      set(kr.first, ctx.bv_val(2, kr.first.get_sort().bv_size()));
      set(kr.second, ctx.bv_val(7, kr.second.get_sort().bv_size()));
    }
    z3::expr claim = domain && all.expr();
    for (const auto& f : s.facts()) claim = claim && f;
    if (m.eval(claim, true).is_true()) {
      std::cout << "satisfied stc_floor.context_is_satisfiable: the domain holds of a 4 x 4 map, "
                   "all free, the robot at (0, 0)\n";
    } else {
      std::cout << "FAILED   stc_floor.context_is_satisfiable: the witness does not satisfy it\n";
      ++lemma_failures;
    }
    s.clear_obligations();
  }

  StepChecker check(s, domain);
  const Bool invariant_marks = invariant(false), invariant_edges = invariant(true);
  std::array<Bool, 4> target_facts{at_target(0), at_target(1), at_target(2), at_target(3)};
  s.clear_obligations();
  const std::array<stc::Command, 9> commands{{{stc::Move::Stop, false},
                                              {stc::Move::East, false},
                                              {stc::Move::East, true},
                                              {stc::Move::North, false},
                                              {stc::Move::North, true},
                                              {stc::Move::West, false},
                                              {stc::Move::West, true},
                                              {stc::Move::South, false},
                                              {stc::Move::South, true}}};

  int paths = 0, skipped = 0;
  for (const stc::Marker marker : {stc::Marker::WholeSubCell, stc::Marker::Edge}) {
    if (only_marker && *only_marker != marker) continue;
    const bool edge = marker == stc::Marker::Edge;
    const std::string m = edge ? "stc_floor.edges" : "stc_floor.marks";
    const z3::expr marker_domain = domain && (edge ? invariant_edges : invariant_marks).expr();
    check.set_domain(marker_domain);

    // The floor as the host's StcWorld holds it (both cell arrays), over copies of the state.
    auto floor_over = [&](Memory<8>& fb, Memory<8>& en, Memory<8>& mk, Memory<16>& ed) {
      ZFloor f;
      f.restore(
          W, H,
          ZStorage{MemoryRef<8>(&fb), MemoryRef<8>(&en), MemoryRef<8>(&mk), MemoryRef<16>(&ed)},
          pos, covered, repeats, stc::NoiseModel{}, marker);
      return f;
    };

    // ---- one command ----
    for (const stc::Command& command : commands) {
      const std::string name = m + "." + command_name(command);
      const bool go = command.move != stc::Move::Stop;
      const int dir = go ? static_cast<int>(command.move) : 0;
      const ZSubCell t = target[static_cast<std::size_t>(dir)];
      const Bool model_moves = Bool(go) && L.cell_free(Layout::cell_of(t));
      const Bool target_free = Bool(go) && L.free_sub(t);
      check.set_domain(marker_domain && target_facts[static_cast<std::size_t>(dir)].expr());
      int k = 0;
      paths += for_each_path(s, [&] {
        const std::string path = name + ".path" + std::to_string(k++);
        Memory<8> fb = free_bits, en = entered, mk = marks;
        Memory<16> ed = edges;
        ZFloor f = floor_over(fb, en, mk, ed);
        const Bool moved = f.apply(command);
        if (!check.feasible()) {
          std::cout << "skipped  " << path << " (its path condition contradicts the domain)\n";
          ++skipped;
          s.clear_obligations();
          return;
        }
        Bool ok = moved == target_free;
        if (!moved.expr().is_true()) {
          // Refused: the model refuses too, and nothing changed.
          ok = ok && !model_moves && same(f.position(), pos) && f.covered() == covered &&
               f.repeats() == repeats &&
               Bool(fb.array() == free_bits.array() && en.array() == entered.array() &&
                    mk.array() == marks.array() && ed.array() == edges.array());
          check.claim(path + ": refused, as the model; nothing changes", ok);
          return;
        }
        ok = ok && same(f.position(), t) && Bool(fb.array() == free_bits.array());
        // The marker: only the robot's old cell changes (by its quadrant's bit) or, for edges,
        // what AntStcWorld.v's light_edge lights, inside the grid.
        if (!edge) {
          const U8 before = marks.peek(L.idx(probe)), after = mk.peek(L.idx(probe));
          const U8 added =
              command.mark ? select(same(probe, cur), Layout::quadrant_mask(pos), U8(0)) : U8(0);
          ok = ok && L.inv_marks(mk, probe) && after == (before | added) &&
               Bool(ed.array() == edges.array());
        } else {
          const U16 pb = edges.peek(L.idx(probe)) >> probe_bit,
                    pa = ed.peek(L.idx(probe)) >> probe_bit;
          // light_edge(pos, opposite(dir)) of AntStcWorld.v, per quadrant e of pos.
          Bool lit(false);
          if (command.mark) {
            const int d = (dir + 2) & 3;
            for (int e = 0; e < 4; ++e) {
              auto at = [&](const ZSubCell& c, int b) {
                return same(probe, c) && probe_bit == U16(b);
              };
              Bool here(false);
              if (d == ((e + 2) & 3))
                here = at(cur, e);
              else if (d == ((e + 1) & 3))
                here = at(cur, (e + 1) & 3);
              else if (d == ((e + 3) & 3))
                here = at(cur, 4 + e) || at(step(cur, d), 8 + ((e + 1) & 3));
              else
                here = at(cur, 8 + e) || at(step(cur, d), 4 + ((e + 3) & 3));
              lit = lit || (Layout::quadrant_is(pos, e) && here);
            }
          }
          ok = ok && L.inv_edges(ed, probe) &&
               implies(L.in_grid(probe),
                       ((pa & U16(1)) == U16(1)) == (((pb & U16(1)) == U16(1)) || lit)) &&
               Bool(mk.array() == marks.array());
        }
        // Entered bits and counts.
        const Bool was = L.entered(entered, t);
        ok = ok &&
             (L.entered(en, probe_sub) == (L.entered(entered, probe_sub) || same(probe_sub, t))) &&
             f.covered() == covered + select(was, I64(0), I64(1)) &&
             f.repeats() == repeats + select(was, I64(1), I64(0));
        // The invariant's position part, when the model moves (the model's own step).
        ok = ok && implies(model_moves,
                           L.in_area(f.position()) && L.cell_free(Layout::cell_of(f.position())));
        check.claim(path + ": moved as the model; marks, entered, counts, invariant", ok);
      });
    }

    // ---- the observation ---- (after the commands: a source mutant of apply() is found, with
    // --first-failure, without proving the observation first; the claims are the same)
    check.set_domain(marker_domain);
    // Checked in parts (each read's bounds, then each field), which the solver decides far faster
    // than their conjunction.
    {
      Memory<8> fb = free_bits, en = entered, mk = marks;
      Memory<16> ed = edges;
      ZFloor f = floor_over(fb, en, mk, ed);
      std::vector<std::pair<std::string, Bool>> parts;
      if (!edge) {
        const ZMarkObservation o = f.observe_marks();
        check.obligations_one_by_one(m + ".observe");
        parts.emplace_back("here is M(cur)", o.here == (marks.peek(L.idx(cur)) & U8(0x0F)) &&
                                                 o.free_neighbours < U8(16));
        for (int d = 0; d < 4; ++d) {
          const auto i = static_cast<std::size_t>(d);
          const Bool free = L.cell_free(nb[i]);
          parts.emplace_back(
              "neighbour " + std::to_string(d) + ": freedom, and M(n) when free, else 0",
              ((((o.free_neighbours >> d) & U8(1)) == U8(1)) == free) &&
                  o.neighbour[i] == select(free, marks.peek(L.idx(nb[i])) & U8(0x0F), U8(0)));
        }
      } else {
        const ZEdgeObservation o = f.observe_edges();
        check.obligations_one_by_one(m + ".observe");
        parts.emplace_back("here is Ed(cur)", o.here == (edges.peek(L.idx(cur)) & U16(0x0FFF)) &&
                                                  o.free_neighbours < U8(16));
        for (int d = 0; d < 4; ++d) {
          const auto i = static_cast<std::size_t>(d);
          parts.emplace_back(
              "neighbour " + std::to_string(d) + ": freedom, and Ed(n) in the grid, else 0",
              ((((o.free_neighbours >> d) & U8(1)) == U8(1)) == L.cell_free(nb[i])) &&
                  o.neighbour[i] ==
                      select(L.in_grid(nb[i]), edges.peek(L.idx(nb[i])) & U16(0x0FFF), U16(0)));
        }
      }
      for (const auto& [what, c] : parts) check.claim(m + ".observe: " + what, c);
    }
  }

  // ---- teeth: wrong claims Z3 must refute ----
  {
    p.reset_domain();
    p.assume(sizes && L.in_area(pos));
    // The partly free divergence: a free sub-cell in a cell that is not free (by the definition).
    const ZSubCell t = target[0];
    p.refute("stc_floor.teeth.partly_free_divergence (the model refuses only where the floor "
             "refuses)",
             implies(L.free_sub(t), L.cell_free_by_definition(Layout::cell_of(t))));
    // Without the border, the north neighbour would be one row of cells_x entries up.
    p.refute("stc_floor.teeth.north_neighbour_without_border",
             L.idx(nb[1]) + U64(L.cx) == L.idx(cur));
  }

  std::cout << paths << " paths through observe + apply, " << skipped
            << " of them impossible under the domain (skipped)\n";
  if (only_marker)
    std::cout << "only the " << (*only_marker == stc::Marker::Edge ? "edges" : "marks")
              << " marker's step was checked (--marker): not the whole proof\n";
  std::cout << "step claims: " << check.proved() << " proved, " << check.failures() << " failed\n";
  const int r = p.result();
  return r != 0 || check.failures() != 0 || lemma_failures != 0 ? 1 : 0;
}
