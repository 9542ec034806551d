// The port held exclusively (serial.hpp): the OFD lock on a serial device and the holder of a
// held one, named from /proc.
#include "serial_internal.hpp"

#include <antkit/kernel/input_error.hpp>
#include <cstdlib>
#include <dirent.h>
#include <fcntl.h>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace antkit::devices::serial_detail {

using kernel::InputError;

// The PID of a process other than (self, self_fd) that has `device` open with a lock on it (an OFD
// lock shows in the fdinfo of the holder's descriptor, as "lock: ... OFDLCK ..."), or -1.
long lock_holder(const struct stat& device, int self_fd) {
  DIR* proc = ::opendir("/proc");
  if (proc == nullptr) return -1;
  const long self = static_cast<long>(::getpid());
  long found = -1;
  while (const dirent* e = ::readdir(proc)) {
    char* end = nullptr;
    const long pid = std::strtol(e->d_name, &end, 10);
    if (end == e->d_name || *end != '\0' || pid <= 0) continue;
    const std::string base = "/proc/" + std::string(e->d_name);
    DIR* fds = ::opendir((base + "/fd").c_str());
    if (fds == nullptr) continue;
    while (const dirent* f = ::readdir(fds)) {
      if (f->d_name[0] == '.') continue;
      if (pid == self && std::atoi(f->d_name) == self_fd) continue;
      struct stat st {};
      if (::stat((base + "/fd/" + f->d_name).c_str(), &st) != 0) continue;
      if (st.st_dev != device.st_dev || st.st_ino != device.st_ino) continue;
      std::ifstream info(base + "/fdinfo/" + f->d_name);
      std::string line;
      while (std::getline(info, line))
        if (line.rfind("lock:", 0) == 0) found = pid;
      if (found > 0) break;
    }
    ::closedir(fds);
    if (found > 0) break;
  }
  ::closedir(proc);
  return found;
}

[[noreturn]] void port_busy(const std::string& path, long pid) {
  throw InputError("port", "'" + path + "' is busy: port busy" +
                               (pid > 0 ? ", held by process " + std::to_string(pid) : ""));
}

// An OFD write lock on the whole device (serial.hpp says why OFD). A kernel without OFD locks
// (EINVAL) leaves TIOCEXCL alone to hold the port.
void lock_port(int fd, const std::string& path) {
  struct flock lk {};
  lk.l_type = F_WRLCK;
  lk.l_whence = SEEK_SET;
  if (::fcntl(fd, F_OFD_SETLK, &lk) == 0) return;
  const int err = errno;
  if (err != EAGAIN && err != EACCES) return;
  struct flock who {};
  who.l_type = F_WRLCK;
  who.l_whence = SEEK_SET;
  long pid = -1;
  // A classic (per-process) lock's holder is named by GETLK; an OFD holder shows as -1.
  if (::fcntl(fd, F_OFD_GETLK, &who) == 0 && who.l_type != F_UNLCK && who.l_pid > 0)
    pid = who.l_pid;
  struct stat st {};
  if (pid <= 0 && ::fstat(fd, &st) == 0) pid = lock_holder(st, fd);
  port_busy(path, pid);
}

} // namespace antkit::devices::serial_detail
