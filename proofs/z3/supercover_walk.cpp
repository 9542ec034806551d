// Z3 proof: one step of the shipped supercover walk (antkit::kernel::SupercoverWalk, raster.hpp),
// instantiated with 32-bit Z3 integers, is free of overflow for every segment inside a grid of side
// kMaxGridSide (grid.hpp), keeps its decision variable's invariant, and never skips a cell.
//
// This is a proof about the shipped template: SupercoverWalk<I32> is the same source as the
// SupercoverWalk<std::int64_t> the rasterizer runs (raster.hpp says the walk is overflow-free even
// in 32 bits; proved here, so the 64-bit instantiation is a fortiori). Its `if (e < 0)` branches
// fork the run (z3_int.hpp, Session::decide): each of the three steps is a path, checked apart.
//
// Induction over the walk: the domain below is the invariant (in local coordinates the segment runs
// from (0, 0) to (dx, dy), the walk is at (i, j) with e = dy (2i + 1) - dx (2j + 1)); it holds at
// the start (supercover.start) and each claim shows one step keeps it (supercover.step.*). By
// induction, every state the walk reaches satisfies it, so no reachable step overflows.
//   supercover.step.no_overflow        every int32 operation of advance() is defined
//   supercover.step.keeps_invariant    e' = dy (2i' + 1) - dx (2j' + 1) and -2dx <= e' <= 2dy
//                                      (the segment touches the closed square of (i', j'))
//   supercover.step.moves_by_one       (i', j') - (i, j) is (1, 0), (0, 1), or (1, 1) at a corner
//   supercover.step.stays_in_box       i' <= dx and j' <= dy
//   supercover.step.skips_nothing      the neighbour not taken is not on the supercover: after an
//                                      x step, (i, j + 1) is not touched; after a y step, (i + 1,
//                                      j) is not; at a corner both side cells are touched (and
//                                      for_each_supercover_interior emits them before the diagonal)
#include "prove.hpp"

#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/raster.hpp>

using namespace antkit::proofs;
using antkit::kernel::kMaxGridSide;
using antkit::kernel::SupercoverStep;
using antkit::kernel::SupercoverWalk;

namespace {

// The invariant's products dy * i and dx * j are kept as two unknowns P and Q: e at the
// cell (i + di, j + dj) is then 2 (P + di dy) + dy - 2 (Q + dj dx) - dx, linear in P and Q.
// Claims proved for ALL P and Q hold in particular for P = dy i, Q = dx j; this spares Z3 the
// multipliers (with them, the invariant's claim did not finish in five minutes). The real
// products' range, [0, 2^40), is part of the domain.
// The claims' own arithmetic runs in 48 bits (|e| < 2^42 everywhere): narrower words are
// cheaper for Z3, and nothing is lost since every value is in range (an obligation says so).
using W = Int<48, true>;

struct Products {
  I32 dx, dy;
  W P, Q;
  // Written as e at (i, j) plus the change, so that every claim shares the one term for e at
  // (i, j): a SAT solver is poor at proving two differently built adder chains equal.
  // Specification arithmetic, unchecked: with P, Q < 2^40 and dx, dy < 2^20 every value is below
  // 2^43 in magnitude, far inside 48 bits (checking it per operation cost Z3 minutes).
  W e_here() const {
    Session::Specification spec;
    return W(2) * P + W(dy) - W(2) * Q - W(dx);
  }
  W e_at(int di, int dj) const {
    Session::Specification spec;
    return e_here() + W(2 * di) * W(dy) - W(2 * dj) * W(dx);
  }
  // The segment touches the closed square of (i + di, j + dj): the decision variable there is in
  // range [-2dx, 2dy].
  Bool touched(int di, int dj) const {
    Session::Specification spec;
    const W v = e_at(di, dj);
    return W(-2) * W(dx) <= v && v <= W(2) * W(dy);
  }
};

} // namespace

