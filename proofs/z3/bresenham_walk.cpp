// Z3 proof: one step of the shipped Bresenham walk (antkit::kernel::BresenhamWalk, raster.hpp),
// instantiated with 32-bit Z3 integers, is free of overflow for every segment inside a grid of side
// kMaxGridSide (grid.hpp), keeps its decision variable's invariant, moves one column and at most
// one row, and lands on the cell nearest to the ideal line, ties going away from a.
//
// A proof about the shipped template: BresenhamWalk<I32> is the same source as the
// BresenhamWalk<std::int64_t> that for_each_bresenham_cell runs. Its one branch (`d >= 0`) forks
// the run (z3_int.hpp, Session::decide); both paths are checked.
//
// Local coordinates (raster.hpp): the segment runs from (0, 0) to (M, m) = (dmajor, dminor) with
// M >= m >= 0; after k major steps the walk is at (k, j) and
//     d = 2m (k + 1) - M (2j + 1)  in  [-2M, 2m).
// The caller (detail::for_each_bresenham_cell_until) maps (k, j) to a cell by reflecting the signs
// and, for a steep segment, swapping x and y; that map is a bijection that keeps 8-adjacency, so
// "never skips a column" below is "never skips a row" for the steep octants.
//
// Induction over the walk: the domain is the invariant; bresenham.start shows it holds at the start
// and each bresenham.step.* claim that one step keeps it, so every reachable state satisfies it.
//   bresenham.start                     k = j = 0 and d in its invariant (or M = 0: nothing to
//   walk) bresenham.step.no_overflow          every int32 operation of advance() is defined
//   bresenham.step.keeps_invariant      d' = 2m (k' + 1) - M (2j' + 1) and -2M <= d' < 2m
//   bresenham.step.moves_to_8_neighbour k' = k + 1 (no column skipped), j' - j in {0, 1}, and the
//                                       returned flag says which
//   bresenham.step.nearest_cell         -M < 2M j' - 2m k' <= M, i.e. with the ideal line's minor
//                                       coordinate y = m k' / M at column k':
//                                       j' - 1/2 <= y < j' + 1/2, so j' = floor(y + 1/2): the
//                                       nearest cell (|j' - y| <= 1/2), and on a tie
//                                       (y = j' - 1/2) the farther from a, as raster.hpp documents
//   bresenham.step.stays_in_box         0 <= j' <= m (over the integers, from nearest_cell)
// Teeth (bresenham.teeth.*): claims that are wrong by one must be refuted by Z3: d' < 2m - 1, the
// tie going the other way (2M j' - 2m k' < M), and "no overflow" for any int32 extents.
#include "prove.hpp"

#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/raster.hpp>

using namespace antkit::proofs;
using antkit::kernel::BresenhamWalk;
using antkit::kernel::kMaxGridSide;

namespace {

// The invariant's products m k and M j are two unknowns P and Q (as in supercover_walk.cpp): every
// claim then is linear, and proved for all P, Q it holds for P = m k, Q = M j. Specification
// arithmetic in 48 bits: with P, Q < 2^40 and M, m < 2^20 every value is far inside 48 bits.
using W = Int<48, true>;

struct Products {
  I32 M, m;
  W P, Q; // m k and M j
  // d at (k, j) by the invariant's formula: the domain says the walk's d equals it.
  W d_formula() const {
    Session::Specification spec;
    return W(2) * P + W(2) * W(m) - W(2) * Q - W(M);
  }
  // d at (k + dk, j + dj), written as d at (k, j) plus the change, with the walk's own d for d at
  // (k, j): equal to the formula's value under the domain (d == d_formula()), and a claim stated
  // this way needs no P and Q, which spares Z3 relating two differently built adder chains (stated
  // over d_formula() the step's claims took minutes).
  W d_at(const I32& d, int dk, int dj) const {
    Session::Specification spec;
    return W(d) + W(2 * dk) * W(m) - W(2 * dj) * W(M);
  }
  Bool in_range(const W& d) const {
    Session::Specification spec;
    return W(-2) * W(M) <= d && d < W(2) * W(m);
  }
  // 2M j' - 2m k' at (k + 1, j + dj): twice the signed distance, times M, from the line to the
  // centre of the chosen cell along the minor axis. By the formula 2M j - 2m (k + 1) = -(d + M),
  // so it is 2dj M - M - d (the walk's d, as in d_at).
  W offset_after(const I32& d, int dj) const {
    Session::Specification spec;
    return W(2 * dj) * W(M) - W(M) - W(d);
  }
};

} // namespace

