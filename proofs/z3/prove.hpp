#pragma once
// The shape of every Z3 proof executable: state claims over symbolic inputs, check them, print a
// counterexample when Z3 finds one, and exit non-zero if any claim failed (so ctest fails).
//
//   int main() {
//     Session s;
//     Prover p(s);
//     auto x = U32::var("x");
//     p.claim("x + 0 == x", (x + 0u == x));
//     return p.result();
//   }
//
// Each claim is checked under the domain given to `assume` (the function's documented domain), and
// so is every obligation (no undefined behaviour) recorded since the previous claim: a claim about
// a computation that may overflow is not proved, whatever the bit-vector says.
//
// No claim passes vacuously. Before a claim counts, its context -- the domain, the path condition
// and every fact -- is checked satisfiable (an unsatisfiable context proves anything, `false`
// included). A context whose domain and facts contradict each other fails the run ("CONTEXT
// UNSATISFIABLE"); a path whose condition contradicts a satisfiable domain (a branch the inputs
// cannot take, which for_each_path runs anyway) is reported and not counted, and a claim that was
// checked on no satisfiable context at all fails at result(). A proved claim kept for later checks
// (keep) is kept as "context implies claim", scoped to the domain and path it was proved under, so
// a later section with another domain does not inherit it.
#include "proof_cache.hpp"
#include "z3_int.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

namespace antkit::proofs {

// The first bit-vector multiplication of two non-constants in e (depth-first), if any: the proofs
// that replace a product by an unknown find the product the shipped code formed with it.
inline std::optional<z3::expr> first_product(const z3::expr& e) {
  if (!e.is_app()) return std::nullopt;
  if (e.decl().decl_kind() == Z3_OP_BMUL && !e.arg(0).is_numeral() && !e.arg(1).is_numeral())
    return e;
  for (unsigned i = 0; i < e.num_args(); ++i)
    if (auto p = first_product(e.arg(i))) return p;
  return std::nullopt;
}

// Whether the term `sub` occurs in e (the same Z3 term, by id): the proofs that prove a term's
// obligations in two phases (those that need a fact about the term, and the others) sort them so.
inline bool mentions_term(const z3::expr& e, const z3::expr& sub) {
  const unsigned target = Z3_get_ast_id(e.ctx(), sub);
  std::vector<z3::expr> todo{e};
  std::unordered_set<unsigned> seen;
  while (!todo.empty()) {
    const z3::expr t = todo.back();
    todo.pop_back();
    const unsigned id = Z3_get_ast_id(t.ctx(), t);
    if (id == target) return true;
    if (!t.is_app() || !seen.insert(id).second) continue;
    for (unsigned i = 0; i < t.num_args(); ++i) todo.push_back(t.arg(i));
  }
  return false;
}

// Runs `body` once per path through the branches it takes on symbolic values (Session::decide),
// depth-first; returns how many paths were run. Claims made inside are checked under the path's
// condition.
template <class Body>
int for_each_path(Session& s, Body&& body) {
  int paths = 0;
  for (bool first = true; s.next_path(first); first = false) {
    body();
    ++paths;
  }
  return paths;
}

class Prover {
public:
  explicit Prover(Session& s) : s_(s), domain_(s.ctx().bool_val(true)) {}

  // The documented domain of the inputs: every later claim and obligation is checked under it.
  void assume(const Bool& d) { domain_ = domain_ && d.expr(); }
  void reset_domain() { domain_ = s_.ctx().bool_val(true); }

  // Checks every pending obligation, then the claim. Prints "proved" or the counterexample.
  bool claim(const std::string& name, const Bool& c) { return claim(name, c.expr()); }
  bool claim(const std::string& name, const z3::expr& c) {
    bool ok = true;
    for (const auto& ob : s_.obligations()) {
      ok = check(name + " [no undefined behaviour: " + ob.what + "]", ob.holds) && ok;
    }
    s_.clear_obligations();
    ok = check(name, c) && ok;
    return ok;
  }

