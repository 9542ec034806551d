#pragma once
// The small option parsers the subcommands share (`--start X,Y`, `--size WxH`, whole numbers,
// probabilities written as decimals), in the library so that tests and fuzz/options.cpp call the
// code the command line runs. Every one reads the whole text exactly (no floating point, no
// leading spaces or signs the format does not name) and throws kernel::InputError(option, ...)
// naming the option and quoting the text on anything else.
#include <antkit/kernel/grid.hpp>
#include <cstdint>
#include <string_view>
#include <utility>

namespace antkit::algorithms {

// A decimal integer in the int64 range ("-12", "7"; not "", "+7", " 7", "7x", "1e3"). Throws
// InputError(option, "'text' is not <what>").
std::int64_t parse_integer(std::string_view option, std::string_view text,
                           std::string_view what = "an integer");

// "A<separator>B": two integers. Throws InputError(option, "'text' is not of the form <expected>").
std::pair<std::int64_t, std::int64_t> parse_pair(std::string_view option, std::string_view text,
                                                 char separator, std::string_view expected);

// "X,Y", each in the int32 range (a sub-cell or a cell; the caller checks it against its map).
kernel::Cell parse_cell(std::string_view option, std::string_view text);

// A probability written as a decimal in [0, 1] with at most six decimals ("0.01", "1", ".5",
// "0."), read exactly into parts per million.
std::uint32_t parse_probability_ppm(std::string_view option, std::string_view text);

} // namespace antkit::algorithms
