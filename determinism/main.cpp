// antkit_determinism: the determinism matrix's program (scripts/determinism.sh, issue 16). It runs
// the golden scenarios of scenarios.cpp, one per controller family and body, in the mode below. It
// links only antkit::algorithms and antkit::kernel, plus the map readers (antkit::maps, which
// needs no CGAL) and the marker-floor robot's integer camera, floor and pilot
// (devices/src/stc_floor_*.cpp but its calibration file: no JSON library), so that any compiler
// builds it and it cross-compiles to a big-endian CPU.
//
//   antkit_determinism --maps DIR [--threads T]   prints "name hash" per scenario
//   antkit_determinism --maps DIR --check FILE [--threads T]
//                                                 exit 1 unless every scenario's hash is FILE's
//   antkit_determinism --maps DIR --trace NAME    one line per step of NAME's run: the step, a
//                                                 hash of the states up to it, and its state (for
//                                                 finding the first step where two builds part)
//   antkit_determinism --maps DIR --mcu-inputs DIR2
//                                                 writes the Cortex-M image's input of every
//                                                 scenario it runs (STC; Buffon on the square with
//                                                 a pillar; the wanderer alone) into DIR2, "name
//                                                 file" per line
//                                                 (the matrix's cortex-m4 configuration)
//   antkit_determinism --maps DIR --stc-tours     every shared map's STC tours (issue 27): per map
//                                                 of DIR/movingai and DIR/ros (name order) and
//                                                 variant the chip runs (ant, ant-edge, online),
//                                                 from `antkit stc`'s start: "stc-tour/<variant>/
//                                                 <file> hash covered repeats returned_to_start"
//   antkit_determinism --teeth native-endian [--check FILE | --trace teeth/native-endian]
//                                                 Buffon's first trail hashed over the bytes of its
//                                                 coordinates as this CPU stores them: FILE's hash
//                                                 on a little-endian CPU only (the matrix's teeth)
//
// Exit status: 0 all match, 1 a mismatch or a missing golden line, 2 bad usage or input.
#include "scenarios.hpp"

#include <algorithm>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/start.hpp>
#include <antkit/stc/world.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace antkit;
using determinism::MapShelf;
using determinism::native_endian_hash;
using determinism::scenarios;
using determinism::Trace;

// `--mcu-inputs DIR`: each Cortex-M input (determinism::for_each_mcu_input) in its own file of
// `dir`, named by the scenario with '/' as '_'; prints "name file" per scenario.
void write_mcu_inputs(MapShelf& shelf, const std::string& dir) {
  determinism::for_each_mcu_input(
      shelf, [&dir](const std::string& name, const std::vector<std::uint8_t>& bytes) {
        std::string file = dir + "/" + name;
        for (auto k = file.size() - name.size(); k < file.size(); ++k)
          if (file[k] == '/') file[k] = '_';
        std::ofstream out(file, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
        if (!out.flush()) throw kernel::InputError(file, "cannot write");
        std::printf("%s %s\n", name.c_str(), file.c_str());
      });
}

// `--stc-tours`: the tours `antkit stc --map F --variant V` makes on every shared map, for the
// variants the Cortex-M image runs, so that a build for another CPU (32-bit ARM Linux under
// qemu-user: scripts/determinism.sh) can be held to the host's on every map, not only the golden
// scenarios' three; determinism/check_stc_tours.sh holds this listing to `antkit stc` itself.
void print_stc_tours(const std::string& maps_dir) {
  std::vector<std::filesystem::path> files;
  for (const char* sub : {"movingai", "ros"})
    for (const auto& entry : std::filesystem::directory_iterator(maps_dir + "/" + sub)) {
      const auto ext = entry.path().extension();
      if (ext == ".map" || ext == ".yaml") files.push_back(entry.path());
    }
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    const maps::GridMap map = maps::load_map(file);
    for (const auto variant : {stc::Variant::Ant, stc::Variant::AntEdge, stc::Variant::Online}) {
      const stc::SubCell start =
          stc::choose_start(map.cells, variant, std::nullopt, map.start, file.string());
      const stc::RunResult r = stc::run_stc(map.cells, start, variant);
      std::printf("stc-tour/%s/%s %s %lld %lld %s\n",
                  std::string(stc::variant_name(variant)).c_str(), file.filename().string().c_str(),
                  kernel::hash_hex(r.hash).c_str(), static_cast<long long>(r.covered),
                  static_cast<long long>(r.repeats), r.returned_to_start ? "true" : "false");
    }
  }
}

int usage(const std::string& why) {
  std::fprintf(stderr,
               "antkit_determinism: %s\nusage: antkit_determinism --maps DIR [--threads T] "
               "[--check FILE | --trace NAME | --list | --mcu-inputs DIR | --stc-tours]\n       "
               "antkit_determinism --teeth "
               "native-endian [--check FILE | --trace teeth/native-endian]\n",
               why.c_str());
  return 2;
}

