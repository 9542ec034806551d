#pragma once
// What every subcommand shares: the --format option and the printing of a result, as a table for
// people (the default) or as JSON for programs. A subcommand builds one JSON value and calls
// emit().
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>
#include <string>

namespace antkit::cli {

enum class Format { Table, Json };

// Adds `--format table|json` to a subcommand.
void add_format_option(CLI::App& sub, Format& format);

// Prints `result`: JSON on one line per top-level value (pretty, indent 2), or a table.
void emit(const nlohmann::json& result, Format format, std::ostream& out);

// A failed check (a replay that diverges, an invariant that does not hold): exit status 1.
class CheckFailed : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace antkit::cli
