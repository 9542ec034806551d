#pragma once
// A Z3 bit-vector integer that behaves like a C++ integer of N bits, so that the kernel's
// arithmetic templates (DESIGN.md rule 6) can be instantiated symbolically and proved with Z3.
//
// Why bit-vectors and not Z3's mathematical integers: the kernel's numbers ARE N-bit words;
// unsigned arithmetic wraps modulo 2^N and that wrap is part of the meaning (Lemire's low word,
// hashes), so only bit-vectors model the code exactly.
//
// Why side conditions: bit-vectors wrap on every operation, but C++ signed overflow, a shift by N
// or more, a division by zero and INT_MIN / -1 are undefined behaviour. Each such operation records
// the condition under which it is defined ("obligation") in the current Session; a proof is only
// valid if every obligation holds for every input in the documented domain, and Session::prove
// checks that first.
//
// Why there is no path condition on obligations: branches in the kernel's templates go through
// select(c, a, b), and select takes both arms already evaluated, exactly as the machine
// instantiation does (a plain function call evaluates both arguments). So an obligation of the arm
// that is not chosen must hold too: the conservative reading is the exact one here.
//
// Conversions follow C++20: widening sign- or zero-extends by the SOURCE signedness, narrowing
// keeps the low bits (defined modulo 2^N since C++20), >> of a negative value is arithmetic, << of
// a signed value is defined when the result is representable (the obligation we record; C++20 made
// it modular, but the kernel's documentation promises no wrap, so wrap is flagged).
//
// Not modelled: C++'s promotion of types narrower than int (a uint16_t * uint16_t is an int
// multiplication). The kernel computes in 32- and 64-bit types; I8..U16 here are plain N-bit words.
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#include <z3++.h>

namespace antkit::proofs {

// One proof run: the Z3 context, and the obligations recorded by the operations executed so far.
class Session {
public:
  Session() { current_ = this; }
  ~Session() {
    if (current_ == this) current_ = nullptr;
  }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  static Session& current() {
    if (current_ == nullptr) {
      std::cerr << "z3_int: no Session is open\n";
      std::abort();
    }
    return *current_;
  }

  z3::context& ctx() { return ctx_; }

  struct Obligation {
    std::string what;
    z3::expr holds;
  };
  void oblige(std::string what, const z3::expr& holds) {
    if (suspended_ == 0) obligations_.push_back({std::move(what), holds});
  }
  // While one of these lives, operations record no obligations: for a claim's own arithmetic (the
  // specification, not the code), whose range its author states beside it.
  class Specification {
  public:
    Specification() { ++Session::current().suspended_; }
    ~Specification() { --Session::current().suspended_; }
    Specification(const Specification&) = delete;
    Specification& operator=(const Specification&) = delete;
  };
  const std::vector<Obligation>& obligations() const { return obligations_; }

  // Facts: theorems of the operations' semantics, stated beside an abstracted result (see unsigned
  // / and % below). Every check assumes them; they must be TRUE of the operation they describe.
  void fact(const z3::expr& f) { facts_.push_back(f); }
  const std::vector<z3::expr>& facts() const { return facts_; }
  // Branching on a symbolic truth value (`if (e < 0)` in a kernel template) forks the run: the
  // driver for_each_path (prove.hpp) re-runs the code once per combination of branch outcomes, and
  // each decision taken is added to the path condition under which that run's claims are checked.
  // A path that cannot happen makes its path condition unsatisfiable, so its claims hold vacuously.
  bool decide(const z3::expr& c) {
    bool taken = true;
    if (decision_ < script_.size())
      taken = script_[decision_];
    else
      script_.push_back(true);
    ++decision_;
    path_.push_back(taken ? c : !c);
    return taken;
  }
  const std::vector<z3::expr>& path() const { return path_; }
  // Starts a run; returns false when every path has been run.
  bool next_path(bool first) {
    path_.clear();
    if (!first) {
      // The next script: the last `true` decision of the previous run turns `false`, later ones
      // are forgotten (depth-first, true before false).
      script_.resize(decision_);
      while (!script_.empty() && !script_.back()) script_.pop_back();
      if (script_.empty()) return false;
      script_.back() = false;
    }
    decision_ = 0;
    return true;
  }

