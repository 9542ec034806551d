#pragma once
// Reads the golden output of a Coq proof's `Compute` commands (proofs/golden/<Name>.out, which the
// ctest proof.coq.<Name> holds equal to what coqc prints): the integers of each result, in order,
// one vector per result. A result runs from its "=" to its " : " type line; Coq may break lines
// anywhere inside it, so only the integers are read. A '-' directly before digits is a sign. The
// `Print Assumptions` report before the first result holds no '='.
#include <catch2/catch.hpp>
#include <cctype>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace antkit::test {

inline std::vector<std::vector<int>> coq_golden_vectors(const std::string& path) {
  std::ifstream in(path);
  INFO("golden file " << path);
  REQUIRE(in.good());
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  auto digit = [&text](std::size_t i) {
    return std::isdigit(static_cast<unsigned char>(text[i])) != 0;
  };
  std::vector<std::vector<int>> out;
  std::size_t pos = 0;
  while ((pos = text.find('=', pos)) != std::string::npos) {
    const std::size_t end = text.find(" : ", pos);
    REQUIRE(end != std::string::npos);
    std::vector<int> numbers;
    std::size_t i = pos;
    while (i < end) {
      const bool minus = text[i] == '-' && i + 1 < end && digit(i + 1);
      if (!minus && !digit(i)) {
        ++i;
        continue;
      }
      if (minus) ++i;
      int v = 0;
      while (i < end && digit(i)) v = v * 10 + (text[i++] - '0');
      numbers.push_back(minus ? -v : v);
    }
    out.push_back(std::move(numbers));
    pos = end;
  }
  return out;
}

} // namespace antkit::test
