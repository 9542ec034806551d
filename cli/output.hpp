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

// A run a stop signal ended (after its safe stop, with the robot known to be stopped): exit status
// 128 + the signal's number, as a shell reports a process the signal killed (130 for SIGINT, 143
// SIGTERM, 129 SIGHUP, 131 SIGQUIT), so that `record ... && record ...` stops at the first.
class Interrupted : public std::runtime_error {
public:
  Interrupted(int signal, const std::string& what) : std::runtime_error(what), signal_(signal) {}
  [[nodiscard]] int status() const noexcept { return 128 + signal_; }

private:
  int signal_;
};

} // namespace antkit::cli
