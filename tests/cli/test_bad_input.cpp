// Bad input, counted: a table of malformed inputs across every parser and every subcommand of the
// real `antkit` executable (files of every format, options, ranges, empty and huge values, binary
// junk). Each must exit 2 with nothing on standard output, one message on standard error that
// starts "antkit: error: " and names where the input is bad (FILE:LINE:COLUMN, the option, or the
// argument), and must leave no output file behind: the scratch directory holds exactly the input
// files before and after every case, although most cases also ask for an output file there.
#include "run_antkit.hpp"
#include "scratch_dir.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>

using antkit::test::run_antkit;
using antkit::test::shared_map;
namespace fs = std::filesystem;

namespace {

struct Case {
  std::string args;  // {D} is the scratch directory, {M} a good MovingAI map, {B} a large one
  std::string where; // the message after "antkit: error: " starts with this ({D} replaced)
  std::string says;  // and contains this
};

std::string expand(std::string text, const std::string& dir, const std::string& map) {
  const std::string big = shared_map("movingai/brc202d.map"); // too large for the Cortex-M image
  for (const auto& [key, value] :
       {std::pair<std::string, std::string>{"{D}", dir}, {"{M}", map}, {"{B}", big}}) {
    for (auto at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
      text.replace(at, key.size(), value);
  }
  return text;
}

void write(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// Deterministic binary junk (every byte value but NUL, newline and quote characters).
std::string junk(std::size_t n, unsigned salt) {
  std::string s;
  std::uint32_t x = 2463534242u ^ salt;
  while (s.size() < n) {
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    const auto c = static_cast<char>(x & 0xFF);
    if (c != '\0' && c != '\n' && c != '\'' && c != '"') s += c;
  }
  return s;
}

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir)) names.insert(e.path().string());
  return names;
}

} // namespace

