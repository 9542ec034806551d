#pragma once
// Each subcommand lives in its own file and adds itself to the app through one function here.
#include <CLI/CLI.hpp>

namespace antkit::cli {} // namespace antkit::cli