  std::string fresh(const char* stem) { return std::string(stem) + "!" + std::to_string(fresh_++); }

  // One abstraction per (dividend, divisor) term, so that the code's a % b and a specification's
  // a % b are the same unknown (Z3 shares equal terms, so their ids agree).
  std::map<std::pair<unsigned, unsigned>, std::pair<z3::expr, z3::expr>>& divisions() {
    return divisions_;
  }
  std::map<std::pair<unsigned, unsigned>, std::pair<z3::expr, z3::expr>>& signed_divisions() {
    return signed_divisions_;
  }
  // Tables read by the kernels (ops::lookup), one Z3 array per (table, width): see lookup() below.
  // Once a table is an array the checks need the array theory (Prover picks QF_ABV, not QF_BV).
  std::map<std::pair<const void*, int>, z3::expr>& tables() { return tables_; }
  bool uses_arrays() const { return !tables_.empty(); }
  void clear_obligations() { obligations_.clear(); }
  // Replaces `from` by `to` in every pending obligation and fact: the generalisation of a term
  // (e.g. a product) to a fresh unknown. Sound for proving: what is proved for every value of the
  // unknown holds for the term's value in particular -- as long as every fact that remains is
  // still true of that value, which the caller argues beside the call.
  void substitute(const z3::expr& from, const z3::expr& to) {
    z3::expr_vector f(ctx_), t(ctx_);
    f.push_back(from);
    t.push_back(to);
    for (auto& ob : obligations_) ob.holds = ob.holds.substitute(f, t);
    for (auto& fa : facts_) fa = fa.substitute(f, t);
  }

private:
  static inline Session* current_ = nullptr;
  z3::context ctx_;
  std::vector<Obligation> obligations_;
  std::vector<z3::expr> facts_;
  int suspended_ = 0;
  std::vector<bool> script_;
  std::size_t decision_ = 0;
  std::vector<z3::expr> path_;
  std::map<std::pair<unsigned, unsigned>, std::pair<z3::expr, z3::expr>> divisions_;
  std::map<std::pair<unsigned, unsigned>, std::pair<z3::expr, z3::expr>> signed_divisions_;
  std::map<std::pair<const void*, int>, z3::expr> tables_;
  int fresh_ = 0;
};

// A symbolic truth value: what comparisons of Int return.
// Signed bit-vector division (truncating, like C++); z3++.h spells it only as operator/.
inline z3::expr sdiv_(const z3::expr& a, const z3::expr& b) {
  return z3::expr(a.ctx(), Z3_mk_bvsdiv(a.ctx(), a, b));
}

class Bool {
public:
  explicit Bool(const z3::expr& e) : e_(e) {}
  Bool(bool b) : e_(Session::current().ctx().bool_val(b)) {}
  static Bool var(const std::string& name) {
    return Bool(Session::current().ctx().bool_const(name.c_str()));
  }
  const z3::expr& expr() const { return e_; }
  // `if (c)` on a symbolic c: forks the run (Session::decide).
  explicit operator bool() const { return Session::current().decide(e_); }
  friend Bool operator&&(const Bool& a, const Bool& b) { return Bool(a.e_ && b.e_); }
  friend Bool operator||(const Bool& a, const Bool& b) { return Bool(a.e_ || b.e_); }
  friend Bool operator==(const Bool& a, const Bool& b) { return Bool(a.e_ == b.e_); }
  friend Bool operator!=(const Bool& a, const Bool& b) { return Bool(a.e_ != b.e_); }
  Bool operator!() const { return Bool(!e_); }

private:
  z3::expr e_;
};

template <int N, bool Signed>
class Int {
  static_assert(N >= 1 && N <= 512);

public:
  static constexpr int bits = N;
  static constexpr bool is_signed = Signed;