  // Proves c like claim() and, when proved, keeps it as a fact for the later checks -- scoped: what
  // is kept is "domain and path imply c", true because c was just proved under them, and harmless
  // to a later section whose domain contradicts this one (the implication is then vacuous there,
  // instead of a contradiction that would prove that section's claims from nothing).
  bool keep(const std::string& name, const Bool& c) { return keep(name, c.expr()); }
  bool keep(const std::string& name, const z3::expr& c) {
    if (!claim(name, c)) return false;
    s_.fact(z3::implies(context(), c));
    return true;
  }

  // The domain and the current path as one condition.
  z3::expr context() const {
    z3::expr all = domain_;
    for (const auto& p : s_.path()) all = all && p;
    return all;
  }

  // A claim over Z3's mathematical integers (no bit-vectors), for the default solver.
  bool claim_over_integers(const std::string& name, const z3::expr& c) {
    integers_ = true;
    const bool ok = claim(name, c);
    integers_ = false;
    return ok;
  }

  // A claim over Z3's real numbers, for the QF_NRA solver (nlsat, a decision procedure for
  // polynomial arithmetic over the reals): a nonlinear lemma that holds over the reals holds over
  // the integers in particular, and nlsat decides it in milliseconds where the integer solver's
  // search is erratic (the same lemma took 7 s in one run and did not finish in another).
  bool claim_over_reals(const std::string& name, const z3::expr& c) {
    logic_ = "QF_NRA";
    const bool ok = claim(name, c);
    logic_ = nullptr;
    return ok;
  }
  bool refute_over_reals(const std::string& name, const z3::expr& c) {
    logic_ = "QF_NRA";
    const bool ok = refute(name, c);
    logic_ = nullptr;
    return ok;
  }

  // The obligations alone (for a function whose only claim is that it is free of UB).
  bool no_undefined_behaviour(const std::string& name) {
    return claim(name, s_.ctx().bool_val(true));
  }

  // A negative check, to show a proof has teeth: `c` must NOT hold in the domain (a deliberately
  // wrong bound, or a domain one bit too large); Z3 must find a counterexample, which is printed.
  // Pending obligations are left for the next claim. Fails (counts as a failure) if c is proved.
  bool refute(const std::string& name, const Bool& c) { return refute(name, c.expr()); }
  bool refute_over_integers(const std::string& name, const z3::expr& c) {
    integers_ = true;
    const bool ok = refute(name, c);
    integers_ = false;
    return ok;
  }
  bool refute(const std::string& name, const z3::expr& c) {
    z3::solver solver = negation_solver(c);
    const z3::check_result r = solver.check();
    if (r == z3::sat) {
      ++refuted_;
      std::cout << "refuted  " << name << " (as it must be), e.g.";
      const z3::model m = solver.get_model();
      for (unsigned i = 0; i < m.size(); ++i) {
        const z3::func_decl d = m[i];
        if (d.arity() != 0 || d.name().str().find('!') != std::string::npos) continue;
        const z3::expr value = m.get_const_interp(d);
        std::cout << " " << d.name().str() << "=";
        if (value.is_bv()) // as a signed integer; Booleans and integers print as they are
          std::cout << m.eval(z3::expr(s_.ctx(), Z3_mk_bv2int(s_.ctx(), value, true)), true);
        else
          std::cout << value;
      }
      std::cout << std::endl;
      return true;
    }
    ++failures_;
    std::cout << "NO TEETH " << name << ": expected a counterexample, Z3 says "
              << (r == z3::unsat ? "it holds" : "unknown") << "\n";
    return false;
  }
  // Every pending obligation as one expression (and forget them): for a negative check that the
  // code has undefined behaviour just outside its domain.
  z3::expr take_obligations() {
    z3::expr all = s_.ctx().bool_val(true);
    for (const auto& ob : s_.obligations()) all = all && ob.holds;
    s_.clear_obligations();
    return all;
  }

