#pragma once
// The proofs' cache of solved queries, content-addressed (as ccache is for compiles, and as
// Isabelle's heaps and Coq's .vo files are for their proofs): a Z3 check whose query is exactly one
// that this machine's Z3 has already decided is answered from the cache instead of being solved
// again. The proofs are still built from the shipped code on every run -- the templates are
// instantiated with Z3 terms, every path is run, every obligation is collected -- and only the
// solver's search over a query seen before, character for character, is skipped.
//
// The key is the whole query: Z3's full version, the solver's logic, and the solver's assertions
// as SMT-LIB 2 text (z3::solver::to_smt2, Z3's benchmark printer: every declaration and assertion
// in full, the text prove.hpp also writes for cvc5). An entry holds its key
// in full and is used only when the key read back equals the query's, so two queries never share an
// answer, whatever the file name's hash. An edit to the code, the proof, a domain or a fact changes
// the text and the query is solved again; so does another Z3.
//
// What is cached: only answers that let a proof pass -- a claim's unsat (proved), a context's sat
// (checked satisfiable: the no-vacuity rule of prove.hpp), a path's sat or unsat (taken, or pruned
// as impossible: stc_floor's feasible()) -- never a failure, an unknown or a refutation (whose
// counterexample is printed from a fresh solve). A proof that fails, fails from a solve in this
// run.
//
// Where: the directory in ANTKIT_PROOF_CACHE (ctest sets it to the build's ANTKIT_PROOF_CACHE
// cache variable, by default ~/.cache/antkit/proofs, so that CI's clean clone reuses it as it
// reuses ccache); unset or empty, nothing is cached and every query is solved. The directory is
// trusted as the build's ccache is: whoever can write it can forge a proof. `make test
// ANTKIT_PROOF_CACHE=` (or deleting the directory) solves everything afresh. Entries are written
// to a temporary name and renamed, so that parallel proofs never read half an entry.
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <unistd.h>
#include <unordered_map>
#include <z3++.h>

namespace antkit::proofs {

class ProofCache {
public:
  // The process's cache, from ANTKIT_PROOF_CACHE (read once).
  static ProofCache& global() {
    static ProofCache cache(std::getenv("ANTKIT_PROOF_CACHE"));
    return cache;
  }
  explicit ProofCache(const char* dir) : dir_(dir != nullptr ? dir : "") {
    std::error_code ignored; // a cache that cannot be made only costs the run its solves
    if (!dir_.empty()) std::filesystem::create_directories(dir_, ignored);
  }
  [[nodiscard]] bool enabled() const noexcept { return !dir_.empty(); }
  [[nodiscard]] const std::string& dir() const noexcept { return dir_; }
  [[nodiscard]] int hits() const noexcept { return hits_; }

  // Which answers of a query may be kept: the ones that let the proof pass there.
  enum class Keep { Unsat, Sat, Either };

  // The solver's answer: from the cache when the same query was decided before with an answer
  // `keep` allows, else solved now and, when `keep` allows the answer, stored. `logic` names the
  // solver the query was given to ("QF_BV", "QF_ABV", "QF_NRA", "" for Z3's default).
  z3::check_result check(z3::solver& solver, std::string_view logic, Keep keep,
                         bool* from_cache = nullptr) {
    if (from_cache != nullptr) *from_cache = false;
    if (!enabled()) return solver.check();
    const std::string key = key_of(solver, logic);
    const std::string path = path_of(key);
    if (const auto cached = lookup(path, key, keep)) {
      ++hits_;
      if (from_cache != nullptr) *from_cache = true;
      return *cached;
    }
    const z3::check_result r = solver.check();
    if (allows(keep, r)) store(path, key, r);
    return r;
  }

private:
  static bool allows(Keep keep, z3::check_result r) {
    return (r == z3::unsat && keep != Keep::Sat) || (r == z3::sat && keep != Keep::Unsat);
  }
  static std::string answer_word(z3::check_result r) { return r == z3::unsat ? "unsat" : "sat"; }

  static std::string key_of(z3::solver& solver, std::string_view logic) {
    std::string key = "z3 ";
    key += Z3_get_full_version();
    key += "\nlogic ";
    key += logic.empty() ? "(default)" : logic;
    key += "\n";
    key += canonical_names(solver.to_smt2());
    return key;
  }

public:
  // Z3's printer names the terms it shares with `let` by their AST ids (?x8719, $x2007), and the
  // ids depend on everything the context made before -- a solve skipped because the cache answered
  // it shifts every later id. So the key renames them in order of first appearance (?x1, $x2, ...):
  // a let's name is a local label, and two texts equal after this renaming are the same formula.
  // The symbols of the proofs (cast.b, fx.a, mul!64, ...) never start with ? or $, and the text of
  // a |quoted symbol| is left as it is.
  static std::string canonical_names(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    std::unordered_map<std::string, std::string> seen;
    std::size_t k = 0;
    while (k < text.size()) {
      const char c = text[k];
      if (c == '|') { // a quoted symbol, copied whole
        const std::size_t end = text.find('|', k + 1);
        const std::size_t stop = end == std::string::npos ? text.size() : end + 1;
        out.append(text, k, stop - k);
        k = stop;
        continue;
      }
      const bool boundary = k == 0 || text[k - 1] == ' ' || text[k - 1] == '(' ||
                            text[k - 1] == '\n' || text[k - 1] == '\t';
      if (boundary && (c == '?' || c == '$') && k + 2 < text.size() && text[k + 1] == 'x' &&
          std::isdigit(static_cast<unsigned char>(text[k + 2])) != 0) {
        std::size_t e = k + 2;
        while (e < text.size() && std::isdigit(static_cast<unsigned char>(text[e])) != 0) ++e;
        if (e == text.size() || text[e] == ' ' || text[e] == ')' || text[e] == '\n') {
          const std::string name = text.substr(k, e - k);
          auto it = seen.find(name);
          if (it == seen.end())
            it =
                seen.emplace(name, std::string(1, c) + "x" + std::to_string(seen.size() + 1)).first;
          out += it->second;
          k = e;
          continue;
        }
      }
      out += c;
      ++k;
    }
    return out;
  }

private:
  // FNV-1a, 64 bits: only the file's name (the key inside decides).
  std::string path_of(const std::string& key) const {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const char c : key) {
      h ^= static_cast<unsigned char>(c);
      h *= 0x100000001b3ULL;
    }
    char name[40];
    std::snprintf(name, sizeof name, "/z3-%016llx-%zu", static_cast<unsigned long long>(h),
                  key.size());
    return dir_ + name;
  }

  // An entry: the answer's word on its own line, then the key, byte for byte.
  static std::optional<z3::check_result> lookup(const std::string& path, const std::string& key,
                                                Keep keep) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const z3::check_result r : {z3::unsat, z3::sat}) {
      const std::string head = answer_word(r) + "\n";
      if (allows(keep, r) && text.size() == head.size() + key.size() &&
          text.compare(0, head.size(), head) == 0 &&
          text.compare(head.size(), std::string::npos, key) == 0)
        return r;
    }
    return std::nullopt;
  }

  static void store(const std::string& path, const std::string& key, z3::check_result answer) {
    const std::string tmp = path + ".tmp" + std::to_string(::getpid());
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) return; // an unwritable cache only costs the next run a solve
      out << answer_word(answer) << "\n" << key;
      if (!out.flush()) {
        std::remove(tmp.c_str());
        return;
      }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) std::remove(tmp.c_str());
  }

  std::string dir_;
  int hits_ = 0;
};

} // namespace antkit::proofs