  // A fresh unknown of this width.
  static Int var(const std::string& name) {
    return Int(Session::current().ctx().bv_const(name.c_str(), N));
  }
  explicit Int(const z3::expr& e) : e_(e) {}

  // Constants: implicit from any C++ integer, as `Rep{1}` or `x + 1` in a template need. The value
  // is taken modulo 2^N, as a conversion to an N-bit type would.
  template <class T>
  requires std::is_integral_v<T> Int(T v) : e_(constant(v)) {}
  Int() : Int(0) {}

  // Conversions between widths and signedness, as static_cast between integer types does.
  template <int M, bool S>
  explicit Int(const Int<M, S>& o) : e_(convert<M, S>(o.expr())) {}

  const z3::expr& expr() const { return e_; }

  // --- arithmetic (obligations for signed overflow) ---
  friend Int operator+(const Int& a, const Int& b) {
    if constexpr (Signed) a.fits("signed +", wide(a.e_) + wide(b.e_));
    return Int(a.e_ + b.e_);
  }
  friend Int operator-(const Int& a, const Int& b) {
    if constexpr (Signed) a.fits("signed -", wide(a.e_) - wide(b.e_));
    return Int(a.e_ - b.e_);
  }
  friend Int operator*(const Int& a, const Int& b) {
    if constexpr (Signed) {
      // Two unknowns: Z3's own signed-overflow predicates, not "the 2N-bit product fits": they
      // bit-blast to an overflow detector instead of a 2N x 2N multiplier (35 s against 2 s for
      // "every int32 product fits in int64"). A constant factor: the 2N-bit product, a cheap
      // shift-and-add that the older proofs (supercover_walk.cpp) were tuned with.
      if (a.e_.is_numeral() || b.e_.is_numeral()) {
        a.fits("signed *", z3::sext(a.e_, N) * z3::sext(b.e_, N), N);
      } else {
        z3::context& c = a.e_.ctx();
        Session::current().oblige("signed *",
                                  z3::expr(c, Z3_mk_bvmul_no_overflow(c, a.e_, b.e_, true)) &&
                                      z3::expr(c, Z3_mk_bvmul_no_underflow(c, a.e_, b.e_)));
      }
    }
    return Int(a.e_ * b.e_);
  }
  // Division truncates toward zero (C++ and bvsdiv agree); % has the sign of the dividend (srem).
  //
  // Unsigned / and % by an unknown divisor are ABSTRACTED: the quotient k and remainder r are fresh
  // unknowns tied to a and b by Euclid's definition, stated exactly (in 2N bits, so without wrap):
  //     b != 0  =>  k * b + r == a  and  r < b.
  // That pair determines k and r uniquely, so nothing is lost; what is gained is that Z3 no longer
  // bit-blasts a divider circuit (checking a 32-bit divider by a symbolic n against anything did
  // not finish in minutes), and a claim that needs only r < b is proved at once.
  //
  // Signed / and % are abstracted the same way, by C++'s truncating definition (stated in 2N bits):
  //     b != 0 and not (a == INT_MIN and b == -1)  =>
  //         k * b + r == a,  |r| < |b|,  and r == 0 or r has the sign of a.
  // These determine k and r uniquely (r is a's remainder toward zero), so again nothing is lost.
  // The INT_MIN / -1 obligation is stated as that comparison, not as "the wide quotient fits", for
  // the same reason: no divider circuit.
  friend Int operator/(const Int& a, const Int& b) {
    a.nonzero("division by zero", b);
    if constexpr (Signed) {
      a.not_min_by_minus_one("signed / (INT_MIN / -1)", b);
      return signed_euclid(a, b).first;
    } else {
      return euclid(a, b).first;
    }
  }
  friend Int operator%(const Int& a, const Int& b) {
    a.nonzero("remainder by zero", b);
    if constexpr (Signed) {
      // INT_MIN % -1 is undefined too (the quotient overflows).
      a.not_min_by_minus_one("signed % (INT_MIN % -1)", b);
      return signed_euclid(a, b).second;
    } else {
      return euclid(a, b).second;
    }
  }
  Int operator-() const {
    if constexpr (Signed) fits("signed unary -", -wide(e_));
    return Int(-e_);
  }
  Int operator~() const { return Int(~e_); }
  friend Int operator&(const Int& a, const Int& b) { return Int(a.e_ & b.e_); }
  friend Int operator|(const Int& a, const Int& b) { return Int(a.e_ | b.e_); }
  friend Int operator^(const Int& a, const Int& b) { return Int(a.e_ ^ b.e_); }

