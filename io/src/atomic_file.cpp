#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <atomic>
#include <fstream>
#include <string>
#include <system_error>
#include <unistd.h>

namespace antkit::io {

namespace {
std::filesystem::path temporary_beside(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  auto tmp = path;
  tmp += ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
  return tmp;
}
} // namespace

void write_file_atomic_at(const std::filesystem::path& path,
                          const std::function<void(const std::filesystem::path&)>& write) {
  const auto tmp = temporary_beside(path);
  try {
    write(tmp);
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) throw kernel::InputError(path.string(), "cannot rename into place: " + ec.message());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
}

void write_file_atomic(const std::filesystem::path& path,
                       const std::function<void(std::ostream&)>& write) {
  write_file_atomic_at(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw kernel::InputError(path.string(), "cannot open for writing");
    write(out);
    out.flush();
    if (!out) throw kernel::InputError(path.string(), "write failed");
  });
}

void write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  write_file_atomic(path, [&](std::ostream& out) {
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
  });
}

} // namespace antkit::io
