#pragma once
// What every subcommand shares: the --format option and the printing of a result, as a table for
// people (the default) or as JSON for programs. A subcommand builds one JSON value and calls
// emit().
#include <CLI/CLI.hpp>
#include <antkit/algorithms/units.hpp>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>
#include <string>
#if ANTKIT_HAVE_MPI
#include <antkit/mpi/session.hpp>
#endif

namespace antkit::cli {

enum class Format { Table, Json };

// Progress of an experiment's stages on stderr: a live bar with the time left when stderr is a
// terminal, else a line per quarter of each stage ("tool: stage: done/total units, t s").
antkit::algorithms::Progress stage_progress(const std::string& tool);

// Adds `--format table|json` to a subcommand.
void add_format_option(CLI::App& sub, Format& format);

// Prints `result`: JSON on one line per top-level value (pretty, indent 2), or a table.
void emit(const nlohmann::json& result, Format format, std::ostream& out);

// Makes the directory --out names (and its parents), or throws kernel::InputError("--out", ...):
// an output directory that cannot be made is refused before a run, not after it.
void make_out_dir(const std::string& dir);

#if ANTKIT_HAVE_MPI
// Under mpirun: rank 0 makes --out and every rank learns whether it could (a collective). Returns
// true when it was made; on rank 0 a refusal throws kernel::InputError("--out", ...), on the other
// ranks it returns false (they have nothing to report and stop).
bool make_out_dir_on_rank0(const antkit::mpi::Session& session, const std::string& dir);
#endif

// A failed check (a replay that diverges, an invariant that does not hold): exit status 1.
class CheckFailed : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace antkit::cli