  // Shifts by a C++ int (the kernel shifts by constants) or by a symbolic amount.
  friend Int operator<<(const Int& a, int s) { return a.shl(Int(s)); }
  friend Int operator>>(const Int& a, int s) { return a.shr(Int(s)); }
  template <int M, bool S>
  friend Int operator<<(const Int& a, const Int<M, S>& s) {
    return a.shl(Int(s));
  }
  template <int M, bool S>
  friend Int operator>>(const Int& a, const Int<M, S>& s) {
    return a.shr(Int(s));
  }

  Int& operator+=(const Int& b) { return *this = *this + b; }
  Int& operator-=(const Int& b) { return *this = *this - b; }
  Int& operator*=(const Int& b) { return *this = *this * b; }
  Int& operator/=(const Int& b) { return *this = *this / b; }
  Int& operator%=(const Int& b) { return *this = *this % b; }
  Int& operator&=(const Int& b) { return *this = *this & b; }
  Int& operator|=(const Int& b) { return *this = *this | b; }
  Int& operator^=(const Int& b) { return *this = *this ^ b; }
  Int& operator<<=(int s) { return *this = *this << s; }
  Int& operator>>=(int s) { return *this = *this >> s; }

  // --- comparisons (Bool is defined below) ---
  friend Bool operator==(const Int& a, const Int& b) { return Bool(a.e_ == b.e_); }
  friend Bool operator!=(const Int& a, const Int& b) { return Bool(a.e_ != b.e_); }
  friend Bool operator<(const Int& a, const Int& b) {
    return Bool(Signed ? z3::slt(a.e_, b.e_) : z3::ult(a.e_, b.e_));
  }
  friend Bool operator<=(const Int& a, const Int& b) {
    return Bool(Signed ? z3::sle(a.e_, b.e_) : z3::ule(a.e_, b.e_));
  }
  friend Bool operator>(const Int& a, const Int& b) {
    return Bool(Signed ? z3::sgt(a.e_, b.e_) : z3::ugt(a.e_, b.e_));
  }
  friend Bool operator>=(const Int& a, const Int& b) {
    return Bool(Signed ? z3::sge(a.e_, b.e_) : z3::uge(a.e_, b.e_));
  }

  // The value as a mathematical integer (Z3 Int sort), for stating claims outside the bit-vector.
  z3::expr to_integer() const { return z3::expr(e_.ctx(), Z3_mk_bv2int(e_.ctx(), e_, Signed)); }

private:
  template <class T>
  static z3::expr constant(T v) {
    auto& c = Session::current().ctx();
    if constexpr (std::is_signed_v<T>)
      return c.bv_val(static_cast<std::int64_t>(v), N);
    else
      return c.bv_val(static_cast<std::uint64_t>(v), N);
  }
  template <int M, bool S>
  static z3::expr convert(const z3::expr& e) {
    if constexpr (M == N)
      return e;
    else if constexpr (M > N)
      return e.extract(N - 1, 0);
    else if constexpr (S)
      return z3::sext(e, N - M);
    else
      return z3::zext(e, N - M);
  }
  // One more bit than N, by this type's signedness: enough to hold the exact + or - of two values.
  static z3::expr wide(const z3::expr& e, int extra = 1) {
    return Signed ? z3::sext(e, static_cast<unsigned>(extra))
                  : z3::zext(e, static_cast<unsigned>(extra));
  }
  // Records that the exact result `exact` (computed `extra` bits wider) is representable in N bits.
  void fits(const char* what, const z3::expr& exact, int extra = 1) const {
    const z3::expr back = wide(exact.extract(N - 1, 0), extra);
    Session::current().oblige(what, exact == back);
  }
  void nonzero(const char* what, const Int& b) const {
    Session::current().oblige(what, b.e_ != Session::current().ctx().bv_val(0, N));
  }
  Int shl(const Int& s) const {
    Session::current().oblige("shift amount in [0, N)",
                              z3::ult(s.e_, z3::expr(e_.ctx().bv_val(N, N))));
    if constexpr (Signed) {
      // Representable result: shifting back arithmetically gives the value again.
      const z3::expr r = z3::shl(e_, s.e_);
      Session::current().oblige("signed << keeps the value", z3::ashr(r, s.e_) == e_);
      return Int(r);
    } else {
      return Int(z3::shl(e_, s.e_));
    }
  }
  Int shr(const Int& s) const {
    Session::current().oblige("shift amount in [0, N)",
                              z3::ult(s.e_, z3::expr(e_.ctx().bv_val(N, N))));
    return Int(Signed ? z3::ashr(e_, s.e_) : z3::lshr(e_, s.e_));
  }