  int result() {
    // A claim every context of which was an impossible path was never checked at all.
    for (const auto& [name, counted] : counted_) {
      if (counted) continue;
      ++failures_;
      std::cout << "VACUOUS  " << name << ": every path it was checked on is impossible\n";
    }
    if (proved_ == 0 && refuted_ == 0) {
      ++failures_;
      std::cout << "FAILED   no claim was checked\n";
    }
    std::cout << (failures_ == 0 ? "all " : "") << proved_ << " proved, " << refuted_
              << " wrong claims refuted, " << impossible_paths_
              << " on impossible paths (not counted), " << failures_ << " failed\n";
    print_cache_use();
    return failures_ == 0 ? 0 : 1;
  }

  // Says how many answers came from the proof cache (proof_cache.hpp), when it is on.
  static void print_cache_use() {
    const ProofCache& cache = ProofCache::global();
    if (!cache.enabled()) return;
    std::cout << "proof cache: " << cache.hits()
              << " answers were those of identical queries solved by this Z3 in earlier runs ("
              << cache.dir() << "; ANTKIT_PROOF_CACHE= solves every query)\n";
  }

private:
  // A solver holding the domain, the path, the facts and the negation of c: unsat proves c, sat
  // refutes it. Bit-vector claims go to Z3's QF_BV solver (simplify, then bit-blast to SAT), which
  // is much faster on them than the default portfolio; claims over mathematical integers (a few
  // nonlinear lemmas) to the default solver; claim_over_reals sets its own logic.
  z3::solver make_solver() {
    return logic_ != nullptr ? z3::solver(s_.ctx(), logic_)
           : integers_       ? z3::solver(s_.ctx())
                             : bit_vector_solver();
  }
  z3::solver negation_solver(const z3::expr& c) {
    z3::solver solver = make_solver();
    solver.add(domain_);
    for (const auto& p : s_.path()) solver.add(p);
    for (const auto& f : s_.facts()) solver.add(f);
    solver.add(!c);
    return solver;
  }

  // Whether the context (domain, path, facts) of the next check has a model: Sat; Impossible when
  // only the path contradicts a satisfiable domain and facts; Contradiction when the domain and
  // facts contradict each other. Each distinct context is decided once (the same context is shared
  // by many claims in a row).
  enum class Context { Sat, Impossible, Contradiction, Unknown };
  Context context_status() {
    std::vector<unsigned> key;
    key.push_back(Z3_get_ast_id(s_.ctx(), domain_));
    key.push_back(static_cast<unsigned>(logic_ != nullptr) * 2 + static_cast<unsigned>(integers_));
    for (const auto& p : s_.path()) key.push_back(Z3_get_ast_id(s_.ctx(), p));
    key.push_back(0xFFFFFFFFu);
    for (const auto& f : s_.facts()) key.push_back(Z3_get_ast_id(s_.ctx(), f));
    if (key == context_key_) return context_;
    context_key_ = key;
    const auto decide = [&](bool with_path) {
      z3::solver solver = make_solver();
      solver.add(domain_);
      if (with_path)
        for (const auto& p : s_.path()) solver.add(p);
      for (const auto& f : s_.facts()) solver.add(f);
      // A satisfiable context is what lets the claims count: that answer may come from the cache
      // of earlier runs (proof_cache.hpp); a contradiction is always solved afresh.
      return ProofCache::global().check(solver, logic_name(), ProofCache::Keep::Sat);
    };
    const z3::check_result all = decide(true);
    if (all == z3::sat)
      context_ = Context::Sat;
    else if (all == z3::unknown)
      context_ = Context::Unknown;
    else if (s_.path().empty())
      context_ = Context::Contradiction;
    else {
      const z3::check_result without_path = decide(false);
      context_ = without_path == z3::sat     ? Context::Impossible
                 : without_path == z3::unsat ? Context::Contradiction
                                             : Context::Unknown;
    }
    return context_;
  }