int main() {
  Session s;
  Prover p(s);
  const I32 M = I32::var("dmajor"), m = I32::var("dminor");
  const I32 k = I32::var("k"), j = I32::var("j"), d = I32::var("d");
  // Segments between cells of [0, kMaxGridSide): after reflection and the swap, 0 <= m <= M and
  // M < kMaxGridSide.
  const Bool extents = I32(0) <= m && m <= M && M < I32(kMaxGridSide);
  p.assume(extents);
  {
    BresenhamWalk<I32> w(M, m);
    const Products start{M, m, W(0), W(0)};
    p.claim("bresenham.start",
            w.k == I32(0) && w.j == I32(0) &&
                (M == I32(0) || (W(w.d) == start.d_formula() && start.in_range(W(w.d)))));
  }

  const Products at{M, m, W::var("P"), W::var("Q")};
  // Not done (k < M), and the invariant.
  const Bool state = I32(0) <= k && k < M && I32(0) <= j && j <= m && W(0) <= at.P &&
                     at.P < (W(1) << 40) && W(0) <= at.Q && at.Q < (W(1) << 40) &&
                     W(d) == at.d_formula() && at.in_range(W(d));
  p.assume(state);
  s.clear_obligations(); // the domain's own arithmetic is a statement, not code
  const z3::expr domain = (extents && state).expr();

  bool teeth = true;
  const int paths = for_each_path(s, [&] {
    BresenhamWalk<I32> w(M, m);
    w.k = k;
    w.j = j;
    w.d = d;
    s.clear_obligations(); // the constructor's 2m - M: covered by bresenham.start
    const bool minor = w.advance();
    p.no_undefined_behaviour("bresenham.step.no_overflow");
    const int dj = minor ? 1 : 0;
    const std::string where = minor ? " (minor step)" : " (major only)";
    p.claim("bresenham.step.keeps_invariant" + where,
            W(w.d) == at.d_at(d, 1, dj) && at.in_range(W(w.d)));
    p.claim("bresenham.step.moves_to_8_neighbour" + where, w.k == k + I32(1) && w.j == j + I32(dj));
    const W offset = at.offset_after(d, dj);
    p.claim("bresenham.step.nearest_cell" + where, W(0) - W(M) < offset && offset <= W(M));
    p.refute("bresenham.teeth: d' < 2m - 1" + where, (W(w.d) < W(2) * W(m) - W(1)).expr());
    if (minor) p.refute("bresenham.teeth: a tie goes towards a" + where, (offset < W(M)).expr());
  });

  // Teeth for no_overflow: the same step, for any non-negative int32 extents (far beyond
  // kMaxGridSide) and d in its range (stated in 64 bits), must overflow on some path: d - 2M
  // reaches below -2^31 once M > 2^30. (Up to M = 2^30 the int32 walk is in fact overflow-free.)
  {
    const I32 M2 = I32::var("dmajor_big"), m2 = I32::var("dminor_big"), d2 = I32::var("d_big");
    const Bool big =
        I32(0) <= m2 && m2 <= M2 && I64(-2) * I64(M2) <= I64(d2) && I64(d2) < I64(2) * I64(m2);
    bool overflows = false;
    for_each_path(s, [&] {
      BresenhamWalk<I32> w(M2, m2);
      w.d = d2;
      s.clear_obligations();
      w.advance();
      z3::expr all = s.ctx().bool_val(true);
      for (const auto& ob : s.obligations()) all = all && ob.holds;
      s.clear_obligations();
      z3::solver solver(s.ctx(), "QF_BV");
      solver.add(big.expr());
      for (const auto& c : s.path()) solver.add(c);
      solver.add(!all);
      overflows = overflows || solver.check() == z3::sat;
    });
    std::cout << (overflows ? "refuted  " : "NOT REFUTED (the proof has no teeth) ")
              << "bresenham.teeth: no overflow for any int32 extents" << std::endl;
    teeth = overflows && teeth;
  }

  // stays_in_box: from nearest_cell, over the integers (nonlinear; Z3's default solver): with
  // 0 <= m <= M, 1 <= k' <= M and -M < 2M j' - 2m k' <= M, j' is in [0, m].
  {
    z3::context& c = s.ctx();
    const z3::expr X = c.int_const("M"), Y = c.int_const("m"), K = c.int_const("k1"),
                   J = c.int_const("j1");
    const z3::expr hyp = 0 <= Y && Y <= X && 1 <= K && K <= X && -X < 2 * X * J - 2 * Y * K &&
                         2 * X * J - 2 * Y * K <= X;
    p.reset_domain();
    p.claim_over_integers("bresenham.step.stays_in_box", z3::implies(hyp, 0 <= J && J <= Y));
  }
  std::cout << paths << " paths through BresenhamWalk::advance\n";
  const int r = p.result();
  return teeth ? r : 1;
}