  void not_min_by_minus_one(const char* what, const Int& b) const {
    z3::context& c = Session::current().ctx();
    const z3::expr min = z3::shl(c.bv_val(1, N), c.bv_val(N - 1, N));
    Session::current().oblige(what, !(e_ == min && b.e_ == c.bv_val(-1, N)));
  }

  static std::pair<Int, Int> signed_euclid(const Int& a, const Int& b) {
    Session& s = Session::current();
    z3::context& c = s.ctx();
    if (a.e_.is_numeral() && b.e_.is_numeral()) // constants: no need to abstract
      return {Int(sdiv_(a.e_, b.e_)), Int(z3::srem(a.e_, b.e_))};
    const std::pair<unsigned, unsigned> key{Z3_get_ast_id(c, a.e_), Z3_get_ast_id(c, b.e_)};
    if (auto it = s.signed_divisions().find(key); it != s.signed_divisions().end())
      return {Int(it->second.first), Int(it->second.second)};
    const Int k = var(s.fresh("squotient")), r = var(s.fresh("sremainder"));
    s.signed_divisions().emplace(key, std::pair{k.e_, r.e_});
    const auto w = [](const z3::expr& e) { return z3::sext(e, N); };
    const z3::expr zero = c.bv_val(0, 2 * N);
    const auto abs2 = [&](const z3::expr& e) { return z3::ite(e < zero, -e, e); };
    const z3::expr min = z3::shl(c.bv_val(1, N), c.bv_val(N - 1, N));
    const z3::expr defined = b.e_ != c.bv_val(0, N) && !(a.e_ == min && b.e_ == c.bv_val(-1, N));
    s.fact(z3::implies(defined, w(k.e_) * w(b.e_) + w(r.e_) == w(a.e_) &&
                                    z3::ult(abs2(w(r.e_)), abs2(w(b.e_))) &&
                                    (r.e_ == c.bv_val(0, N) || (z3::slt(r.e_, c.bv_val(0, N)) ==
                                                                z3::slt(a.e_, c.bv_val(0, N))))));
    return {k, r};
  }

  static std::pair<Int, Int> euclid(const Int& a, const Int& b) {
    Session& s = Session::current();
    if (a.e_.is_numeral() && b.e_.is_numeral()) // constants: no need to abstract
      return {Int(z3::udiv(a.e_, b.e_)), Int(z3::urem(a.e_, b.e_))};
    const std::pair<unsigned, unsigned> key{Z3_get_ast_id(s.ctx(), a.e_),
                                            Z3_get_ast_id(s.ctx(), b.e_)};
    if (auto it = s.divisions().find(key); it != s.divisions().end())
      return {Int(it->second.first), Int(it->second.second)};
    const Int k = var(s.fresh("quotient")), r = var(s.fresh("remainder"));
    s.divisions().emplace(key, std::pair{k.e_, r.e_});
    const auto w = [](const z3::expr& e) { return z3::zext(e, N); };
    s.fact(z3::implies(b.e_ != s.ctx().bv_val(0, N),
                       w(k.e_) * w(b.e_) + w(r.e_) == w(a.e_) && z3::ult(r.e_, b.e_)));
    return {k, r};
  }

