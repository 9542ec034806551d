#pragma once
// The one error type for bad input (DESIGN.md, Errors): a malformed file, an unknown spec, an
// out-of-range parameter. The `antkit` command prints `antkit: error: <what()>` and exits 2.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace antkit::kernel {

class InputError : public std::runtime_error {
public:
  // `where` names the input: a file (with a position), a spec, or the library's own word for a
  // parameter such as "trail width" (the command line shows each word as the option that carries
  // it: cli/main.cpp and each subcommand's Registration; the Python module shows it as it is).
  InputError(const std::string& where, const std::string& message)
      : std::runtime_error(where.empty() ? message : where + ": " + message), where_(where),
        message_(message) {}
  // A position in a text file; line and column count from 1 (column in bytes).
  InputError(const std::string& file, std::size_t line, std::size_t column,
             const std::string& message)
      : InputError(file + ":" + std::to_string(line) + ":" + std::to_string(column), message) {
    line_ = line;
    column_ = column;
  }

  [[nodiscard]] const std::string& where() const noexcept { return where_; }
  [[nodiscard]] const std::string& message() const noexcept { return message_; }
  [[nodiscard]] std::size_t line() const noexcept { return line_; } // 0 when not a file position
  [[nodiscard]] std::size_t column() const noexcept {
    return column_;
  } // 0 when not a file position

private:
  std::string where_;
  std::string message_;
  std::size_t line_ = 0;
  std::size_t column_ = 0;
};

} // namespace antkit::kernel
