#include "output.hpp"

#include <algorithm>
#include <antkit/algorithms/options.hpp>
#include <antkit/kernel/input_error.hpp>
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <unistd.h>
#include <vector>

namespace antkit::cli {

antkit::algorithms::Progress stage_progress(const std::string& tool) {
  const auto start = std::chrono::steady_clock::now();
  const auto seconds = [start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const bool tty = ::isatty(STDERR_FILENO) != 0;
  auto stage_start = std::make_shared<std::pair<std::string, double>>();
  return [tool, tty, stage_start, seconds](std::string_view stage, std::uint64_t done,
                                           std::uint64_t total) {
    if (stage_start->first != stage) *stage_start = {std::string(stage), seconds()};
    const double elapsed = seconds() - stage_start->second;
    if (tty) {
      const int filled = static_cast<int>(30.0 * static_cast<double>(done) /
                                          static_cast<double>(std::max<std::uint64_t>(total, 1)));
      const double left =
          done > 0 ? elapsed / static_cast<double>(done) * static_cast<double>(total - done) : 0.0;
      std::cerr << "\r" << stage << " [" << std::string(static_cast<std::size_t>(filled), '#')
                << std::string(static_cast<std::size_t>(30 - filled), '.') << "] " << done << "/"
                << total << ", about " << std::fixed << std::setprecision(0) << left << " s left   "
                << std::defaultfloat << std::setprecision(6) << (done == total ? "\n" : "")
                << std::flush;
    } else if (total > 0 && (done == total || (4 * done) / total != (4 * (done - 1)) / total)) {
      std::cerr << tool << ": " << stage << ": " << done << "/" << total << " units, " << std::fixed
                << std::setprecision(1) << elapsed << " s" << std::defaultfloat
                << std::setprecision(6) << '\n';
    }
  };
}

void make_out_dir(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw kernel::InputError("--out", "cannot create the directory " + dir);
}

#if ANTKIT_HAVE_MPI
bool make_out_dir_on_rank0(const antkit::mpi::Session& session, const std::string& dir) {
  std::string refused;
  if (session.rank() == 0) {
    try {
      make_out_dir(dir);
    } catch (const kernel::InputError& e) {
      refused = e.message();
    }
  }
  if (session.all(refused.empty())) return true;
  if (session.rank() == 0) throw kernel::InputError("--out", refused);
  return false;
}
#endif

void add_format_option(CLI::App& sub, Format& format) {
  sub.add_option_function<std::string>(
         "--format",
         [&format](const std::string& name) {
           format = name == "json" ? Format::Json : Format::Table;
         },
         "Output: table (for people, the default) or json")
      ->check(CLI::IsMember({"table", "json"}))
      ->default_str("table");
}

namespace {

std::string scalar_text(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v.get<double>());
    return buf;
  }
  return v.dump();
}

bool is_scalar(const nlohmann::json& v) {
  return !v.is_object() && !v.is_array();
}

// A short array of scalars prints inline; anything longer is summarised.
std::string inline_text(const nlohmann::json& v) {
  if (is_scalar(v)) return scalar_text(v);
  if (v.is_array() && v.size() <= 8 &&
      std::all_of(v.begin(), v.end(), [](const auto& e) { return is_scalar(e); })) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + scalar_text(v[i]);
    return s + "]";
  }
  if (v.is_array() && v.size() <= 4 && std::all_of(v.begin(), v.end(), [](const auto& e) {
        return e.is_array() && e.size() <= 4;
      })) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + inline_text(v[i]);
    return s + "]";
  }
  return v.is_array() ? "(" + std::to_string(v.size()) + " items; use --format json)"
                      : "(object; use --format json)";
}

void key_value_rows(const nlohmann::json& obj, const std::string& prefix,
                    std::vector<std::pair<std::string, std::string>>& rows,
                    std::vector<std::pair<std::string, const nlohmann::json*>>& tables) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    const std::string key = prefix + it.key();
    const auto& v = it.value();
    if (v.is_object()) {
      key_value_rows(v, key + ".", rows, tables);
    } else if (v.is_array() && !v.empty() &&
               std::all_of(v.begin(), v.end(), [](const auto& e) { return e.is_object(); })) {
      tables.emplace_back(key, &v);
    } else {
      rows.emplace_back(key, inline_text(v));
    }
  }
}

void print_rows(const std::vector<std::pair<std::string, std::string>>& rows, std::ostream& out) {
  std::size_t width = 0;
  for (const auto& [k, _] : rows) width = std::max(width, k.size());
  for (const auto& [k, v] : rows) out << k << std::string(width - k.size() + 2, ' ') << v << '\n';
}

// An array of objects prints as a table whose columns are the keys of its first element.
void print_table(const std::string& title, const nlohmann::json& arr, std::ostream& out) {
  std::vector<std::string> columns;
  for (auto it = arr.front().begin(); it != arr.front().end(); ++it) columns.push_back(it.key());
  std::vector<std::vector<std::string>> cells;
  std::vector<std::size_t> width;
  for (const auto& c : columns) width.push_back(c.size());
  for (const auto& row : arr) {
    std::vector<std::string> line;
    for (std::size_t i = 0; i < columns.size(); ++i) {
      line.push_back(row.contains(columns[i]) ? inline_text(row[columns[i]]) : "");
      width[i] = std::max(width[i], line.back().size());
    }
    cells.push_back(std::move(line));
  }
  out << '\n' << title << ":\n";
  auto print_line = [&](const std::vector<std::string>& line) {
    for (std::size_t i = 0; i < line.size(); ++i)
      out << (i ? "  " : "  ") << line[i] << std::string(width[i] - line[i].size(), ' ');
    out << '\n';
  };
  print_line(columns);
  for (const auto& line : cells) print_line(line);
}

} // namespace

void emit(const nlohmann::json& result, Format format, std::ostream& out) {
  if (format == Format::Json) {
    out << result.dump(2) << '\n';
    return;
  }
  if (!result.is_object()) {
    out << inline_text(result) << '\n';
    return;
  }
  std::vector<std::pair<std::string, std::string>> rows;
  std::vector<std::pair<std::string, const nlohmann::json*>> tables;
  key_value_rows(result, "", rows, tables);
  print_rows(rows, out);
  for (const auto& [title, arr] : tables) print_table(title, *arr, out);
}

} // namespace antkit::cli
