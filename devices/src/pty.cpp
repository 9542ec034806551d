// The emulators' pseudo-terminals (serial.hpp).
#include <antkit/devices/serial.hpp>
#include <cerrno>
#include <fcntl.h>
#include <stdlib.h>
#include <system_error>
#include <termios.h>
#include <unistd.h>
#include <utility>

namespace antkit::devices {

Pty::Pty(SerialPort master, std::string slave_path, int keeper)
    : master_(std::move(master)), slave_path_(std::move(slave_path)), keeper_(keeper) {}

Pty Pty::open() {
  const int m = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (m < 0) throw std::system_error(errno, std::generic_category(), "posix_openpt");
  if (::grantpt(m) != 0 || ::unlockpt(m) != 0) {
    const int err = errno;
    ::close(m);
    throw std::system_error(err, std::generic_category(), "grantpt/unlockpt");
  }
  char name[128] = {};
  if (::ptsname_r(m, name, sizeof name) != 0) {
    const int err = errno;
    ::close(m);
    throw std::system_error(err, std::generic_category(), "ptsname");
  }
  // Raw mode on the pair before any client opens it: no echo, no CR/NL translation.
  const int keeper = ::open(name, O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (keeper < 0) {
    const int err = errno;
    ::close(m);
    throw std::system_error(err, std::generic_category(), "open pty slave");
  }
  termios t{};
  ::tcgetattr(keeper, &t);
  ::cfmakeraw(&t);
  ::tcsetattr(keeper, TCSANOW, &t);
  return Pty(SerialPort(m, std::string("pty master of ") + name), name, keeper);
}

Pty::~Pty() {
  close_slave_keeper();
}

void Pty::close_slave_keeper() noexcept {
  if (keeper_ >= 0) ::close(keeper_);
  keeper_ = -1;
}

void Pty::hang_up() noexcept {
  master_.close();
  close_slave_keeper();
}

} // namespace antkit::devices
