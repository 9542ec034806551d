// The papers as data (papers.hpp): the report's files, and the registered papers in id order.
#include <algorithm>
#include <antkit/experiments/papers.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <sstream>

namespace antkit::experiments {

// Generated from experiments/src/paper_*.cpp (experiments/CMakeLists.txt).
std::vector<PaperEntry> registered_papers();

void ReportFiles::dir(const std::string& sub) {
  std::error_code ec;
  std::filesystem::create_directories(out_ / sub, ec);
  if (!std::filesystem::is_directory(out_ / sub))
    throw kernel::InputError("output directory",
                             "cannot make the directory '" + (out_ / sub).string() + "'");
}

void ReportFiles::text(const std::string& rel_path, const std::string& content) {
  io::write_file_atomic(out_ / rel_path, content);
  files_.emplace_back(rel_path);
}

void ReportFiles::figure(const std::string& stem, const Figure& f) {
  save_figure(f, out_ / (stem + ".svg"), out_ / (stem + ".png"));
  files_.emplace_back(stem + ".svg");
  files_.emplace_back(stem + ".png");
}

std::string report_image(const std::string& stem, const std::string& alt) {
  return "![" + alt + "](" + stem + ".png)\n\n(" + stem + ".svg, " + stem + ".png)\n\n";
}

std::string embed_markdown(const std::string& md) {
  std::istringstream in(md);
  std::ostringstream out;
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    if (first && line.rfind("# ", 0) == 0) {
      first = false;
      continue;
    }
    first = false;
    if (line.rfind("#", 0) == 0) line = "##" + line;
    out << line << '\n';
  }
  return out.str();
}

const std::vector<PaperEntry>& papers() {
  static const std::vector<PaperEntry> entries = [] {
    auto all = registered_papers();
    std::sort(all.begin(), all.end(),
              [](const PaperEntry& a, const PaperEntry& b) { return a.id < b.id; });
    return all;
  }();
  return entries;
}

} // namespace antkit::experiments