int main() {
  Session s;
  Prover p(s);
  const I32 dx = I32::var("dx"), dy = I32::var("dy");
  const I32 i = I32::var("i"), j = I32::var("j"), e = I32::var("e");
  // Segments between cells of [0, kMaxGridSide): the reflected extents are below kMaxGridSide.
  p.assume(I32(0) <= dx && dx < I32(kMaxGridSide) && I32(0) <= dy && dy < I32(kMaxGridSide));

  const Products at{dx, dy, W::var("P"), W::var("Q")};
  {
    // At the start P = dy * 0 = 0 and Q = 0.
    SupercoverWalk<I32> w(dx, dy);
    const Products start{dx, dy, W(0), W(0)};
    p.claim("supercover.start",
            W(w.e) == start.e_at(0, 0) && start.touched(0, 0) && w.i == I32(0) && w.j == I32(0));
  }

  p.assume(I32(0) <= i && i <= dx && I32(0) <= j && j <= dy && !(i == dx && j == dy));
  // The true P = dy i and Q = dx j lie in [0, 2^40); saying so keeps the claims' own 64-bit
  // arithmetic (which records obligations like any other) free of overflow.
  p.assume(W(0) <= at.P && at.P < (W(1) << 40) && W(0) <= at.Q && at.Q < (W(1) << 40));
  p.assume(W(e) == at.e_at(0, 0));
  p.assume(I32(-2) * dx <= e && e <= I32(2) * dy);
  s.clear_obligations(); // the domain's own arithmetic is a statement, not code

  const int paths = for_each_path(s, [&] {
    SupercoverWalk<I32> w(dx, dy);
    w.i = i;
    w.j = j;
    w.e = e;
    s.clear_obligations(); // the constructor's dy - dx: covered by supercover.start
    const SupercoverStep step = w.advance();
    p.no_undefined_behaviour("supercover.step.no_overflow");
    const I32 di = w.i - i, dj = w.j - j;
    Bool moved(false), invariant(false);
    switch (step) {
    case SupercoverStep::X:
      moved = di == I32(1) && dj == I32(0);
      invariant = W(w.e) == at.e_at(1, 0) && at.touched(1, 0);
      p.claim("supercover.step.skips_nothing (x step)", !at.touched(0, 1));
      break;
    case SupercoverStep::Y:
      moved = di == I32(0) && dj == I32(1);
      invariant = W(w.e) == at.e_at(0, 1) && at.touched(0, 1);
      p.claim("supercover.step.skips_nothing (y step)", !at.touched(1, 0));
      break;
    case SupercoverStep::Corner:
      moved = di == I32(1) && dj == I32(1) && e == I32(0);
      invariant = W(w.e) == at.e_at(1, 1) && at.touched(1, 1);
      p.claim("supercover.step.skips_nothing (corner)", at.touched(1, 0) && at.touched(0, 1));
      break;
    }
    p.claim("supercover.step.keeps_invariant", invariant);
    p.claim("supercover.step.moves_by_one", moved);
  });

  // stays_in_box: an x step is never taken at i = dx, nor a y step at j = dy (before the end).
  // This one needs the products themselves; stated over Z3's mathematical integers, where its
  // nonlinear arithmetic proves it at once:
  //   i = dx, j < dy  =>  e = dy (2dx + 1) - dx (2j + 1) = 2dx (dy - j) + dy - dx >= dx + dy >= 0,
  //   j = dy, i < dx  =>  e = dy (2i + 1) - dx (2dy + 1) = -2dy (dx - i) + dy - dx <= -dx - dy <=
  //   0,
  // so at the right edge the walk never steps x (e < 0), at the top edge never y (e > 0), and at a
  // corner (e == 0) the two imply dx = dy = 0, the end.
  {
    z3::context& c = s.ctx();
    const z3::expr X = c.int_const("dx"), Y = c.int_const("dy"), I = c.int_const("i"),
                   J = c.int_const("j");
    const z3::expr E = Y * (2 * I + 1) - X * (2 * J + 1);
    const z3::expr box =
        0 <= X && 0 <= Y && 0 <= I && I <= X && 0 <= J && J <= Y && !(I == X && J == Y);
    p.reset_domain();
    p.claim_over_integers("supercover.step.stays_in_box (x step only left of dx)",
                          z3::implies(box && I == X, E >= 0));
    p.claim_over_integers("supercover.step.stays_in_box (y step only below dy)",
                          z3::implies(box && J == Y, E <= 0));
    p.claim_over_integers("supercover.step.stays_in_box (no corner on an edge)",
                          z3::implies(box && (I == X || J == Y), E != 0));
  }
  std::cout << paths << " paths through SupercoverWalk::advance\n";
  return p.result();
}
