#pragma once
// The Coq decision table of ant-like STC (proofs/golden/AntDecide.out, what coqc computes from
// proofs/coq/AntDecide.v's `decide`) and the reduction AntDecide.v proves `decide` reads its input
// through. Read by proof_tie_ant_stc (ant_stc_tie.cpp: the host's ant_decide and world against the
// table) and proof_tie_ant_decide_digest (ant_decide_digest.cpp: the table's digest the Cortex-M4
// image's must equal).
#include <antkit/stc/subcell.hpp>
#include <array>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace antkit::proofs {

// The four strings coqc prints for `Compute table E/N/W/S` (one per current quadrant).
inline std::optional<std::array<std::string, 4>> read_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  std::array<std::string, 4> out;
  std::size_t pos = 0;
  for (auto& s : out) {
    const std::size_t open = text.find('"', pos);
    if (open == std::string::npos) return std::nullopt;
    const std::size_t close = text.find('"', open + 1);
    if (close == std::string::npos) return std::nullopt;
    s = text.substr(open + 1, close - open - 1);
    if (s.size() != 16 * 16 * 16 * 2) return std::nullopt;
    pos = close + 1;
  }
  return out;
}

// What an entry says ant_decide returns: '.' Stop (and done set), else Go m q: move m, mark, q.
struct Expected {
  bool stop = true;
  int move = 0;
  int q = 0;
};

inline Expected decode(char c) {
  if (c == '.') return {};
  const int v = c - 'a';
  return {false, v / 4, v % 4};
}

// AntDecide.v's reduction: is_new d = free d && the neighbour's mask is 0; entry = the mark of the
// neighbour across side cur on its sub-cell cur - 1.
inline std::size_t table_index(int here, int free, const std::array<std::uint8_t, 4>& nb, int cur) {
  int is_new = 0;
  for (int d = 0; d < 4; ++d)
    if (((free >> d) & 1) != 0 && nb[static_cast<std::size_t>(d)] == 0) is_new |= 1 << d;
  const int entry = (nb[static_cast<std::size_t>(cur)] >> stc::dir_add(cur, 3)) & 1;
  return static_cast<std::size_t>(((here * 16 + free) * 16 + is_new) * 2 + entry);
}

} // namespace antkit::proofs