  bool check(const std::string& name, const z3::expr& c) {
    const auto t0 = std::chrono::steady_clock::now();
    counted_.try_emplace(name, false);
    switch (context_status()) {
    case Context::Sat:
      break;
    case Context::Impossible:
      ++impossible_paths_;
      std::cout << "skipped  " << name << ": this path is impossible in the domain (not counted)\n";
      return true;
    case Context::Contradiction:
      ++failures_;
      counted_[name] = true; // failed already: not also reported as vacuous
      std::cout << "CONTEXT UNSATISFIABLE  " << name
                << ": the domain and the kept facts contradict each other, so every claim would "
                   "pass (false included); not proved\n";
      return false;
    case Context::Unknown:
      ++failures_;
      counted_[name] = true;
      std::cout << "UNKNOWN  " << name
                << ": Z3 could not decide whether the context is satisfiable\n";
      return false;
    }
    counted_[name] = true;
    z3::solver solver = negation_solver(c);
    dump_smt2(name, solver);
    bool cached = false;
    const z3::check_result r =
        ProofCache::global().check(solver, logic_name(), ProofCache::Keep::Unsat, &cached);
    const auto ms =
        std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - t0)
            .count();
    if (r == z3::unsat) {
      ++proved_;
      std::cout << "proved   " << name << " (" << ms << " ms" << (cached ? ", cached" : "") << ")"
                << std::endl;
      return true;
    }
    ++failures_;
    if (r == z3::unknown) {
      std::cout << "UNKNOWN  " << name << ": Z3 gave up (" << solver.reason_unknown() << ")\n";
      return false;
    }
    std::cout << "FAILED   " << name << "\n  counterexample:" << std::endl;
    const z3::model m = solver.get_model();
    for (unsigned i = 0; i < m.size(); ++i) {
      const z3::func_decl d = m[i];
      if (d.arity() != 0) continue;
      const z3::expr v = m.get_const_interp(d);
      std::cout << "    " << d.name().str() << " = " << v;
      if (v.is_bv()) {
        // Unsigned and signed readings, since the same bits are both.
        const z3::expr u = m.eval(z3::expr(s_.ctx(), Z3_mk_bv2int(s_.ctx(), v, false)), true);
        const z3::expr sg = m.eval(z3::expr(s_.ctx(), Z3_mk_bv2int(s_.ctx(), v, true)), true);
        std::cout << "  (unsigned " << u << ", signed " << sg << ")";
      }
      std::cout << "\n";
    }
    return false;
  }

  // With ANTKIT_SMT2_DIR set, every check that counts is also written there as an SMT-LIB 2 file
  // (NNNN.smt2, the claim's name in a comment on its first line; the negated claim, so the expected
  // answer is unsat): proofs/cmake/run_cvc5.cmake re-solves them with a second solver, so that one
  // solver's bug is not a single point of failure.
  void dump_smt2(const std::string& name, z3::solver& solver) {
    const char* dir = std::getenv("ANTKIT_SMT2_DIR");
    if (dir == nullptr || *dir == '\0') return;
    char file[32];
    std::snprintf(file, sizeof file, "/%04d.smt2", dumped_++);
    std::ofstream out(std::string(dir) + file);
    if (!out) {
      ++failures_;
      std::cout << "FAILED   cannot write " << dir << file << " (ANTKIT_SMT2_DIR)\n";
      return;
    }
    std::string one_line = name;
    for (char& ch : one_line)
      if (ch == '\n') ch = ' ';
    out << "; " << one_line << "\n";
    // The claims over integers mix the integers with the session's bit-vector facts: ALL.
    const char* logic = logic_ == nullptr && integers_ ? "ALL" : logic_name();
    out << "(set-logic " << logic << ")\n";
    // Let names renamed in order of appearance (proof_cache.hpp): the same check, the same text,
    // whatever the context made before it (cvc5's re-check keeps its answers by the text).
    out << ProofCache::canonical_names(portable_smt2(solver.to_smt2()));
  }