TEST_CASE("antkit: every malformed input of the table exits 2, located, with no output file",
          "[cli][errors]") {
  const antkit::test::ScratchDir scratch("bad-input");
  const fs::path& dir = scratch.path();
  const fs::path d = dir;
  // MovingAI maps
  write(d / "junk.map", junk(300, 1));
  write(d / "empty.map", "");
  write(d / "short.map", "type octile\nheight 2\nwidth 3\nmap\n...\n.x\n");
  write(d / "badchar.map", "type octile\nheight 2\nwidth 2\nmap\n..\n.Q\n");
  write(d / "huge.map", "type octile\nheight 99999999\nwidth 99999999\nmap\n");
  write(d / "noheight.map", "type octile\nwidth 2\nmap\n..\n");
  write(d / "blocked.map", "type octile\nheight 2\nwidth 2\nmap\n@@\n@@\n");
  // ROS map_server pairs
  write(d / "junk.yaml", junk(200, 2));
  write(d / "nopgm.yaml", "image: absent.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                          "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  write(d / "negres.yaml", "image: ok.pgm\nresolution: -1\norigin: [0, 0, 0]\nnegate: 0\n"
                           "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  write(d / "negate.yaml", "image: ok.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 2\n"
                           "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  write(d / "thresh.yaml", "image: ok.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                           "occupied_thresh: 0.1\nfree_thresh: 0.9\n");
  write(d / "shortpgm.yaml", "image: short.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                             "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  write(d / "ok.pgm", std::string("P5\n2 2\n255\n") + std::string(4, '\xfe'));
  write(d / "short.pgm", std::string("P5\n2 2\n255\n") + std::string(1, '\xfe'));
  // ASCII maps
  write(d / "junk.txt", junk(200, 3));
  write(d / "ragged.txt", "..\n.#?\n");
  // WKT arenas
  write(d / "junk.wkt", junk(300, 4));
  write(d / "empty.wkt", "");
  write(d / "open.wkt", "POLYGON ((0 0, 10 0, 10 10, 0 10))");
  write(d / "bowtie.wkt", "POLYGON ((0 0, 1 1, 1 0, 0 1, 0 0))");
  // hardware logs
  write(d / "junk.jsonl", junk(300, 5));
  write(d / "empty.jsonl", "");
  write(d / "header.jsonl", "{\"antkit_log\":1}\n");
  write(d / "nested.jsonl", std::string(4096, '[') + "\n");
  // A Hemisson log from before exchange times were logged: its odometry cannot be reckoned again.
  write(
      d / "untimed.jsonl",
      "{\"schema\":1,\"antkit\":\"0.1.0\",\"robot\":\"hemisson\",\"port\":{\"path\":\"/dev/pts/1\","
      "\"baud\":115200,\"framing\":\"8N1\"},\"controller\":{\"name\":\"buffon\",\"params\":"
      "{\"trial\":0,\"visit\":1}},\"seed\":1}\n"
      "{\"step\":0,\"t_ns\":5000,\"io\":[[\"N\\r\",\"n,0,0,0,0,0,0,0,0\\r\\n\"],[\"D,4,4\\r\","
      "\"d\\r\\n\"]],"
      "\"obs\":[0,0,0,0,0,0],\"cmd\":[0,0,4,4],\"odo\":[0,0],\"state\":\"0000000000000000\"}\n");
  // tours (antkit check stc)
  write(d / "tour_text.csv", "zero,one\n");
  write(d / "tour_row.csv", "x,y\n0,0\n1,zero\n");
  write(d / "tour_empty.csv", "");
  write(d / "tour_ok.csv", "0,0\n1,0\n");
  write(d / "tour_syntax.json", "[[0,0],\n[1,0,]");
  write(d / "tour_shape.json", "{\"path\": [[0,0],[1,0,2]]}");
  write(d / "tour_float.json", "[[0,0.5]]");
  write(d / "tour_nopath.json", "{\"start\": [0,0]}");
  write(d / "tour_startoff.json", "{\"path\": [[0,0]], \"start\": [5000,0]}");
  write(d / "tour_junk.json", "[" + junk(200, 7));
  // cell states (check explore) and coverage traces (check cover)
  write(d / "cells_ragged.txt", "FS\nF\n");
  write(d / "cells_char.txt", "FS\nFQ\n");
  write(d / "cells_small.txt", "FS\nFS\n");
  write(d / "cells_nocells.json", "{\"algo\": 1}");
  write(d / "cells_overflow.json", "{\"cells\": [\"F\"], \"eme\": 4E427}");
  write(d / "trace_order.csv", "0,0,0,0,0\n0,2,0,0,0\n");
  write(d / "trace_bearing.csv", "# sensor: 2\n0,0,0,0,9\n");
  write(d / "trace_nosensor.csv", "0,0,1,1,0\n");
  write(d / "trace_short.csv", "# sensor: 2\n0,0,1,1,0\n0,1,2,1,0\n1,0,1,1,0\n");
  // ROS 2 bags (bag info, buffon-from-logs --topic): junk, an MCAP file cut after its Header, a
  // .db3 that is not rosbag2's, a folder without metadata.yaml, a metadata.yaml of another storage
  write(d / "junk.mcap", junk(300, 8));
  write(d / "cut.mcap", std::string("\x89MCAP0\r\n\x01\x08", 10) + std::string(15, '\0'));
  write(d / "other.db3", std::string("SQLite format 3\0", 16) + junk(300, 9));
  fs::create_directories(d / "nometa");
  fs::create_directories(d / "leveldb");
  write(d / "leveldb" / "metadata.yaml",
        "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: leveldb\n");
  const auto inputs = listing(dir);

  const std::string bin = junk(12, 6);
  const std::vector<Case> cases{
      // map: every reader, through `map info` and `map convert`
      {"map info {D}/junk.map", "{D}/junk.map:1:1:", "type octile"},
      {"map info {D}/empty.map", "{D}/empty.map:1:1:", "header"},
      {"map info {D}/short.map", "{D}/short.map:6:3:", "row 1 has 2 cells"},
      {"map info {D}/badchar.map", "{D}/badchar.map:6:2:", "unexpected cell 'Q'"},
      {"map info {D}/huge.map", "{D}/huge.map:3:1:", "outside the supported range"},
      {"map info {D}/noheight.map", "{D}/noheight.map:3:1:", "height"},
      {"map info {D}/junk.yaml", "{D}/junk.yaml:1:1:", "key: value"},
      {"map info {D}/nopgm.yaml", "{D}/nopgm.yaml:1:8:", "cannot read the image"},
      {"map info {D}/negres.yaml", "{D}/negres.yaml:2:13:", "not positive"},
      {"map info {D}/negate.yaml", "{D}/negate.yaml:4:9:", "negate"},
      {"map info {D}/thresh.yaml", "{D}/thresh.yaml:6:14:", "free_thresh"},
      {"map info {D}/shortpgm.yaml", "{D}/short.pgm:4:2:", "truncated PGM"},
      {"map info {D}/junk.txt", "{D}/junk.txt:1:1:", "unexpected cell"},
      {"map info {D}/ragged.txt", "{D}/ragged.txt:2:3:", "row 1 has 3 cells"},
      {"map info {D}/missing.map", "{D}/missing.map:", "cannot open"},
      {"map info {D}/junk.pgm", "{D}/junk.pgm:", "unknown map extension"},
      {"map info", "--map is required", ""},
      {"map convert {M} {D}/out.bmp", "{D}/out.bmp:", "unknown map extension"},
      {"map convert {D}/junk.map {D}/out.map", "{D}/junk.map:1:1:", "type octile"},
      // check stc
      {"check stc --map {M} --path {D}/tour_text.csv", "{D}/tour_text.csv:1:1:", "expected x,y"},
      {"check stc --map {M} --path {D}/tour_row.csv", "{D}/tour_row.csv:3:3:", "expected y"},
      {"check stc --map {M} --path {D}/tour_empty.csv", "{D}/tour_empty.csv:", "no tour"},
      {"check stc --map {M} --path {D}/absent.csv", "{D}/absent.csv:", "cannot open"},
      {"check stc --map {M} --path {D}/tour_syntax.json", "{D}/tour_syntax.json:2:6:", "JSON"},
      {"check stc --map {M} --path {D}/tour_shape.json", "{D}/tour_shape.json:", "path[1]"},
      {"check stc --map {M} --path {D}/tour_float.json", "{D}/tour_float.json:", "not whole"},
      {"check stc --map {M} --path {D}/tour_nopath.json", "{D}/tour_nopath.json:", "no \"path\""},
      {"check stc --map {M} --path {D}/tour_startoff.json", "{D}/tour_startoff.json:", "outside"},
      {"check stc --map {M} --path {D}/tour_junk.json", "{D}/tour_junk.json:1:", "JSON"},
      {"check stc --map {D}/junk.map --path {D}/tour_ok.csv", "{D}/junk.map:1:1:", ""},
      {"check stc --map {M} --path {D}/tour_ok.csv --start 9999,0", "--start:", "outside"},
      {"check stc --map {M} --path {D}/tour_ok.csv --start 1", "--start:", "X,Y"},
      {"check stc --map {M} --path {D}/tour_ok.csv --format xml", "--format:", "xml"},
      {"check stc --map {M}", "--path is required", ""},
      {"check stc --map {M} --path ''", "--path:", "empty value"},
      {"check", "A subcommand is required", ""},
      {"check explore --map {M} --cells {D}/cells_ragged.txt",
       "{D}/cells_ragged.txt:2:1:", "row 1"},
      {"check explore --map {M} --cells {D}/cells_char.txt", "{D}/cells_char.txt:2:2:", "'Q'"},
      {"check explore --map {M} --cells {D}/cells_small.txt", "{D}/cells_small.txt:", "2x2"},
      {"check explore --map {M} --cells {D}/cells_nocells.json",
       "{D}/cells_nocells.json:", "no \"cells\""},
      {"check explore --map {M} --cells {D}/absent.txt", "{D}/absent.txt:", "cannot open"},
      {"check explore --map {M} --cells {D}/cells_overflow.json",
       "{D}/cells_overflow.json:", "number overflow"},
      {"check explore --map {M}", "--cells is required", ""},
      {"check cover --map {M} --log {D}/trace_order.csv --sensor 2",
       "{D}/trace_order.csv:2:1:", "robot 1"},
      {"check cover --map {M} --log {D}/trace_bearing.csv",
       "{D}/trace_bearing.csv:2:9:", "outside [0, 7]"},
      {"check cover --map {M} --log {D}/trace_nosensor.csv", "{D}/trace_nosensor.csv:", "--sensor"},
      {"check cover --map {M} --log {D}/trace_short.csv", "{D}/trace_short.csv:", "1 of 2"},
      {"check cover --map {M} --log {D}/trace_nosensor.csv --sensor 256", "--sensor:", "255"},
      {"check cover --map {M} --log {D}/trace_nosensor.csv --sensor x",
       "Could not convert: --sensor", ""},
      {"cover --map {M} --algo rw --trace {D}/nodir/trace.csv", "{D}/nodir/trace.csv", ""},
      // campaign
      {"campaign rs --cases 10 --out {D}/camp", "FAMILY:", "'rs'"},
      {"campaign buffon --cases 10 --plant max-width=3 --out {D}/camp", "--plant:", "grid maps"},
      {"campaign stc --cases 0 --out {D}/camp", "--cases:", "at least one"},
      {"campaign stc --cases 10 --max-size 0x4 --out {D}/camp", "--max-size:", "1x1"},
      {"campaign stc --cases 10 --max-size 8 --out {D}/camp", "--max-size:", "WxH"},
      {"campaign los --cases 10 --variants frontier,zigzag --out {D}/camp",
       "--variants:", "'zigzag'"},
      {"campaign uniform --cases 10 --threads 0 --out {D}/camp", "--threads:", "1 to 256"},
      {"campaign uniform --cases 10 --time -1 --out {D}/camp", "--time:", "0 or more"},
      {"campaign stc --cases 10", "--out is required", ""},
      {"campaign los --cases 10 --plant width=3 --out {D}/camp", "--plant:", "max-width=N"},
      {"campaign los --cases 10 --plant max-width=x --out {D}/camp", "--plant:", "'x'"},
      {"campaign los --cases 10 --plant max-width=2000 --out {D}/camp", "--plant:", "[0, 1024]"},
      // stc and stc-noise
      {"stc --map {D}/junk.map --variant ant --svg {D}/out.svg", "{D}/junk.map:1:1:", ""},
      {"stc --map {D}/blocked.map --variant ant --svg {D}/out.svg", "{D}/blocked.map:", "no free"},
      {"stc --map {M} --variant zigzag --svg {D}/out.svg", "--variant:", "'zigzag'"},
      {"stc --map {M} --variant ant --start 1 --svg {D}/out.svg", "--start:", "X,Y"},
      {"stc --map {M} --variant ant --start 1, --svg {D}/out.svg", "--start:", "X,Y"},
      {"stc --map {M} --variant ant --start 99999999999,0", "--start:", "out of range"},
      {"stc --map {M} --variant ant --start 40,40 --svg {D}/out.svg", "--start:", "outside"},
      {"stc --map {M} --variant ant --start '" + bin + "'", "--start:", "X,Y"},
      {"stc --map {M} --variant ant --noise 1.5 --svg {D}/out.svg", "--noise:", "probability"},
      {"stc --map {M} --variant ant --noise 0.1234567", "--noise:", "six decimals"},
      {"stc --map {M} --variant ant --noise -0.1", "--noise:", "probability"},
      {"stc --map {M} --variant ant --noise ''", "--noise:", "empty value"},
      {"stc --map {M} --variant online --noise 0.1 --svg {D}/out.svg", "--noise:", "online"},
      {"stc --map {M} --variant ant --format xml", "--format:", "xml"},
      {"stc-noise --map {M} --levels 0,abc", "--levels:", "'abc'"},
      {"stc-noise --map {M} --trials 0", "--trials:", "outside"},
      {"stc-noise --map {M} --variant online", "--variant:", "ant and ant-edge"},
      // dev stc-mcu-input (scripts/run-on-mcu.sh): antkit stc's refusals, and the chip's limits
      {"dev stc-mcu-input --map {M} --variant offline --out {D}/in.bin", "--variant:", "host only"},
      {"dev stc-mcu-input --map {M} --variant ant --start 99,0 --out {D}/in.bin",
       "--start:", "outside"},
      {"dev stc-mcu-input --map {M} --variant ant --noise 2 --out {D}/in.bin", "--noise:", ""},
      {"dev stc-mcu-input --map {D}/junk.map --variant ant --out {D}/in.bin",
       "{D}/junk.map:1:1:", ""},
      {"dev stc-mcu-input --map {B} --variant ant-edge --out {D}/in.bin",
       "{B}:", "which has 114688"},
      // cover and cover-experiment
      {"cover --algo rw --size 0x5 --density 0.1 --svg {D}/out.svg", "--size:", "'0x5'"},
      {"cover --algo rw --size 5 --density 0.1", "--size:", "'5'"},
      {"cover --algo rw --size 99999x99999 --density 0.1", "--size:", "99999x99999"},
      {"cover --algo rw --size 10x10 --density 1.5 --svg {D}/out.svg", "--density:", "'1.5'"},
      {"cover --algo rw --size 10x10 --density 20.5.5%", "--density:", "20.5.5"},
      {"cover --algo rw --size 10x10 --density '" + bin + "'", "--density:", "fraction"},
      {"cover --algo rw --size 10x10 --density 0.1 --robots 0", "--robots:", "1 to 1024"},
      {"cover --algo rw --size 10x10 --density 0.1 --robots 1000", "--robots:", "free region"},
      {"cover --algo rw --size 10x10 --density 0.1 --sensor -1", "--sensor:", "[0, 255]"},
      {"cover --algo rw --size 10x10 --density 0.1 --sensor 9999", "--sensor:", "[0, 255]"},
      {"cover --algo rw --size 10x10 --density 0 --sensor 99999999999999999999",
       "--sensor:", "[0, 255]"},
      {"cover --algo frontier --size 10x10 --density 0 --sensor 0", "--sensor:", "at least 1"},
      {"cover --algo rw --size 10x10 --density 0.1 --limit -5", "--limit:", ">= 0"},
      {"cover --algo zz --size 10x10 --density 0.1", "--algo:", "'zz'"},
      {"cover --algo rw --map {D}/junk.map --svg {D}/out.svg", "{D}/junk.map:1:1:", ""},
      {"cover --algo rw --map {M} --size 4x4", "give either --map FILE or --size", ""},
      {"cover-experiment --runs 0 --out {D}/outdir", "--runs:", "1 to 1000"},
      {"cover-experiment --size 2x --out {D}/outdir", "--size:", "'2x'"},
      // explore and explore-tables
      {"explore --algo frontier --size 10x10 --start 20,20 --svg {D}/out.svg",
       "--start:", "outside"},
      {"explore --algo frontier --size 10x10 --start a,b", "--start:", "X,Y"},
      {"explore --algo frontier --size 10xx10 --svg {D}/out.svg", "--size:", "WxH"},
      {"explore --algo frontier --size 1x1", "--size:", "[2, 2048]"},
      {"explore --algo frontier --map {D}/junk.map --svg {D}/out.svg", "{D}/junk.map:1:1:", ""},
      {"explore --algo frontier --size 10x10 --obstacles 1000", "--obstacles:", "more obstacles"},
      {"explore --algo spiral --size 10x10", "--algo:", "spiral"},
      {"explore --algo frontier --size 10x10 --start ''", "--start:", "empty value"},
      {"explore-tables --seed abc --out {D}/outdir", "Could not convert: --seed = abc", ""},
      // buffon, buffon-experiment, arena
      {"buffon --arena hexagon --svg {D}/out.svg", "--arena:1:1:", "unknown arena family"},
      {"buffon --arena circle:d=10 --trials 0", "--trials:", "[1, 100000]"},
      {"buffon --arena circle:d=10 --steps -1 --svg {D}/out.svg", "--steps:", "[1, 10000000]"},
      {"buffon --arena circle:d=10 --steps 99999999999999999999999", "--steps:", "[1, 10000000]"},
      {"buffon --arena circle:d=10 --width 0", "--width:", "[0.01, 10]"},
      {"buffon --arena circle:d=10 --noise 2", "--noise:", "[0, 1]"},
      {"buffon --arena circle:d=10 --precision 1.5", "--precision:", "'1.5'"},
      {"buffon --arena circle:d=10 --precision '" + bin + "'", "--precision:", "precision"},
      {"buffon --arena circle:d=10 --threads 0", "--threads:", "[1, 256]"},
      {"buffon --arena circle:d=10 --rule markers --svg {D}/out.svg",
       "--rule:", "needs --precision"},
      {"buffon --arena circle:d=10 --precision 0.1 --rule best", "--rule:", "'best'"},
      {"buffon --arena circle:d=10 --max-steps 1000", "--max-steps:", "needs --precision"},
      {"buffon --arena circle:d=10 --precision 0.1 --rule fixed --max-steps 1000",
       "--max-steps:", "--rule online or markers"},
      {"buffon --arena circle:d=10 --precision 0.1 --max-steps2 1000",
       "--max-steps2:", "--rule fixed"},
      {"buffon --arena circle:d=10 --precision 0.1 --rule online --max-steps 1",
       "--max-steps:", "[2, 100000000]"},
      {"buffon --arena circle:d=10 --precision 0.1 --max-steps 150000000",
       "--max-steps:", "[2, 100000000]"},
      {"buffon-cost --out {D}/cost --trials -1", "--trials:", "[1, 100000]"},
      {"buffon-cost --out {D}/cost --trials 0", "--trials:", "[1, 100000]"},
      {"buffon-cost --out {D}/cost --max-steps 1", "--max-steps:", "[2, 100000000]"},
      {"buffon-cost --out {D}/cost --threads 0", "--threads:", "[1, 256]"},
      {"buffon-cost --out /proc/antkit-cost", "--out:", "cannot create"},
      {"buffon --arena {D}/junk.wkt --svg {D}/out.svg", "{D}/junk.wkt:1:1:", "POLYGON"},
      {"buffon --arena {D}/empty.wkt", "{D}/empty.wkt:1:1:", "POLYGON"},
      {"buffon --arena {D}/open.wkt", "{D}/open.wkt:1:10:", "not closed"},
      {"buffon --arena {D}/bowtie.wkt", "{D}/bowtie.wkt:1:9:", "not simple"},
      {"buffon --arena circle:d=10 --format xml", "--format:", "xml"},
      {"buffon --arena circle:d=10 --bogus", "The following argument was not expected: --bogus",
       ""},
      {"buffon-experiment --figure 4 --out {D}/outdir", "--figure:", "5, 6, 7, 8, 9 or 14"},
      // reproduce (the runs themselves are tested in tests/experiments)
      {"reproduce --only los,sheng --out {D}/outdir", "--only:", "'sheng'"},
      {"reproduce --quick --full --out {D}/outdir", "--full:", "not both"},
      {"reproduce --threads 0 --out {D}/outdir", "--threads:", "1 to 256"},
      {"reproduce --only los --out /proc/antkit-reproduce", "--out:", "cannot create"},
      {"reproduce --only los", "--out is required", ""},
      {"reproduce --budget 800 --only los --out {D}/outdir", "--budget:", "for --decide"},
      {"reproduce --decide --budget 50 --only los --out {D}/outdir", "--budget:", "100 to 100000"},
      {"reproduce --decide --budget 10x --only los --out {D}/outdir", "--budget:", "s, m or h"},
      {"reproduce --decide --budget soon --only los --out {D}/outdir", "--budget:", "a duration"},
      {"reproduce --decide --unit-budget los --only los --out {D}/outdir",
       "--unit-budget:", "UNIT=TRIALS"},
      {"reproduce --decide --unit-budget los=5 --only los --out {D}/outdir",
       "--unit-budget:", "to 100000 trials per arena for 'los'"},
      {"reproduce --decide --unit-budget buffon/figure14=200 --only los --out {D}/outdir",
       "--unit-budget:", "not a unit of the papers run (los)"},
      {"reproduce --unit-budget los=200 --only los --out {D}/outdir",
       "--unit-budget:", "for --decide"},
      {"cover-experiment --sensor-model sonar --runs 1", "--sensor-model:", "'sonar'"},
      {"arena circle:d=1e400 --raster 1 --out {D}/out.map", "SPEC:1:10:", "bad number"},
      {"arena circle:d= --raster 1 --out {D}/out.map", "SPEC:1:10:", "bad number"},
      {"arena standard --raster abc --out {D}/out.map", "--raster:", "'abc'"},
      // hardware logs: replay, buffon-from-logs, rs-from-log
      {"replay {D}/junk.jsonl", "{D}/junk.jsonl:1:1:", "'{'"},
      {"replay {D}/empty.jsonl", "{D}/empty.jsonl:1:1:", "empty log"},
      {"replay {D}/header.jsonl", "{D}/header.jsonl:1:", "antkit_log"},
      {"replay {D}/nested.jsonl", "{D}/nested.jsonl:1:1:", "expected '{'"},
      {"replay {D}/missing.jsonl", "{D}/missing.jsonl:", "cannot read"},
      {"replay {D}/untimed.jsonl", "{D}/untimed.jsonl:2:1:", "an exchange without its time"},
      {"replay {D}/junk.jsonl --until abc", "Could not convert: --until = abc", ""},
      // hardware logs to MCAP: export mcap, replay --mcap (no MCAP file either)
      {"export mcap {D}/junk.jsonl --out {D}/x.mcap", "{D}/junk.jsonl:1:1:", "'{'"},
      {"export mcap {D}/empty.jsonl --out {D}/x.mcap", "{D}/empty.jsonl:1:1:", "empty log"},
      {"export mcap {D}/header.jsonl --out {D}/x.mcap", "{D}/header.jsonl:1:", "antkit_log"},
      {"export mcap {D}/missing.jsonl --out {D}/x.mcap", "{D}/missing.jsonl:", "cannot read"},
      {"export mcap {D}/junk.jsonl", "--out is required", ""},
      {"export mcap {D}/junk.jsonl --out {D}/x.mcap --threads 257", "--threads:", "[0, 256]"},
      {"replay {D}/junk.jsonl --mcap {D}/x.mcap", "{D}/junk.jsonl:1:1:", "'{'"},
      {"replay {D}/untimed.jsonl --mcap {D}/x.mcap",
       "{D}/untimed.jsonl:2:1:", "an exchange without its time"},
      {"buffon-from-logs {D}/junk.jsonl {D}/junk.jsonl", "{D}/junk.jsonl:1:1:", ""},
      {"buffon-from-logs {D}/header.jsonl", "visit2 is required", ""},
      {"rs-from-log {D}/empty.jsonl", "{D}/empty.jsonl:1:1:", ""},
      // ROS 2 bags
      {"bag info {D}/junk.mcap", "{D}/junk.mcap:", "not a bag"},
      {"bag info {D}/cut.mcap", "{D}/cut.mcap: byte ", "truncated MCAP file"},
      {"bag info {D}/other.db3", "{D}/other.db3:", "expected a rosbag2 .db3"},
      {"bag info {D}/nometa", "{D}/nometa:", "without metadata.yaml"},
      {"bag info {D}/leveldb", "{D}/leveldb/metadata.yaml:3:23:", "storage_identifier 'leveldb'"},
      {"bag info {D}/missing.mcap", "{D}/missing.mcap:", "cannot open"},
      {"buffon-from-logs --topic /odom {D}/cut.mcap {D}/junk.mcap", "{D}/cut.mcap: byte ",
       "truncated"},
      {"buffon-from-logs --topic /odom --stamp now {D}/cut.mcap {D}/junk.mcap",
       "--stamp:", "expected bag or header"},
      // record and emulate (their options; the link itself is tested over ptys elsewhere)
      {"record --device roomba --port /dev/null --controller buffon --out {D}/log.jsonl",
       "--device:", "roomba"},
      {"record --device khepera --port {D}/absent --controller buffon --out {D}/log.jsonl",
       "--port:", "cannot open"},
      {"record --device khepera --port /dev/null --controller buffon --out {D}/log.jsonl",
       "--port:", "not a serial port"},
      {"record --device khepera --port /dev/null --controller zz --out {D}/log.jsonl",
       "--controller:", "'zz'"},
      {"record --device khepera --port /dev/null --controller buffon --arena nonsense --out "
       "{D}/log.jsonl",
       "--arena:", "nonsense"},
      {"record --device khepera --port /dev/null --controller buffon --stop-within 0 --out "
       "{D}/log.jsonl",
       "--stop-within:", "milliseconds"},
      {"record --device khepera --port /dev/null --controller buffon --force --out /dev/null",
       "/dev/null:", "is the robot's port"},
      {"emulate khepera --fault silent=x", "--fault:", "silent=x"},
      {"record --device khepera --port /dev/null --controller buffon --visit 3 --out {D}/log.jsonl",
       "--controller:", "visit=3"},
      {"record --device khepera --port /dev/null --controller buffon --param visit --out "
       "{D}/log.jsonl",
       "--param:", "KEY=VALUE"},
      {"record --device khepera --port /dev/null --controller buffon --param visit=+2 --out "
       "{D}/log.jsonl",
       "--param:", "'+2'"},
      {"record --device khepera --port /dev/null --controller buffon --baud 12345 --out "
       "{D}/log.jsonl",
       "--baud:", "'12345'"},
      {"record --device khepera --port /dev/null --controller buffon --framing 9Z3 --out "
       "{D}/log.jsonl",
       "--framing:", "'9Z3'"},
      // the devices' own options: out of the declared range, not a number, another device's
      {"record --device khepera --port /dev/null --controller buffon --period 60001 --out "
       "{D}/log.jsonl",
       "--period:", "[0, 60000]"},
      {"record --device stc-floor --port /dev/null --controller ant --start 0,0 --led-ms -1 --out "
       "{D}/log.jsonl",
       "--led-ms:", "[0, 60000]"},
      {"record --device epuck2 --port /dev/null --controller buffon --map {M} --out {D}/log.jsonl",
       "--map:", "of the stc-floor robot"},
      {"emulate stc-floor --map {M} --noise 256", "--noise:", "[0, 255]"},
      {"emulate stc-floor --map {M} --fade 1.5", "--fade:", "'1.5' is not a whole number"},
      {"emulate stc-floor --map {M} --start 1", "--start:", "X,Y"},
      {"emulate stc-floor --map {M} --listen 127.0.0.1:0", "--listen:", "serves a pty"},
      {"emulate hemisson --heading 2", "--heading:", "of the stc-floor robot"},
      {"emulate roomba", "robot:", "roomba"},
      {"emulate khepera --fault delay=2:5", "--fault:", "probability"},
      {"emulate khepera --fault '" + bin + "'", "--fault:", "expected delay=P:MS"},
      {"emulate khepera --arena {D}/junk.wkt", "{D}/junk.wkt:1:1:", "POLYGON"},
      {"emulate", "robot is required", ""},
      {"nosuchcommand", "unknown subcommand 'nosuchcommand'", "arena, bag, buffon"},
  };
  const auto map = shared_map("movingai/empty-32-32.map");
  std::printf("bad-input table: %zu cases\n", cases.size());
  REQUIRE(cases.size() >= 60);
  for (const auto& c : cases) {
    const auto args = expand(c.args, dir.string(), map);
    INFO("antkit " << args);
    const auto r = run_antkit(args);
    INFO("stderr: " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    const std::string prefix = "antkit: error: " + expand(c.where, dir.string(), map);
    CHECK(r.err.rfind(prefix, 0) == 0);
    const auto first_line = r.err.substr(0, r.err.find('\n'));
    CHECK(first_line.size() > std::string("antkit: error: ").size());
    CHECK(first_line.find(c.says) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') <= 2);
    CHECK(listing(dir) == inputs);
  }
}
