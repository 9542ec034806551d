#pragma once
// A test server that behaves as Webots' Khepera TCP/IP relay controller does, written from the
// facts in PROTOCOLS.md, the shared devices notes ("Khepera in Webots, over TCP"), not from
// antkit's emulator, so that an adapter tested against it is not only tested against our own code:
//   * it listens with a backlog of 1 (on 127.0.0.1 here; the real relay on port 10020 of any
//     address: the port is a parameter, 0 for any free one) and accepts one client, once: it never
//     calls accept() again, so a second client's connect completes in the kernel's backlog and is
//     never served, and a client that has gone cannot come back;
//   * every control step (250 ms of simulated time; here a short real period, a parameter) it
//     polls the socket without waiting, reads at most 256 bytes and acts on the first letter of
//     what it read only -- a second command in the same read is lost;
//   * replies end CR LF; an unknown command gets a bare "\n"; `exit` closes the connection;
//   * D,l,r sets the wheels' velocities in rad/s (at most the motors' default maxVelocity, 10);
//     G,l,r answers "g" and does nothing; H answers each wheel's angle since the start as
//     (int)(50 * angle / pi), 100 counts a turn, never reset; N answers eight readings (a trivial
//     world: the given constant readings, all 0 in open space by default); O eight light readings;
//     B answers "b,0,0"; L,n,a answers "l".
// The wheel angles advance by velocity x 0.25 s every control step, as the simulation's do.
#include <algorithm>
#include <arpa/inet.h>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <netinet/in.h>
#include <poll.h>
#include <stdexcept>
#include <string>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace antkit::test {

// What the relay's world is, and how fast it runs.
struct WebotsRelayOptions {
  std::uint16_t port = 0;               // 0: any free port (the relay's is 10020)
  std::chrono::microseconds step{1000}; // real time per control step
  std::array<int, 8> proximity{};       // what N reads (open space: all 0)
  std::array<int, 8> light{};           // what O reads
};

class WebotsRelay {
public:
  using Options = WebotsRelayOptions;

  explicit WebotsRelay(Options options = Options()) : options_(options) {
    listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (listen_fd_ < 0) throw std::runtime_error("relay: socket");
    const int one = 1;
    ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(options_.port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::bind(listen_fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 ||
        ::listen(listen_fd_, 1) != 0) {
      ::close(listen_fd_);
      throw std::runtime_error("relay: cannot listen");
    }
    socklen_t len = sizeof a;
    ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&a), &len);
    port_ = ntohs(a.sin_port);
    thread_ = std::thread([this] { run(); });
  }
  WebotsRelay(const WebotsRelay&) = delete;
  WebotsRelay& operator=(const WebotsRelay&) = delete;
  ~WebotsRelay() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    if (client_fd_ >= 0) ::close(client_fd_);
    if (listen_fd_ >= 0) ::close(listen_fd_);
  }

  [[nodiscard]] std::uint16_t port() const noexcept { return port_; }
  [[nodiscard]] std::string port_spec() const { return "tcp:127.0.0.1:" + std::to_string(port_); }
  // What it read, one entry per read (each acted on by its first letter only).
  [[nodiscard]] std::vector<std::string> reads() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return reads_;
  }
  [[nodiscard]] int accepted() const noexcept { return accepted_.load(); }

private:
  void run() {
    // The relay blocks in accept() when the simulation starts; here: until a client comes or the
    // test ends.
    while (!stop_ && client_fd_ < 0) {
      pollfd p{listen_fd_, POLLIN, 0};
      if (::poll(&p, 1, 5) > 0) {
        client_fd_ = ::accept(listen_fd_, nullptr, nullptr);
        if (client_fd_ >= 0) ++accepted_;
      }
    }
    while (!stop_) {
      std::this_thread::sleep_for(options_.step); // wb_robot_step(250)
      for (int w = 0; w < 2; ++w) angle_[w] += velocity_[w] * 0.25;
      if (client_fd_ < 0) continue; // gone: the relay cannot take another client
      pollfd p{client_fd_, POLLIN, 0};
      if (::poll(&p, 1, 0) <= 0) continue; // no wait: nothing this step
      char buffer[257];
      const ssize_t n = ::recv(client_fd_, buffer, 256, 0);
      if (n <= 0) { // the client has closed (or reset) its end
        ::close(client_fd_);
        client_fd_ = -1;
        continue;
      }
      buffer[n] = '\0';
      {
        std::lock_guard<std::mutex> lock(mutex_);
        reads_.emplace_back(buffer, static_cast<std::size_t>(n));
      }
      act(buffer);
    }
  }

  void reply(const std::string& text) {
    ::send(client_fd_, text.data(), text.size(), MSG_NOSIGNAL);
  }

  static std::string values(char letter, const std::array<int, 8>& v) {
    std::string s(1, letter);
    for (const int x : v) s += "," + std::to_string(x);
    return s + "\r\n";
  }

  void act(const char* buffer) {
    switch (buffer[0]) {
    case 'D': {
      int l = 0, r = 0;
      if (std::sscanf(buffer, "D,%d,%d", &l, &r) == 2) {
        // The motors' maxVelocity bounds what a velocity can be.
        velocity_[0] = std::max(-kMaxVelocity, std::min(kMaxVelocity, static_cast<double>(l)));
        velocity_[1] = std::max(-kMaxVelocity, std::min(kMaxVelocity, static_cast<double>(r)));
      }
      return reply("d\r\n");
    }
    case 'L':
      return reply("l\r\n");
    case 'G': // the position counters are not reset
      return reply("g\r\n");
    case 'B':
      return reply("b,0,0\r\n");
    case 'N':
      return reply(values('n', options_.proximity));
    case 'O':
      return reply(values('o', options_.light));
    case 'H': {
      const int l = static_cast<int>(50.0 * angle_[0] / M_PI);
      const int r = static_cast<int>(50.0 * angle_[1] / M_PI);
      return reply("h," + std::to_string(l) + "," + std::to_string(r) + "\r\n");
    }
    default:
      if (std::strncmp(buffer, "exit", 4) == 0) {
        ::close(client_fd_);
        client_fd_ = -1;
        return;
      }
      return reply("\n");
    }
  }

  static constexpr double kMaxVelocity = 10.0;
  Options options_;
  int listen_fd_ = -1, client_fd_ = -1;
  std::uint16_t port_ = 0;
  std::atomic<bool> stop_{false};
  std::atomic<int> accepted_{0};
  double velocity_[2] = {0, 0}, angle_[2] = {0, 0};
  mutable std::mutex mutex_;
  std::vector<std::string> reads_;
  std::thread thread_;
};

} // namespace antkit::test
