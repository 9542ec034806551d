#pragma once
// `antkit buffon --mcap FILE`: one Buffon's-needle run of paper 000 (two random-walk visits of an
// arena) as MCAP for Foxglove (issue 42, "--mcap where a run has a timeline"). It writes trial 0
// (as --svg draws it): a run of several trials has one timeline per trial, and trial 0's is the
// one a reader can reproduce with --trials 1; /log's first line says "trial 0 of N".
// The visits are one after the other, as the robot makes them: visit 1's position j (j = 0 the
// start) is at j * kBuffonStepNs, visit 2's position j at (n1 + j) * kBuffonStepNs, n1 being
// visit 1's positions (steps + 1); sequence = that index on the run's timeline. Channels (schema
// encoding jsonschema, message encoding json; devices::mcap_schema's texts), frame "arena", 1 m a
// unit (a body diameter), the arena's own coordinates:
//   /arena         foxglove.SceneUpdate   at time 0: the walls as one line list
//   /visit1/pose   foxglove.PoseInFrame   each position of visit 1: the robot's centre, facing
//                                         the way it last moved (a blocked step keeps it)
//   /visit2/pose                          each position of visit 2
//   /visit1/trail  foxglove.PosesInFrame  every ceil(n / 100)-th position of the visit and its
//   /visit2/trail                         last, at most 1000 poses each (trail_due, trail_poses)
//   /log           foxglove.Log           what ran (INFO, time 0); each step of visit 2 whose
//                                         segment properly crosses visit 1's trail (INFO, with the
//                                         running count: the last is crossings_exact); the result
//                                         at the last position (INFO: crossings, BC, nBC, lengths,
//                                         the closed-form area and its interval)
// The pheromone detector's transitions (BC) are counted by the trial, not kept per step: /log has
// the exact crossings' steps and BC's total.
#include <antkit/buffon/area_measurement.hpp>
#include <antkit/commands/stc_mcap.hpp>
#include <filesystem>
#include <string>

namespace antkit::commands {

inline constexpr std::uint64_t kBuffonStepNs = 100000000; // 10 steps a second

// Before the run: InputError ("--mcap") under --precision's markers rule (one walk lays both
// markers in alternating pieces: there are no two visits to draw; --rule fixed or online have
// them), and for a run whose visits may hold more than kStcMcapMaxSubcells positions together
// (without --precision, or with the fixed rule: known from the steps). The online rule's lengths
// are known after the run: write_buffon_mcap checks them.
void check_buffon_mcap(const buffon::AreaMeasurementParams& params);

// Writes trial 0 of `m` (measured on `world` with params.keep_first_trails) to `out`, whole or not
// at all. `arena` names the arena (its spec or file), `area` is its exact area. InputError
// ("--mcap") for visits of more than kStcMcapMaxSubcells positions together.
McapWritten write_buffon_mcap(const buffon::World& world, const buffon::AreaMeasurement& m,
                              const buffon::AreaMeasurementParams& params, const std::string& arena,
                              double area, const std::filesystem::path& out);

} // namespace antkit::commands
