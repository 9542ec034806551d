// replay_records() reads a whole log a batch ahead on a second thread (replay.hpp): held to the
// reading on the calling thread, result for result and error for error, on a 2000-step Khepera
// log (eight batches) as it was recorded and damaged in the ways logs are damaged: cut at any
// byte, a malformed line, a record edited (a divergence, then the rest read unchecked), the stop
// record missing.
#include "emulated_robot.hpp"

#include <antkit/devices/controllers.hpp>
#include <antkit/devices/emulated_log.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <fstream>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <sstream>
#include <variant>

namespace devices = antkit::devices;
using antkit::test::TempDir;

namespace {

const std::string& long_log() {
  static const std::string log =
      devices::emulated_log(devices::RobotKind::Khepera,
                            antkit::geometry::build_arena_spec("circle:d=30").arena.walls_fx(),
                            devices::make_spec("buffon", 3, {{"visit", 1}}, "test"), 2000);
  return log;
}

// The replay's result, or the error it threw.
using Outcome = std::variant<devices::ReplayResult, std::string>;
Outcome replay_with(const std::string& path, devices::detail::ReadAhead mode) {
  devices::detail::set_read_ahead(mode);
  Outcome out;
  try {
    out = devices::replay(path);
  } catch (const antkit::kernel::InputError& e) {
    out = std::string(e.what());
  }
  devices::detail::set_read_ahead(devices::detail::ReadAhead::Auto);
  return out;
}

std::string describe(const Outcome& o) {
  if (const auto* e = std::get_if<std::string>(&o)) return "error: " + *e;
  const auto& r = std::get<devices::ReplayResult>(o);
  std::ostringstream s;
  s << "steps " << r.steps << ", identical " << r.identical << ", truncated " << r.truncated
    << ", complete " << r.complete << ", hash " << r.hash;
  if (r.first_divergence)
    s << ", divergence at " << r.first_divergence->step << " " << r.first_divergence->field;
  return s.str();
}

void write(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

} // namespace

TEST_CASE("replay reads ahead to the same result: the recorded log", "[devices][replay]") {
  TempDir dir;
  const auto path = dir.file("long.jsonl");
  write(path, long_log());
  const auto ahead = replay_with(path, devices::detail::ReadAhead::Always);
  const auto here = replay_with(path, devices::detail::ReadAhead::Never);
  INFO(describe(ahead) << " / " << describe(here));
  REQUIRE(std::holds_alternative<devices::ReplayResult>(ahead));
  CHECK(std::get<devices::ReplayResult>(ahead).identical);
  CHECK(std::get<devices::ReplayResult>(ahead).steps == 2000);
  CHECK(ahead == here);
}

TEST_CASE("replay reads ahead to the same result: damaged logs", "[devices][replay][property]") {
  TempDir dir;
  const auto path = dir.file("damaged.jsonl");
  const std::string& log = long_log();
  std::vector<std::size_t> starts; // each line's first byte
  for (std::size_t at = 0; at < log.size(); at = log.find('\n', at) + 1) starts.push_back(at);
  rc::prop("the same outcome read ahead and not", [&] {
    std::string text = log;
    const auto line = *rc::gen::inRange<std::size_t>(1, starts.size() - 1);
    switch (*rc::gen::inRange(0, 4)) {
    case 0: // cut at any byte
      text.resize(*rc::gen::inRange<std::size_t>(starts[1], log.size()));
      break;
    case 1: // a malformed line
      text.replace(starts[line], starts[line + 1] - starts[line] - 1, "{\"step\":oops}");
      break;
    case 2: { // a record edited (its state hash), and maybe a malformed line after it
      const auto at = text.find("\"state\":\"", starts[line]) + 9;
      text[at] = text[at] == '0' ? '1' : '0';
      if (*rc::gen::arbitrary<bool>() && line + 1 < starts.size() - 1) {
        const auto later = *rc::gen::inRange<std::size_t>(line + 1, starts.size() - 1);
        text.replace(starts[later], starts[later + 1] - starts[later] - 1, "junk");
      }
      break;
    }
    default: // the stop record missing
      text.resize(starts.back());
    }
    write(path, text);
    const auto ahead = replay_with(path, devices::detail::ReadAhead::Always);
    const auto here = replay_with(path, devices::detail::ReadAhead::Never);
    RC_LOG() << describe(ahead) << " / " << describe(here) << "\n";
    RC_ASSERT(ahead == here);
  });
}

// Reading ahead also reads records' exchanges as the replay's link does (LoggedLink::read_attempt,
// on the reading thread; every record's with AlwaysAttempts, else while that thread is ahead): the
// attempts worked out there must be the ones the checking thread works out itself, for exchanges
// damaged as a faulty line damages them: a reply replaced by stale lines, junk, a cut or a bad
// line, bytes after the reply, a failed attempt and its resend, a drain. Each damaged log replays
// to the same result (divergence and words) either way, and the damage must reach both outcomes:
// replays that stay identical (a fault then its resend, stale lines before the reply) and replays
// that diverge.
TEST_CASE("replay reads ahead to the same result: damaged exchanges",
          "[devices][replay][property]") {
  TempDir dir;
  const auto path = dir.file("exchanges.jsonl");
  const std::string& log = long_log();
  std::vector<std::size_t> starts; // each line's first byte
  for (std::size_t at = 0; at < log.size(); at = log.find('\n', at) + 1) starts.push_back(at);
  static const std::vector<std::string> kPieces = {"n,1,2,3,4,5,6,7,8\r\n",
                                                   "d\r\n",
                                                   "h,10,-20\r\n",
                                                   "e,0,0\r\n",
                                                   "z,Protocol error\r\n",
                                                   "n,1,2\r\n",
                                                   "h,1\r\n",
                                                   "junk",
                                                   "\r\n",
                                                   "\n",
                                                   "n,1,2,",
                                                   "d\r",
                                                   "h,99999999999,0\r\n",
                                                   "\xff\n"};
  std::size_t identical = 0, diverged = 0;
  rc::prop("the same outcome read ahead and not", [&] {
    std::string text = log;
    // A step record after the first (the first holds the identification and the start).
    const auto line = *rc::gen::inRange<std::size_t>(2, starts.size() - 2);
    const std::size_t begin = starts[line], end = starts[line + 1] - 1;
    devices::LogRecord r;
    RC_ASSERT(devices::detail::read_canonical_step(text.substr(begin, end - begin), r));
    RC_PRE(!r.io.empty());
    const auto k = *rc::gen::inRange<std::size_t>(0, r.io.size());
    std::string bytes = *rc::gen::element(std::string(), r.io[k].received);
    const auto pieces = *rc::gen::inRange(0, 4);
    for (int i = 0; i < pieces; ++i) {
      const auto& piece = *rc::gen::elementOf(kPieces);
      if (*rc::gen::arbitrary<bool>())
        bytes = piece + bytes;
      else
        bytes += piece;
    }
    switch (*rc::gen::inRange(0, 3)) {
    case 0: // the attempt's bytes damaged
      r.io[k].received = bytes;
      break;
    case 1: // a failed attempt before it, with those bytes: then the resend
      r.io.insert(r.io.begin() + static_cast<std::ptrdiff_t>(k),
                  devices::Exchange{r.io[k].sent, bytes, r.io[k].t_ns});
      break;
    default: // a drain before it
      r.io.insert(r.io.begin() + static_cast<std::ptrdiff_t>(k),
                  devices::Exchange{"", bytes, r.io[k].t_ns});
    }
    text.replace(begin, end - begin, devices::format_record(r));
    write(path, text);
    // Every record's attempts read ahead; those the reading thread had time for; none.
    const auto every = replay_with(path, devices::detail::ReadAhead::AlwaysAttempts);
    const auto ahead = replay_with(path, devices::detail::ReadAhead::Always);
    const auto here = replay_with(path, devices::detail::ReadAhead::Never);
    RC_LOG() << describe(every) << " / " << describe(ahead) << " / " << describe(here) << "\n";
    RC_ASSERT(every == here);
    RC_ASSERT(ahead == here);
    if (const auto* result = std::get_if<devices::ReplayResult>(&here))
      ++(result->identical ? identical : diverged);
  });
  CHECK(identical > 0);
  CHECK(diverged > 0);
}
