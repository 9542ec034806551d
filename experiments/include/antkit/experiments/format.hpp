#pragma once
// How the experiments write numbers into their tables and reports (one place for every file).
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>

namespace antkit::experiments {

// 10 significant digits (the CSV files).
[[nodiscard]] inline std::string number(double v) {
  std::ostringstream s;
  s << std::setprecision(10) << v;
  return s.str();
}

// `decimals` decimals (the Markdown tables).
[[nodiscard]] inline std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

} // namespace antkit::experiments