  z3::expr e_;
};

// A precondition of a kernel's documented domain (int_ops.hpp: ops::require), e.g. "divisor is not
// zero", or, from ops::narrow, "the value fits the narrower type": recorded as an obligation, so a
// claim is proved only if the domain the prover assumes implies it. (Found by argument-dependent
// lookup: the kernels call require unqualified.)
inline void require(const Bool& holds, const char* what) {
  Session::current().oblige(std::string("require: ") + what, holds.expr());
}

// Branch-free choice: the kernel's templates write `select(c, a, b)` where they would write
// `c ? a : b`, so that the same source runs on machine integers and on Z3 terms.
template <int N, bool S>
Int<N, S> select(const Bool& c, const Int<N, S>& a, const Int<N, S>& b) {
  return Int<N, S>(z3::ite(c.expr(), a.expr(), b.expr()));
}
inline Bool select(const Bool& c, const Bool& a, const Bool& b) {
  return Bool(z3::ite(c.expr(), a.expr(), b.expr()));
}

// A table read (int_ops.hpp, ops::lookup), preferred by overload resolution to the generic chain
// of 1026 selects there (this one is more specialised: its index is an Int). The table becomes ONE
// Z3 array constant per (table, width), the same for every read, constrained by one fact per entry:
//     table!k[i] == table[i]      for i = 0 .. size - 1,
// true of the shipped table by construction (each fact is the entry's value, converted to N bits
// as the generic lookup's I(table[i]) converts it). Outside [0, size) the array is unconstrained,
// so a claim that depended on such a read could not be proved -- and the read itself records the
// obligation 0 <= index < size, which the machine build checks (ops::lookup's require).
// Why: with the ite chain, every claim carried two 1026-way multiplexers into the bit-blaster;
// with the array, a claim that needs no entry (the formula, the absence of overflow) never looks
// at the facts, and a claim about the entries (a table lemma) is proved once, by case split over
// the index, and then stated as a fact about the two reads (see proofs/z3/angle_sine.cpp).
template <class Table, int N, bool S>
Int<N, S> lookup(const Table& table, const Int<N, S>& index) {
  Session& s = Session::current();
  z3::context& c = s.ctx();
  const std::size_t size = table.size();
  // Written over N + 1 bits so that `size` itself is representable whatever the width.
  const z3::expr wide_index = S ? z3::sext(index.expr(), 1) : z3::zext(index.expr(), 1);
  const z3::expr zero = c.bv_val(0, N + 1);
  s.oblige("table index in range",
           z3::sle(zero, wide_index) &&
               z3::slt(wide_index, c.bv_val(static_cast<std::uint64_t>(size), N + 1)));
  const std::pair<const void*, int> key{static_cast<const void*>(table.data()), N};
  auto it = s.tables().find(key);
  if (it == s.tables().end()) {
    const z3::sort bv = c.bv_sort(N);
    const z3::expr a = c.constant(s.fresh("table").c_str(), c.array_sort(bv, bv));
    for (std::size_t i = 0; i < size; ++i)
      s.fact(z3::select(a, Int<N, S>(i).expr()) == Int<N, S>(table[i]).expr());
    it = s.tables().emplace(key, a).first;
  }
  return Int<N, S>(z3::select(it->second, index.expr()));
}
// The array behind a table (after the first lookup at width N): for stating table lemmas.
template <class Table>
z3::expr table_array(const Table& table, int n) {
  return Session::current().tables().at({static_cast<const void*>(table.data()), n});
}

using I8 = Int<8, true>;
using U8 = Int<8, false>;
using I16 = Int<16, true>;
using U16 = Int<16, false>;
using I32 = Int<32, true>;
using U32 = Int<32, false>;
using I64 = Int<64, true>;
using U64 = Int<64, false>;
using I128 = Int<128, true>;
using U128 = Int<128, false>;

} // namespace antkit::proofs
