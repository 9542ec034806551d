#pragma once
// The link of a replay (internal; replay.cpp, device_epuck2.cpp): serves a body's requests from a
// log's exchanges, running the live link's decisions (link.hpp) on the logged bytes, whatever the
// framing. Each request the body asks for must be the bytes the log says were sent; after a
// failed attempt, the framing's resynchronisation must come next (when it has one); each
// attempt's received bytes must be what the live link could have read (Reading::Lines: stale
// lines, then the reply or a fault, nothing after a reply; Reading::Bytes: the reply's size
// exactly, or a fault); the attempts of one request end at its first valid reply, as live.
#include <antkit/devices/framing.hpp>
#include <antkit/devices/link.hpp>
#include <antkit/devices/replay.hpp>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::devices::detail {

// A divergence found inside the shared body code (a sent byte, a reply): ends the record's check.
struct Diverged {
  Divergence d;
};

// What one attempt's received bytes are to the live link (link.hpp) that sent the exchange's
// `sent`: its reply (the unit [begin, end) of `received`), a fault (the live link sent again),
// or bytes read after a reply line (a divergence; [begin, end) is that line). It follows from the
// exchange alone, so a replay that reads ahead works it out on its reading thread.
struct Attempt {
  enum class Kind : std::uint8_t { Reply, Fault, After };
  Kind kind = Kind::Fault;
  std::size_t begin = 0, end = 0;
  friend bool operator==(const Attempt&, const Attempt&) = default;
};

class LoggedLink final : public CommandLink {
public:
  LoggedLink(const Framing& framing, LinkOptions options)
      : framing_(framing), resync_(framing.resync()), options_(std::move(options)) {}
  // `attempts`: read_attempt() of each of io's exchanges, worked out ahead (a replay's reading
  // thread), or empty (each is read here when it is reached).
  void load(const std::vector<Exchange>& io, std::int64_t step, std::string field,
            std::span<const Attempt> attempts = {}) {
    io_ = &io;
    attempts_ = attempts.size() == io.size() ? attempts : std::span<const Attempt>();
    k_ = 0;
    step_ = step;
    field_ = std::move(field);
  }
  // What `e` is as the attempt that sent e.sent (Attempt): the framing's reading of its bytes.
  // Depends on the framing and `e` only, so it may run on another thread than the replay's.
  [[nodiscard]] Attempt read_attempt(const Exchange& e) const;
  // read_attempt(), and a Reply's values as the framing decoded them in judging it
  // (Framing::kind; cleared for any other attempt, or where the framing keeps none).
  [[nodiscard]] Attempt read_attempt(const Exchange& e, Fields& fields) const;
  [[nodiscard]] std::size_t position() const noexcept { return k_; }
  [[nodiscard]] bool at_end() const noexcept { return k_ >= io_->size(); }
  // In the stop record the log may end in the middle of a request (the run ended there): that is
  // a link failure, not a divergence.
  void set_end_is_failure(bool on) noexcept { end_is_failure_ = on; }

  [[nodiscard]] const Framing& framing() const noexcept override { return framing_; }
  [[nodiscard]] const LinkOptions& options() const noexcept override { return options_; }
  void pause(std::chrono::milliseconds) override {}
  void rearm() noexcept override {}
  [[nodiscard]] const Fields* reply_fields() const noexcept override {
    return fields_.letter != 0 ? &fields_ : nullptr;
  }
  [[nodiscard]] std::uint64_t sends() const noexcept override { return sends_; }
  [[nodiscard]] std::int64_t last_send_ns() const noexcept override { return last_send_ns_; }

  // The exchanges are the log's: nothing is appended to `io`.
  std::string transact(const std::string& request, std::vector<Exchange>& io) override;
  // The reply as a view of the log's own bytes (valid while the loaded exchanges are): no copy.
  std::string_view transact_view(const std::string& request, std::vector<Exchange>& io,
                                 std::string& reply) override;
  void resync(std::vector<Exchange>& io) override;

private:
  // The next exchange that sent something (drained bytes skipped): it must have sent `sent`.
  const Exchange& expect(const std::string& sent, bool resend);
  // transact(): the reply, in the loaded exchanges.
  std::string_view reply_of(const std::string& request);
  const Framing& framing_;
  std::string resync_; // framing_.resync(): the same bytes every time
  LinkOptions options_;
  const std::vector<Exchange>* io_ = nullptr;
  std::span<const Attempt> attempts_; // io_'s, read ahead (empty: read here)
  std::size_t k_ = 0;
  std::int64_t step_ = 0;
  std::string field_;
  bool end_is_failure_ = false;
  std::uint64_t sends_ = 0;
  std::int64_t last_send_ns_ = -1;
  Fields fields_; // the last reply's (reply_fields())
};

} // namespace antkit::devices::detail