  // Z3 writes its own names for "signed multiplication does not overflow upwards / downwards",
  // (bvsmul_noovfl x y) and (bvsmul_noudfl x y); SMT-LIB's (and cvc5's) predicate is "overflows
  // either way", (bvsmulo x y). The product of two signed words overflows upwards only when their
  // signs agree and downwards only when they differ (with a zero factor nothing overflows), so
  //   (bvsmul_noovfl x y) = (not (and (bvsmulo x y) (= (bvslt x 0) (bvslt y 0))))
  //   (bvsmul_noudfl x y) = (not (and (bvsmulo x y) (distinct (bvslt x 0) (bvslt y 0))))
  // exactly, 0 written (bvsub x x) so that it has x's width.
  static std::string portable_smt2(const std::string& text) {
    const auto space = [&](std::size_t k) {
      return k < text.size() && (text[k] == ' ' || text[k] == '\n' || text[k] == '\t');
    };
    // The end of the s-expression that starts at k: an atom (|quoted| or plain) or a term.
    const auto sexp_end = [&](std::size_t k) {
      if (k < text.size() && text[k] == '|') return text.find('|', k + 1) + 1;
      if (k >= text.size() || text[k] != '(') {
        while (k < text.size() && !space(k) && text[k] != '(' && text[k] != ')') ++k;
        return k;
      }
      for (int depth = 0; k < text.size(); ++k) {
        if (text[k] == '|') k = text.find('|', k + 1);
        if (text[k] == '(') ++depth;
        if (text[k] == ')' && --depth == 0) return k + 1;
      }
      return k;
    };
    std::string out;
    std::size_t from = 0;
    for (;;) {
      const std::size_t over = text.find("(bvsmul_noovfl ", from);
      const std::size_t under = text.find("(bvsmul_noudfl ", from);
      const std::size_t at = std::min(over, under);
      if (at == std::string::npos) break;
      out.append(text, from, at - from);
      std::size_t k = at + 15; // after "(bvsmul_noXXfl "
      while (space(k)) ++k;
      const std::size_t x_end = sexp_end(k);
      const std::string x = portable_smt2(text.substr(k, x_end - k));
      k = x_end;
      while (space(k)) ++k;
      const std::size_t y_end = sexp_end(k);
      const std::string y = portable_smt2(text.substr(k, y_end - k));
      k = y_end;
      while (space(k)) ++k;
      const std::string signs = "(bvslt " + x + " (bvsub " + x + " " + x + ")) (bvslt " + y +
                                " (bvsub " + y + " " + y + "))";
      out += "(not (and (bvsmulo " + x + " " + y + ") (" + (at == over ? "=" : "distinct") + " " +
             signs + ")))";
      from = k + 1; // past the term's closing parenthesis
    }
    out.append(text, from, std::string::npos);
    return out;
  }

  // The solver a check goes to, by the name it was made with ("": Z3's default, for the claims
  // over integers): part of a query's key in the proof cache.
  const char* logic_name() const {
    return logic_ != nullptr ? logic_ : integers_ ? "" : s_.uses_arrays() ? "QF_ABV" : "QF_BV";
  }

  // QF_BV, or QF_ABV once a kernel has read a table as a Z3 array (z3_int.hpp, lookup): QF_BV's
  // tactic rejects array terms.
  z3::solver bit_vector_solver() {
    return z3::solver(s_.ctx(), s_.uses_arrays() ? "QF_ABV" : "QF_BV");
  }

  Session& s_;
  z3::expr domain_;
  bool integers_ = false;
  const char* logic_ = nullptr; // a solver chosen by logic name (claim_over_reals), or none
  int proved_ = 0;
  int refuted_ = 0;
  int failures_ = 0;
  int impossible_paths_ = 0;
  static inline int dumped_ = 0;        // process-wide: a program may run several Provers
  std::map<std::string, bool> counted_; // claim -> checked on at least one satisfiable context
  std::vector<unsigned> context_key_;   // the last context decided, and its status
  Context context_ = Context::Sat;
};

} // namespace antkit::proofs