int check_against(const std::map<std::string, std::string>& got, const std::string& file,
                  unsigned threads) {
  std::ifstream in(file);
  if (!in) {
    std::fprintf(stderr, "antkit_determinism: %s: cannot read\n", file.c_str());
    return 2;
  }
  std::size_t bad = 0, checked = 0, line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string name, hash, extra;
    if (!(fields >> name >> hash) || (fields >> extra) || hash.size() != 16) {
      std::fprintf(stderr, "antkit_determinism: %s:%zu: expected \"name hash\" (16 hex digits)\n",
                   file.c_str(), line_no);
      return 2;
    }
    const auto it = got.find(name);
    if (it == got.end()) continue; // another mode's line (the teeth, or the scenarios)
    ++checked;
    if (it->second != hash) {
      std::printf("MISMATCH %s: golden %s, this build %s\n", name.c_str(), hash.c_str(),
                  it->second.c_str());
      ++bad;
    }
  }
  if (checked != got.size()) {
    for (const auto& [name, hash] : got) {
      std::ifstream again(file);
      bool found = false;
      for (std::string line; !found && std::getline(again, line);)
        found = line.rfind(name + " ", 0) == 0;
      if (!found)
        std::printf("MISSING %s %s: no golden line in %s\n", name.c_str(), hash.c_str(),
                    file.c_str());
    }
    return 1;
  }
  std::printf("determinism: %zu of %zu scenarios match %s (threads %u)\n", checked - bad, checked,
              file.c_str(), threads);
  return bad == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
  unsigned threads = 1;
  std::string maps_dir, check, trace_name, teeth, mcu_dir;
  bool list = false, stc_tours = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--list" || a == "--stc-tours") {
      (a == "--list" ? list : stc_tours) = true;
      continue;
    }
    if (i + 1 >= argc) return usage(a + " needs a value");
    const std::string v = argv[++i];
    if (a == "--threads") {
      if (v.empty() || v.size() > 2 ||
          !std::all_of(v.begin(), v.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return usage("--threads: expected 1 to 64, got '" + v + "'");
      threads = static_cast<unsigned>(std::stoul(v));
      if (threads < 1 || threads > 64) return usage("--threads: expected 1 to 64, got " + v);
    } else if (a == "--maps") {
      maps_dir = v;
    } else if (a == "--check") {
      check = v;
    } else if (a == "--trace") {
      trace_name = v;
    } else if (a == "--teeth") {
      teeth = v;
    } else if (a == "--mcu-inputs") {
      mcu_dir = v;
    } else {
      return usage("unknown option " + a);
    }
  }
  if (!teeth.empty() && teeth != "native-endian")
    return usage("--teeth: only native-endian, got " + teeth);
  if (teeth.empty() && maps_dir.empty()) return usage("--maps DIR is required");
  try {
    std::map<std::string, std::string> got;
    if (!teeth.empty()) {
      std::vector<std::string> lines;
      Trace trace(trace_name.empty() ? nullptr : &lines);
      got["teeth/native-endian"] = kernel::hash_hex(native_endian_hash(trace));
      for (std::size_t k = 0; k < lines.size(); ++k) std::printf("%zu %s\n", k, lines[k].c_str());
      if (!trace_name.empty()) return 0;
    } else {
      if (stc_tours) {
        print_stc_tours(maps_dir);
        return 0;
      }
      MapShelf shelf(maps_dir);
      if (!mcu_dir.empty()) {
        write_mcu_inputs(shelf, mcu_dir);
        return 0;
      }
      const auto all = scenarios(shelf);
      if (list) {
        for (const auto& s : all) std::printf("%s\n", s.name.c_str());
        return 0;
      }
      if (!trace_name.empty()) {
        for (const auto& s : all)
          if (s.name == trace_name) {
            std::vector<std::string> lines;
            Trace trace(&lines);
            s.run(threads, trace);
            for (std::size_t k = 0; k < lines.size(); ++k)
              std::printf("%zu %s\n", k, lines[k].c_str());
            return 0;
          }
        return usage("no scenario " + trace_name + " (--list lists them)");
      }
      for (const auto& s : all) {
        Trace none(nullptr);
        got[s.name] = kernel::hash_hex(s.run(threads, none));
      }
    }
    if (check.empty()) {
      for (const auto& [name, hash] : got) std::printf("%s %s\n", name.c_str(), hash.c_str());
      return 0;
    }
    return check_against(got, check, threads);
  } catch (const kernel::InputError& e) {
    std::fprintf(stderr, "antkit_determinism: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "antkit_determinism: %s\n", e.what());
    return 2;
  }
}