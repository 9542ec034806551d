#include <algorithm>
#include <antkit/buffon/measurement.hpp>
#include <antkit/experiments/buffon_figures.hpp>
#include <antkit/experiments/drawing.hpp>
#include <antkit/experiments/explore_tables.hpp>
#include <antkit/experiments/format.hpp>
#include <antkit/experiments/paper_tables.hpp>
#include <antkit/experiments/reproduce.hpp>
#include <antkit/experiments/stc_tours.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/atomic_file.hpp>
#include <antkit/geometry/fixed_convert.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/world.hpp>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

namespace antkit::experiments {

namespace ut = antkit::uniform::experiments;
using kernel::InputError;

namespace {

const std::vector<std::string> kFamilies = {"buffon", "los", "stc", "uniform"};

std::string pct(double v, int decimals = 1) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f %%", decimals, 100 * v);
  return buf;
}

// Holds when `good` of `all` pass, partly when at least `partly_from` of them do.
Verdict count_verdict(std::size_t good, std::size_t all, double partly_fraction = 0.5) {
  if (all > 0 && good == all) return Verdict::Holds;
  if (all > 0 && static_cast<double>(good) >= partly_fraction * static_cast<double>(all) &&
      good > 0)
    return Verdict::Partly;
  return Verdict::DoesNotHold;
}

double rel(double a, double b) {
  return b != 0 ? std::abs(a - b) / std::abs(b) : 0.0;
}

// The output directory, its subdirectories, and the files written (relative paths).
class Writer {
public:
  explicit Writer(std::filesystem::path out) : out_(std::move(out)) {}
  void dir(const std::string& sub) {
    std::error_code ec;
    std::filesystem::create_directories(out_ / sub, ec);
    if (!std::filesystem::is_directory(out_ / sub))
      throw InputError("--out", "cannot make the directory '" + (out_ / sub).string() + "'");
  }
  void text(const std::string& rel_path, const std::string& content) {
    geometry::write_file_atomic(out_ / rel_path, content);
    files_.emplace_back(rel_path);
  }
  void figure(const std::string& stem, const Figure& f) {
    save_figure(f, out_ / (stem + ".svg"), out_ / (stem + ".png"));
    files_.emplace_back(stem + ".svg");
    files_.emplace_back(stem + ".png");
  }
  [[nodiscard]] const std::filesystem::path& out() const { return out_; }
  void added(const std::string& rel_path) { files_.emplace_back(rel_path); }
  [[nodiscard]] const std::vector<std::filesystem::path>& files() const { return files_; }

private:
  std::filesystem::path out_;
  std::vector<std::filesystem::path> files_;
};

// A Markdown file's body under the report's own heading level: its first "# " title dropped and
// every other heading two levels deeper.
std::string embed(const std::string& md) {
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

std::string image(const std::string& stem, const std::string& alt) {
  return "![" + alt + "](" + stem + ".png)\n\n(" + stem + ".svg, " + stem + ".png)\n\n";
}

// ---------------------------------------------------------------------------------------------
// Paper 000.

struct BuffonResults {
  std::map<int, BuffonFigure> figures;
  Figure14 fig14;
};

const BuffonFigureRow* find_row(const BuffonFigure& f, const std::string& series, double x) {
  for (const auto& r : f.rows)
    if (r.arena.series == series && r.arena.x == x) return &r;
  return nullptr;
}

void buffon_claims(const BuffonResults& b, std::vector<Claim>& claims) {
  const auto& f5 = b.figures.at(5);
  {
    Claim c{"000-1",
            "000",
            "Figure 5, section 6.1",
            "nBC of square and circular arenas of equal area agree for all but the two smallest "
            "sizes.",
            "agree: medians differ by at most 5 %; holds when every size from d = 30 agrees",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0, all = 0;
    double worst = 0, worst_d = 0;
    for (double d = 30; d <= 100; d += 10) {
      const auto *ci = find_row(f5, "circle", d), *sq = find_row(f5, "square", d);
      if (!ci || !sq) continue;
      const double r = rel(sq->nbc_median, ci->nbc_median);
      ++all;
      good += r <= 0.05;
      if (r > worst) worst = r, worst_d = d;
    }
    const auto small = [&](double d) {
      const auto *ci = find_row(f5, "circle", d), *sq = find_row(f5, "square", d);
      return ci && sq ? pct(rel(sq->nbc_median, ci->nbc_median)) : std::string("-");
    };
    c.verdict = count_verdict(good, all, 0.75);
    c.measured = std::to_string(good) + " of " + std::to_string(all) +
                 " sizes agree; largest difference from d = 30: " + pct(worst) +
                 " (d = " + fixed(worst_d, 0) + "); d = 10: " + small(10) +
                 ", d = 20: " + small(20);
    if (c.verdict != Verdict::Holds)
      c.why = "the square's median departs from the circle's by more than 5 % at d = " +
              fixed(worst_d, 0) + ".";
    claims.push_back(c);
  }
  {
    Claim c{"000-3",
            "000",
            "Figure 5, section 6.1",
            "nBC is robust: half of the measurements lie in a narrow band around the median over "
            "a wide range of sizes.",
            "narrow: interquartile range at most 25 % of the median, every circle and square from "
            "d = 30",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0, all = 0;
    double widest = 0;
    for (const auto& r : f5.rows) {
      if (r.arena.x < 30 || r.nbc_median <= 0) continue;
      const double w = (r.nbc_q3 - r.nbc_q1) / r.nbc_median;
      ++all;
      good += w <= 0.25;
      widest = std::max(widest, w);
    }
    c.verdict = count_verdict(good, all, 0.75);
    c.measured = std::to_string(good) + " of " + std::to_string(all) +
                 " arenas; widest IQR / median: " + pct(widest);
    if (c.verdict != Verdict::Holds)
      c.why = "some arenas' interquartile range exceeds a quarter of their median at this trial "
              "count.";
    claims.push_back(c);
  }
  {
    Claim c{"000-4",
            "000",
            "Figure 5, section 6.1",
            "In the two smallest arenas nBC is lower than expected, because the trails blend.",
            "Buffon efficiency nBC pi A / (2 L1) (1 for an ideal needle count) below 0.9 at d = 10 "
            "and 20 and below every larger circle's",
            Verdict::DoesNotHold,
            "",
            ""};
    double larger_min = 1e300;
    std::string per_size;
    for (const auto& r : f5.rows)
      if (r.arena.series == "circle") {
        if (r.arena.x >= 30) larger_min = std::min(larger_min, r.efficiency);
        if (r.arena.x <= 30 || r.arena.x == 100)
          per_size += (per_size.empty() ? "" : ", ") +
                      ("d = " + fixed(r.arena.x, 0) + ": " + fixed(r.efficiency, 2));
      }
    std::size_t good = 0;
    for (double d : {10.0, 20.0})
      if (const auto* r = find_row(f5, "circle", d))
        good += r->efficiency < 0.9 && r->efficiency < larger_min;
    c.verdict = count_verdict(good, 2);
    c.measured = "efficiency " + per_size;
    if (c.verdict != Verdict::Holds)
      c.why = "only " + std::to_string(good) +
              " of the two smallest circles has an efficiency below 0.9 and below the larger "
              "circles'.";
    claims.push_back(c);
  }
  const auto& f6 = b.figures.at(6);
  {
    Claim c{"000-5",
            "000",
            "Figure 6, section 6.2.1",
            "The median nBC of ellipses of the standard area stays about the circle's as "
            "compactness changes.",
            "about: within 10 % of the circle's median, all three ellipses",
            Verdict::DoesNotHold,
            "",
            ""};
    const double circle = f6.rows.at(0).nbc_median;
    std::size_t good = 0;
    std::string list;
    for (std::size_t i = 1; i < f6.rows.size(); ++i) {
      const double r = rel(f6.rows[i].nbc_median, circle);
      good += r <= 0.10;
      list += (list.empty() ? "" : ", ") + pct(r);
    }
    c.verdict = count_verdict(good, f6.rows.size() - 1);
    c.measured = "differences from the circle (e = 0.968, 0.994, 0.998): " + list;
    if (c.verdict != Verdict::Holds)
      c.why = "the least compact ellipses' medians move by more than 10 %.";
    claims.push_back(c);
  }
  {
    Claim c{"000-6",
            "000",
            "Figure 6, section 6.2.1",
            "As the arena becomes less compact the spread of nBC grows and the median rises.",
            "both: the IQR grows with compactness at every step, and the most eccentric ellipse's "
            "median is above the circle's",
            Verdict::DoesNotHold,
            "",
            ""};
    bool growing = true;
    std::string iqrs;
    for (std::size_t i = 0; i < f6.rows.size(); ++i) {
      const double w = f6.rows[i].nbc_q3 - f6.rows[i].nbc_q1;
      if (i > 0) growing = growing && w >= f6.rows[i - 1].nbc_q3 - f6.rows[i - 1].nbc_q1;
      iqrs += (iqrs.empty() ? "" : ", ") + fixed(w, 3);
    }
    const bool rises = f6.rows.back().nbc_median > f6.rows.front().nbc_median;
    c.verdict = growing && rises   ? Verdict::Holds
                : growing || rises ? Verdict::Partly
                                   : Verdict::DoesNotHold;
    c.measured = "IQR (circle to e = 0.998): " + iqrs + "; median " +
                 fixed(f6.rows.front().nbc_median, 4) + " to " +
                 fixed(f6.rows.back().nbc_median, 4);
    if (c.verdict != Verdict::Holds)
      c.why = std::string(growing ? "" : "the IQR does not grow at every step") +
              (growing || rises ? "" : "; ") + (rises ? "" : "the median does not rise") + ".";
    claims.push_back(c);
  }
  const auto& f7 = b.figures.at(7);
  {
    Claim c{
        "000-7",
        "000",
        "Figure 7, section 6.2.2",
        "A partial barrier (I-shaped or plus-shaped) has no significant effect on the measurement.",
        "no significant effect: every barrier of 10-70 % of the diameter within 10 % of the "
        "standard arena's median",
        Verdict::DoesNotHold,
        "",
        ""};
    const double standard = f7.rows.at(0).nbc_median;
    std::size_t good = 0, all = 0;
    double worst = 0;
    std::string worst_at;
    for (const auto& r : f7.rows) {
      if (r.arena.series == "none" || r.arena.x > 70) continue;
      const double d = rel(r.nbc_median, standard);
      ++all;
      good += d <= 0.10;
      if (d > worst) worst = d, worst_at = r.arena.series + " " + fixed(r.arena.x, 0) + " %";
    }
    c.verdict = count_verdict(good, all, 0.75);
    c.measured = std::to_string(good) + " of " + std::to_string(all) +
                 " barriers; largest change " + pct(worst) + " (" + worst_at + ")";
    if (c.verdict != Verdict::Holds) {
      std::string off;
      for (const auto& r : f7.rows)
        if (r.arena.series != "none" && r.arena.x <= 70 && rel(r.nbc_median, standard) > 0.10)
          off += (off.empty() ? "" : ", ") + r.arena.series + " " + fixed(r.arena.x, 0) + " %";
      c.why = "the median moves by more than 10 % with " + off + ".";
    }
    claims.push_back(c);
  }
  {
    Claim c{"000-8",
            "000",
            "Figure 7, section 6.2.2",
            "With the longest barrier the robot stays stuck in lobes and the variance grows.",
            "the IQR at 80 % is the largest of its barrier's series, for both barrier shapes",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0;
    std::string list;
    for (const char* series : {"barrier-i", "barrier-plus"}) {
      double longest = 0, others = 0;
      for (const auto& r : f7.rows) {
        if (r.arena.series != series) continue;
        const double w = r.nbc_q3 - r.nbc_q1;
        if (r.arena.x == 80)
          longest = w;
        else
          others = std::max(others, w);
      }
      good += longest > others;
      list += (list.empty() ? "" : "; ") + std::string(series) + ": IQR at 80 % " +
              fixed(longest, 3) + ", largest shorter " + fixed(others, 3);
    }
    c.verdict = count_verdict(good, 2);
    c.measured = list;
    if (c.verdict != Verdict::Holds)
      c.why = "a shorter barrier's spread is as large as the longest's.";
    claims.push_back(c);
  }
  const auto& f8 = b.figures.at(8);
  {
    Claim c{"000-9",
            "000",
            "Figure 8, section 6.2.2",
            "nBC is almost invariant to the arena's shape: standard, ring, plus-shaped hole and "
            "obstacles of the same area agree.",
            "almost invariant: every shape within 10 % of the standard arena's median",
            Verdict::DoesNotHold,
            "",
            ""};
    const double standard = f8.rows.at(0).nbc_median;
    std::size_t good = 0;
    std::string list;
    for (std::size_t i = 1; i < f8.rows.size(); ++i) {
      const double d = (f8.rows[i].nbc_median - standard) / standard;
      good += std::abs(d) <= 0.10;
      list +=
          (list.empty() ? "" : ", ") + f8.rows[i].arena.series + " " + (d >= 0 ? "+" : "") + pct(d);
    }
    c.verdict = count_verdict(good, f8.rows.size() - 1);
    c.measured = "against the standard arena: " + list;
    if (c.verdict != Verdict::Holds) {
      std::string off;
      for (std::size_t i = 1; i < f8.rows.size(); ++i)
        if (rel(f8.rows[i].nbc_median, standard) > 0.10)
          off += (off.empty() ? "" : ", ") + f8.rows[i].arena.series;
      c.why = "the median nBC of " + off +
              " differs from the standard arena's by more than 10 %: equal areas do not give "
              "equal nBC there (a candidate cause, not separated here: the hole or obstacles keep "
              "both walks in narrower corridors, where their trails meet more often).";
    }
    claims.push_back(c);
  }
  const auto& f9 = b.figures.at(9);
  {
    Claim c{
        "000-10",
        "000",
        "Figure 9, section 6.3",
        "A thicker trail extends blending (too low nBC) to larger arenas.",
        "blending size: the largest circle whose efficiency is below 0.9; it never shrinks as w "
        "grows and is larger at w = 0.4 than at w = 0.05",
        Verdict::DoesNotHold,
        "",
        ""};
    std::vector<std::pair<std::string, double>> sizes;
    for (const auto& r : f9.rows) {
      if (sizes.empty() || sizes.back().first != r.arena.series)
        sizes.emplace_back(r.arena.series, 0);
      if (r.efficiency < 0.9) sizes.back().second = std::max(sizes.back().second, r.arena.x);
    }
    bool growing = true;
    std::string list;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      if (i > 0) growing = growing && sizes[i].second >= sizes[i - 1].second;
      list += (list.empty() ? "" : ", ") + sizes[i].first + ": d <= " + fixed(sizes[i].second, 0);
    }
    const bool larger = !sizes.empty() && sizes.back().second > sizes.front().second;
    c.verdict = growing && larger ? Verdict::Holds
                : larger          ? Verdict::Partly
                                  : Verdict::DoesNotHold;
    c.measured = "blending sizes " + list;
    if (c.verdict != Verdict::Holds)
      c.why = "the blending size does not grow steadily with the trail width here.";
    claims.push_back(c);
  }
  const auto& f14 = b.fig14;
  if (!f14.rows.empty()) {
    const double last = f14.rows.back().total_length;
    {
      Claim c{"000-11",
              "000",
              "Figure 14, section 8.1",
              "Random Search needs a longer trail for a larger arena to give a reliable estimate.",
              "at the longest trail, RS estimate / area falls as the diameter grows",
              Verdict::DoesNotHold,
              "",
              ""};
      std::vector<std::pair<double, double>> at_last;
      for (const auto& r : f14.rows)
        if (r.total_length == last) at_last.emplace_back(r.diameter, r.rs_median / r.area);
      bool falling = true;
      std::string list;
      for (std::size_t i = 0; i < at_last.size(); ++i) {
        if (i > 0) falling = falling && at_last[i].second < at_last[i - 1].second;
        list += (list.empty() ? "" : ", ") +
                ("d = " + fixed(at_last[i].first, 0) + ": " + fixed(at_last[i].second, 2));
      }
      c.verdict = falling ? Verdict::Holds : Verdict::DoesNotHold;
      c.measured = "RS / area at total length " + fixed(last, 0) + ": " + list;
      if (!falling) c.why = "the RS estimate does not fall steadily with the diameter.";
      claims.push_back(c);
    }
    {
      Claim c{"000-12",
              "000",
              "Figure 14, section 8.1",
              "Calibrated Buffon estimates are reliable even for short trails and depend little "
              "on the arena's size.",
              "reliable: every test circle's median estimate within 15 % of its area from the "
              "third checkpoint (total length 1008) on",
              Verdict::DoesNotHold,
              "",
              ""};
      std::size_t good = 0, all = 0;
      double worst = 0;
      std::string worst_at;
      for (const auto& r : f14.rows) {
        if (r.total_length < 1000) continue;
        const double e = rel(r.buffon_median, r.area);
        ++all;
        good += e <= 0.15;
        if (e > worst)
          worst = e,
          worst_at = "d = " + fixed(r.diameter, 0) + ", length " + fixed(r.total_length, 0);
      }
      c.verdict = count_verdict(good, all, 0.75);
      c.measured = std::to_string(good) + " of " + std::to_string(all) +
                   " (circle, checkpoint) medians within 15 %; worst " + pct(worst) + " (" +
                   worst_at + ")";
      if (c.verdict != Verdict::Holds)
        c.why = "some medians are off by more than 15 % at " + worst_at +
                "; with few trials the calibration fit itself is noisy.";
      claims.push_back(c);
    }
  }
}

std::string buffon_rows_table(const BuffonFigure& f) {
  std::ostringstream s;
  s << "| series | x | arena | median nBC | IQR | efficiency |\n|---|---|---|---|---|---|\n";
  for (const auto& r : f.rows)
    s << "| " << r.arena.series << " | " << number(r.arena.x) << " | `" << r.arena.spec << "` | "
      << fixed(r.nbc_median, 4) << " | " << fixed(r.nbc_q1, 4) << " - " << fixed(r.nbc_q3, 4)
      << " | " << fixed(r.efficiency, 3) << " |\n";
  return s.str();
}

// Figure 4: the trails of trial 0 in three circles (experiment 4400 + k).
void buffon_figure4(Writer& w, std::uint64_t seed) {
  std::vector<TrailPanel> panels;
  const double diameters[] = {20, 50, 100};
  for (std::size_t k = 0; k < 3; ++k) {
    const auto arena =
        geometry::build_arena_spec("circle:d=" + number(diameters[k]), "figure").arena;
    buffon::TrialParams params;
    params.seed = seed;
    params.experiment = 4400 + k;
    params.keep_trails = true;
    const auto r = buffon::run_trial(buffon::World(arena.walls_fx()), params, 0);
    TrailPanel p;
    p.title = "circle, d = " + number(diameters[k]) + " (area " + fixed(arena.area(), 0) + ")";
    for (const auto& ring : arena.rings()) {
      std::vector<XY> pts;
      for (const auto& v : ring) pts.emplace_back(v[0], v[1]);
      p.rings.push_back(std::move(pts));
    }
    // Every 8th point (a step is 0.04 units), keeping the points around a jump.
    const auto thin = [](const std::vector<kernel::FxPoint>& pts) {
      std::vector<XY> out;
      for (std::size_t i = 0; i < pts.size(); ++i)
        if (i % 8 == 0 || i + 1 == pts.size())
          out.emplace_back(geometry::to_double(pts[i].x), geometry::to_double(pts[i].y));
      return out;
    };
    p.trail1 = thin(r.trail1);
    p.trail2 = thin(r.trail2);
    panels.push_back(std::move(p));
  }
  save_trails_figure("Paper 000, Figure 4: two visits' trails in three circles",
                     "Trial 0 of each circle, 50 000 steps per visit, trail width 0.1 (unit: the "
                     "robot's diameter).\nIn the smallest circle the trails cover the floor and "
                     "blend: crossings are undercounted there.",
                     panels, w.out() / "buffon/figure4.svg", w.out() / "buffon/figure4.png");
  w.added("buffon/figure4.svg");
  w.added("buffon/figure4.png");
}

// ---------------------------------------------------------------------------------------------
// Paper 001.

void los_claims(const ExploreTables& t, std::vector<Claim>& claims) {
  const auto& env = kExploreEnvironments;
  {
    Claim c{"001-1",
            "001",
            "Table 2, section III",
            "Moving the obstacles (same number) does not change the exploration time much.",
            "not much: sample deviation at most 20 % of the mean in every column (the paper's "
            "are 6-14 %)",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0;
    double worst = 0;
    for (std::size_t e = 1; e < env.size(); ++e) {
      const auto& v = t.runs[e][0].steps;
      const double cv = sample_deviation(v) / mean_of(v);
      good += cv <= 0.2;
      worst = std::max(worst, cv);
    }
    c.verdict = count_verdict(good, env.size() - 1, 0.6);
    c.measured = std::to_string(good) + " of " + std::to_string(env.size() - 1) +
                 " columns; largest deviation / mean " + pct(worst);
    if (c.verdict != Verdict::Holds)
      c.why = "in some columns the steps vary more with the layout than in the paper.";
    claims.push_back(c);
  }
  {
    Claim c{"001-2",
            "001",
            "Tables 2-3",
            "Fast wall-follow's steps grow with the number of scattered obstacles (0, 1, 2, 5, "
            "10).",
            "the mean steps rise at every step of 0, 1, 2, 5, 10 obstacles",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0;
    std::string list = fixed(mean_of(t.runs[0][0].steps), 1);
    for (std::size_t e = 1; e <= 4; ++e) {
      good += mean_of(t.runs[e][0].steps) > mean_of(t.runs[e - 1][0].steps);
      list += ", " + fixed(mean_of(t.runs[e][0].steps), 1);
    }
    c.verdict = count_verdict(good, 4, 0.75);
    c.measured = "mean steps " + list + " (paper: 47, 82.5, 98.1, 121.5, 146.1)";
    if (c.verdict != Verdict::Holds) c.why = "the mean does not rise at every step.";
    claims.push_back(c);
  }
  const auto eme_claim = [&](const char* id, std::size_t baseline, const std::string& against) {
    Claim c{id,
            "001",
            "Table 3, Figure 5",
            "Fast wall-follow uses less motor energy (E.M.E) than " + against +
                " in every environment.",
            "the mean E.M.E of fast wall-follow below the baseline's, all 7 environments",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0;
    std::string lost;
    for (std::size_t e = 0; e < env.size(); ++e) {
      const bool better = mean_of(t.runs[e][0].eme) < mean_of(t.runs[e][baseline].eme);
      good += better;
      if (!better)
        lost += (lost.empty() ? "" : "; ") + std::string(env[e].name) + " " +
                fixed(mean_of(t.runs[e][0].eme), 1) + " vs " +
                fixed(mean_of(t.runs[e][baseline].eme), 1);
    }
    c.verdict = count_verdict(good, env.size());
    c.measured =
        std::to_string(good) + " of 7 environments" + (lost.empty() ? "" : "; not in: " + lost);
    if (c.verdict != Verdict::Holds)
      c.why = "against " + against +
              ", fast wall-follow's E.M.E is higher where it is not better: tracing every wall "
              "costs steps that a frontier search with these settings does not spend.";
    claims.push_back(c);
  };
  eme_claim("001-3", 1,
            "Sheng et al. (our frontier baseline without sweeping, the original method)");
  eme_claim("001-3b", 2, "our frontier baseline with line-of-sight sweeping (the strong baseline)");
  {
    Claim c{"001-4",
            "001",
            "Table 3, Figure 6",
            "Fast wall-follow needs fewer steps than Sheng et al. with no or few (fewer than ten) "
            "obstacles.",
            "mean steps below the frontier baseline without sweeping, environments with 0, 1, 2 "
            "and 5 obstacles",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0;
    std::string list;
    for (std::size_t e = 0; e <= 3; ++e) {
      good += mean_of(t.runs[e][0].steps) < mean_of(t.runs[e][1].steps);
      list += (list.empty() ? "" : ", ") + fixed(mean_of(t.runs[e][0].steps), 1) + " vs " +
              fixed(mean_of(t.runs[e][1].steps), 1);
    }
    c.verdict = count_verdict(good, 4);
    c.measured = std::to_string(good) + " of 4 (" + list + ")";
    if (c.verdict != Verdict::Holds)
      c.why = "our frontier baseline, unlike the paper's Sheng et al. (about 155 steps whatever "
              "the obstacles), is faster than wall-following in some of these rooms.";
    claims.push_back(c);
  }
}

// ---------------------------------------------------------------------------------------------
// Paper 002.

void stc_claims(const StcTours& s, std::vector<Claim>& claims) {
  std::map<std::string, std::pair<std::size_t, std::size_t>> by_variant; // passed, all
  std::string failures;
  for (const auto& r : s.tours) {
    auto& [ok, all] = by_variant[r.variant];
    ++all;
    ok += r.audit_ok;
    if (!r.audit_ok && failures.size() < 300)
      failures += (failures.empty() ? "" : "; ") + r.map + " " + r.variant + ": " + r.audit;
  }
  const auto list = [&](std::initializer_list<const char*> names, std::size_t& good,
                        std::size_t& all) {
    std::string text;
    for (const char* n : names) {
      const auto& [ok, count] = by_variant[n];
      good += ok;
      all += count;
      text += (text.empty() ? "" : ", ") + std::string(n) + " " + std::to_string(ok) + "/" +
              std::to_string(count);
    }
    return text;
  };
  {
    Claim c{"002-1",
            "002",
            "Task description, the ant-like STC algorithm",
            "Ant-like STC passes exactly once over every sub-cell and returns to the cell where it "
            "started.",
            "every tour of ant and ant-edge (and of offline and online STC) passes antkit check "
            "stc: each reachable sub-cell entered exactly once, 4-adjacent free moves, back to "
            "the start cell",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0, all = 0;
    const std::string text = list({"ant", "ant-edge", "offline", "online"}, good, all);
    c.verdict = count_verdict(good, all, 1.0);
    c.measured = text + " tours pass on " + std::to_string(s.maps.size()) + " maps";
    if (c.verdict != Verdict::Holds) c.why = failures;
    claims.push_back(c);
  }
  {
    Claim c{"002-full",
            "002",
            "(Full-STC, beside the paper)",
            "Full-STC covers every reachable free sub-cell, repeats allowed.",
            "every Full-STC tour passes antkit check stc --coverage",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0, all = 0;
    const std::string text = list({"full"}, good, all);
    c.verdict = count_verdict(good, all, 1.0);
    c.measured = text + " tours pass";
    if (c.verdict != Verdict::Holds) c.why = failures;
    claims.push_back(c);
  }
}

// ---------------------------------------------------------------------------------------------
// Paper 004.

void uniform_claims(const std::vector<ut::TablesRow>& rows, const std::vector<ut::TablesRow>& disk,
                    std::uint32_t runs, std::vector<Claim>& claims) {
  {
    Claim c{"004-2",
            "004",
            "Tables 1-4, results",
            "A* reaches 100 % coverage in every row.",
            "every run of A* views every viewable free cell, all 16 rows",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0;
    for (const auto& r : rows) good += r.complete[2] == runs;
    c.verdict = count_verdict(good, rows.size(), 1.0);
    c.measured = std::to_string(good) + " of " + std::to_string(rows.size()) + " rows complete";
    if (c.verdict != Verdict::Holds) c.why = "some A* runs stopped short of full coverage.";
    claims.push_back(c);
  }
  const auto at = [&](const std::vector<ut::TablesRow>& rs, int density, int robots) {
    for (const auto& r : rs)
      if (r.paper->density_percent == density && r.paper->robots == robots) return &r;
    return static_cast<const ut::TablesRow*>(nullptr);
  };
  {
    Claim c{"004-3",
            "004",
            "Tables 1-4, results",
            "PM's coverage falls as the obstacle density rises.",
            "for each robot count, PM's mean coverage at 0 % >= 10 % >= 20 % >= 30 %",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0;
    std::string list;
    for (int robots = 1; robots <= 4; ++robots) {
      bool falling = true;
      for (const auto& [a, b] : {std::pair{0, 10}, std::pair{10, 20}, std::pair{20, 30}})
        falling = falling && at(rows, a, robots)->coverage[1] >= at(rows, b, robots)->coverage[1];
      good += falling;
      list += (list.empty() ? "" : "; ") + std::to_string(robots) +
              " robot(s): " + fixed(at(rows, 0, robots)->coverage[1], 1) + " to " +
              fixed(at(rows, 30, robots)->coverage[1], 1) + " %";
    }
    c.verdict = count_verdict(good, 4);
    c.measured = list;
    if (c.verdict != Verdict::Holds) c.why = "the fall is not monotone for every robot count.";
    claims.push_back(c);
  }
  {
    Claim c{"004-3b",
            "004",
            "Tables 1-4, results",
            "PM's movements stay small and steady (fewer than A*'s) with obstacles.",
            "PM's mean movements below A*'s in all 12 rows with obstacles",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0, all = 0;
    for (const auto& r : rows)
      if (r.paper->density_percent > 0) ++all, good += r.movements[1] < r.movements[2];
    c.verdict = count_verdict(good, all);
    c.measured = std::to_string(good) + " of " + std::to_string(all) + " rows";
    if (c.verdict != Verdict::Holds) c.why = "in some rows PM moves more than A*.";
    claims.push_back(c);
  }
  {
    Claim c{"004-4",
            "004",
            "Tables 1-3, results",
            "More robots raise PM's coverage, so PM should approach A* with enough robots.",
            "PM's mean coverage with 4 robots above 1 robot's, every density with obstacles",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0;
    std::string list;
    for (const int d : {10, 20, 30}) {
      good += at(rows, d, 4)->coverage[1] > at(rows, d, 1)->coverage[1];
      list += (list.empty() ? "" : "; ") + std::to_string(d) +
              " %: " + fixed(at(rows, d, 1)->coverage[1], 1) + " to " +
              fixed(at(rows, d, 4)->coverage[1], 1);
    }
    c.verdict = count_verdict(good, 3);
    c.measured = list + " % (1 to 4 robots)";
    if (c.verdict == Verdict::Holds && at(rows, 30, 4)->coverage[1] < 50)
      c.why = "it rises, but far from A*'s 100 %.";
    claims.push_back(c);
  }
  {
    Claim c{"004-5",
            "004",
            "Table 4",
            "Without obstacles PM reaches full coverage with fewer movements than A* (3 and 4 "
            "robots).",
            "0 % density, 3 and 4 robots: every PM run complete and PM's mean movements below "
            "A*'s",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0;
    std::string list;
    for (const int robots : {3, 4}) {
      const auto* r = at(rows, 0, robots);
      good += r->complete[1] == runs && r->movements[1] < r->movements[2];
      list += (list.empty() ? "" : "; ") + std::to_string(robots) + " robots: PM " +
              fixed(r->coverage[1], 1) + " % in " + fixed(r->movements[1], 1) + " vs A* " +
              fixed(r->movements[2], 1);
    }
    c.verdict = count_verdict(good, 2);
    c.measured = list;
    if (c.verdict != Verdict::Holds)
      c.why = "our PM does not complete every run of an empty room: it ceases when no unviewed "
              "cell is within its sensor range, and can leave far corners unviewed.";
    claims.push_back(c);
  }
  {
    Claim c{"004-6",
            "004",
            "Tables 1-4, results",
            "RW, the baseline, covers least.",
            "RW's mean coverage below PM's and A*'s, all 16 rows",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0;
    for (const auto& r : rows)
      good += r.coverage[0] < r.coverage[1] && r.coverage[0] < r.coverage[2];
    c.verdict = count_verdict(good, rows.size());
    c.measured = std::to_string(good) + " of " + std::to_string(rows.size()) + " rows";
    if (c.verdict != Verdict::Holds) {
      std::string off;
      for (const auto& r : rows)
        if (!(r.coverage[0] < r.coverage[1] && r.coverage[0] < r.coverage[2]))
          off += (off.empty() ? "" : ", ") + std::to_string(r.paper->density_percent) + " % / " +
                 std::to_string(r.paper->robots);
      c.why = "RW views at least as much as our PM in the rows (density / robots) " + off +
              ": our PM ceases early there, while RW runs as many ticks as A*.";
    }
    claims.push_back(c);
  }
  {
    Claim c{"004-pm",
            "004",
            "Tables 1-3",
            "PM covers 35-83 % of the free cells with obstacles (the paper's numbers).",
            "our PM's mean coverage within 10 points of the paper's in every row with obstacles",
            Verdict::DoesNotHold,
            "",
            ""};
    std::size_t good = 0, all = 0, disk_good = 0;
    double lo = 1e300, hi = 0, dlo = 1e300, dhi = 0;
    for (const auto& r : rows) {
      if (r.paper->density_percent == 0) continue;
      ++all;
      good += std::abs(r.coverage[1] - r.paper->coverage[1]) <= 10;
      lo = std::min(lo, r.coverage[1]), hi = std::max(hi, r.coverage[1]);
      if (const auto* d = at(disk, r.paper->density_percent, r.paper->robots)) {
        disk_good += std::abs(d->coverage[1] - r.paper->coverage[1]) <= 10;
        dlo = std::min(dlo, d->coverage[1]), dhi = std::max(dhi, d->coverage[1]);
      }
    }
    c.verdict = count_verdict(good, all);
    c.measured = "ours " + fixed(lo, 1) + "-" + fixed(hi, 1) + " % (" + std::to_string(good) +
                 " of " + std::to_string(all) + " rows within 10 points)";
    if (!disk.empty())
      c.measured += "; with a disk sensor that sees through walls " + fixed(dlo, 1) + "-" +
                    fixed(dhi, 1) + " % (" + std::to_string(disk_good) + " of " +
                    std::to_string(all) + ")";
    if (c.verdict != Verdict::Holds) {
      c.why = "our PM stops when no unviewed cell is in sensor range, early among obstacles.";
      if (!disk.empty())
        c.why += disk_good * 2 > all
                     ? " A sensor without line of sight closes most of the gap: the paper's "
                       "sensor probably sees through obstacles."
                     : " A sensor without line of sight (a disk) does not close the gap, so a "
                       "sensor that sees through obstacles does not explain the paper's numbers; "
                       "the paper's PM must keep going where ours ceases (its text does not say "
                       "how).";
    }
    claims.push_back(c);
  }
}

// The papers' own words for each claim (from the texts in ../shared/papers).
const std::map<std::string, std::string>& quotes() {
  static const std::map<std::string, std::string> q = {
      {"000-1", "nBC values for square and circular arenas are approximately the same for all "
                "sizes except the two smallest arenas."},
      {"000-3", "50% of the measurements lie within a narrow band of the median for a wide range "
                "of arena sizes. The plot clearly indicates that nBC provides a robust measure "
                "for area."},
      {"000-4", "nBC values of the two smallest arenas (with area 348 and 1392 unit^2) obtained "
                "are lower than expected. This is due to the blending of trails"},
      {"000-5", "nBC values remain approximately the same despite the change in the compactness "
                "of the arena."},
      {"000-6", "As the arena becomes less compact, the variance in the nBC values obtained using "
                "two-pass strategy increase (indicated by the growth in the error bars) also "
                "affecting the median value."},
      {"000-7", "the partial barrier inside an arena has no significant affect on its size "
                "measurement."},
      {"000-8", "causing the robot to remain stuck in some of the lobes. As a result of this, the "
                "variance [...] corresponding to the the largest barrier length is increased."},
      {"000-9", "The plots clearly show that nBC remains almost invariant with respect to arena "
                "shape."},
      {"000-10", "as the thickness of the pheromone increases, blending (which can be seen by "
                 "smaller-than-expected nBC values for small areas) affects larger areas."},
      {"000-11", "one needs to increase the trail length with the size of the area being measured "
                 "for a reliable estimate."},
      {"000-12", "Buffon's needle method provides reliable area estimates for even short trail "
                 "lengths, showing little dependency to the size of the arena."},
      {"001-1", "It is clear from Table 2 that changing the positions of the obstacles does not "
                "dramatically affect the exploration time."},
      {"001-2", "the exploration time varies not only with the number of obstacles but also with "
                "the distribution of the obstacles themselves. (Table 3: 47, 82.5, 98.1, 121.5, "
                "146.1 steps.)"},
      {"001-3", "Our proposed wall-follow algorithm is better than the exploration algorithm in "
                "[4] in terms of robot motor energy consumption (see Fig.5)."},
      {"001-3b", "Our proposed wall-follow algorithm is better than the exploration algorithm in "
                 "[4] in terms of robot motor energy consumption (see Fig.5)."},
      {"001-4", "The proposed exploration algorithm consumes less exploration time than in "
                "environments with no obstacles or with few obstacles (less than ten) as shown in "
                "Fig.6."},
      {"002-1", "The Robot's task is to cover the floor, passing exactly once over each sub-cell "
                "and to return to the same cell where it started."},
      {"004-2", "It is obvious that A* produces superior coverage in all four control studies. "
                "(Tables 1-4: 100.0 % in every row.)"},
      {"004-3", "The performance of the PM algorithm degrades with increasing obstacle density"},
      {"004-3b", "though the movements taken to achieve coverage remains relatively smaller and "
                 "consistent."},
      {"004-4", "It is evident that PM should be able to achieve similar coverage as A* if more "
                "robots are deployed in the environment."},
      {"004-5", "It is also possible for PM to achieve this uniform coverage with fewer movements "
                "than A*. (Table 4: 566.0 vs 749.0 with 3 robots, 421.0 vs 553.0 with 4.)"},
      {"004-6", "As expected, the worst performance is by RW, the baseline."},
      {"004-pm", "(Tables 1-3: PM covers 34.96 to 82.82 % with 10-30 % obstacles.)"},
  };
  return q;
}

} // namespace

Trials trials_of(Scale scale) {
  if (scale == Scale::Full) return {};
  return {20, 3, 6, 10};
}

const char* verdict_text(Verdict v) {
  switch (v) {
  case Verdict::Holds:
    return "holds";
  case Verdict::Partly:
    return "partly";
  case Verdict::DoesNotHold:
    return "does not hold";
  }
  return "?";
}

void validate(const ReproduceOptions& options) {
  for (const auto& name : options.only)
    if (std::find(kFamilies.begin(), kFamilies.end(), name) == kFamilies.end())
      throw InputError("--only", "'" + name + "' is not one of buffon, los, stc, uniform");
}

std::string reproduce_command(const ReproduceOptions& o, const std::vector<std::string>& only) {
  std::string s =
      std::string("antkit reproduce ") + (o.scale == Scale::Full ? "--full" : "--quick");
  if (!only.empty()) {
    s += " --only ";
    for (std::size_t i = 0; i < only.size(); ++i) s += (i ? "," : "") + only[i];
  }
  s += " --seed " + std::to_string(o.seed);
  if (only.empty() || std::find(only.begin(), only.end(), "stc") != only.end())
    s += " --maps " + (o.maps_dir.empty() ? std::string("''") : o.maps_dir.string());
  return s + " --out DIR";
}

std::string claims_markdown(const std::vector<Claim>& claims) {
  // A '|' inside a cell would end it.
  const auto cell = [](const std::string& text) {
    std::string out;
    for (const char ch : text) out += ch == '|' ? std::string("\\|") : std::string(1, ch);
    return out;
  };
  std::ostringstream s;
  s << "| claim | paper | where | the paper says | verdict | measured | why (where it does not "
       "hold) |\n|---|---|---|---|---|---|---|\n";
  for (const auto& c : claims)
    s << "| " << c.id << " | " << c.paper << " | " << cell(c.source) << " | " << cell(c.text)
      << " | **" << verdict_text(c.verdict) << "** | " << cell(c.measured) << " | " << cell(c.why)
      << " |\n";
  return s.str();
}

ReproduceReport reproduce(const ReproduceOptions& o, const Runner& runner) {
  validate(o);
  const auto wants = [&](const char* family) {
    return o.only.empty() || std::find(o.only.begin(), o.only.end(), family) != o.only.end();
  };
  const Trials trials = trials_of(o.scale);
  Writer w(o.out);
  if (runner.root())
    for (const char* family : {"buffon", "los", "stc", "uniform"})
      if (wants(family)) w.dir(family);
  if (runner.root() && wants("uniform")) w.dir("uniform/disk");
  ReproduceReport report;
  std::ostringstream md;
  const std::string scale = o.scale == Scale::Full ? "full" : "quick";

  // Paper 000.
  BuffonResults buffon;
  if (wants("buffon")) {
    for (const int figure : {5, 6, 7, 8, 9}) {
      BuffonFigureParams p;
      p.figure = figure;
      p.trials = trials.buffon;
      p.seed = o.seed;
      buffon.figures.emplace(figure, run_buffon_figure(p, runner));
    }
    BuffonFigureParams p14;
    p14.figure = 14;
    p14.trials = trials.buffon;
    p14.seed = o.seed;
    buffon.fig14 = run_figure14(p14, runner);
  }
  ExploreTables los;
  if (wants("los")) los = run_explore_tables(o.seed, runner);
  StcTours stc;
  StcToursParams stc_params;
  stc_params.maps_dir = o.maps_dir;
  stc_params.random_maps = trials.stc_random_maps;
  stc_params.noise_trials = trials.stc_noise_trials;
  stc_params.seed = o.seed;
  if (wants("stc")) stc = run_stc_tours(stc_params, runner);
  ut::TablesConfig uc;
  uc.runs = static_cast<std::uint32_t>(trials.uniform_runs);
  uc.seed = o.seed;
  ut::TablesConfig disk_config = uc;
  disk_config.sensor_model = uniform::SensorModel::Disk;
  std::vector<ut::TablesRow> uniform_rows, disk_rows;
  if (wants("uniform")) {
    uniform_rows = ut::run_tables(uc, runner);
    disk_rows = ut::run_tables(disk_config, runner);
  }
  if (!runner.root()) return report;

  // Decide and write (rank 0).
  std::ostringstream body;
  if (wants("buffon")) {
    buffon_claims(buffon, report.claims);
    buffon_figure4(w, o.seed);
    body << "## Paper 000: Buffon's-needle area measurement\n\n"
         << trials.buffon << " trials per arena (the paper: 100), 50 000 steps per visit, trail "
         << "width 0.1 unless the figure varies it. nBC is the Buffon count per unit length of "
            "visit 2; efficiency is nBC pi A / (2 L1), 1 for an ideal needle count. The paper "
            "gives no numbers for these figures, only statements (section 6), which the claims "
            "above test.\n\n"
         << "### Figure 4: trails\n\n"
         << image("buffon/figure4", "Figure 4: trails in three circles");
    const char* captions[] = {"",
                              "",
                              "",
                              "",
                              "",
                              "Figure 5: circles and squares",
                              "Figure 6: compactness",
                              "Figure 7: barriers",
                              "Figure 8: holes and obstacles",
                              "Figure 9: trail width"};
    for (auto& [figure, f] : buffon.figures) {
      const std::string stem = "buffon/figure" + std::to_string(figure);
      w.text(stem + ".csv", buffon_figure_csv(f));
      w.figure(stem, buffon_figure_plot(f));
      body << "### " << captions[figure] << "\n\n" << image(stem, captions[figure]);
      if (figure == 5) {
        w.figure("buffon/figure5b", buffon_figure5b_plot(f));
        body << image("buffon/figure5b", "Figure 5b: squares against circles");
      }
      body << buffon_rows_table(f) << '\n';
      report.experiments.push_back({"paper 000, figure " + std::to_string(figure), f.hash,
                                    "antkit buffon-experiment --figure " + std::to_string(figure) +
                                        " --trials " + std::to_string(trials.buffon) + " --seed " +
                                        std::to_string(o.seed) + " --out DIR (prints this hash)"});
    }
    w.text("buffon/figure14.csv", figure14_csv(buffon.fig14));
    w.figure("buffon/figure14", figure14_plot(buffon.fig14));
    body << "### Figure 14: calibrated Buffon against Random Search\n\n"
         << image("buffon/figure14", "Figure 14")
         << "Rows: buffon/figure14.csv (medians and interquartile ranges per circle and "
            "checkpoint, with the fit a + b nBC^c).\n\n";
    report.experiments.push_back({"paper 000, figure 14", buffon.fig14.hash,
                                  "antkit buffon-experiment --figure 14 --trials " +
                                      std::to_string(trials.buffon) + " --seed " +
                                      std::to_string(o.seed) + " --out DIR (prints this hash)"});
  }
  if (wants("los")) {
    los_claims(los, report.claims);
    w.text("los/table2.csv", table2_csv(los));
    w.text("los/table2.md", table2_markdown(los));
    w.text("los/table3.csv", table3_csv(los));
    w.text("los/table3.md", table3_markdown(los));
    w.figure("los/figures5-6", explore_plot(los));
    explore_stages_figure(o.seed, o.out / "los/figure4.svg", o.out / "los/figure4.png");
    w.added("los/figure4.svg");
    w.added("los/figure4.png");
    body << "## Paper 001: two-robot line-of-sight exploration\n\n"
         << "25 x 25 cells, the paper's 10 repetitions (5 for the blocks) per environment, seed "
         << o.seed
         << ". \"Sheng et al.\" (ours) is the frontier baseline as paper 001 describes it: "
            "g = w1 I - w2 D + w3 lambda with w1 = w2 = 1, w3 = 0, and the information gain I "
            "counting only the cells outside the other robot's sensor range and target, without "
            "line-of-sight sweeping; the strong baseline is the same with sweeping. Each cell: "
            "ours / the paper's.\n\n"
         << "### Figure 4: stages of one run\n\n"
         << image("los/figure4", "Figure 4: stages of one run") << "### Table 2\n\n"
         << embed(table2_markdown(los)) << "\n### Table 3\n\n"
         << embed(table3_markdown(los)) << "\n### Figures 5-6\n\n"
         << image("los/figures5-6", "Figures 5-6: steps and E.M.E");
    report.experiments.push_back({"paper 001, tables 2-3", los.hash,
                                  "antkit explore-tables --seed " + std::to_string(o.seed) +
                                      " --out DIR --format json (prints this hash)"});
  }
  if (wants("stc")) {
    stc_claims(stc, report.claims);
    w.text("stc/tours.csv", stc_tours_csv(stc));
    w.text("stc/noise.csv", stc_noise_csv(stc));
    if (!stc.noise.empty()) w.figure("stc/noise", stc_noise_plot(stc));
    body << "## Paper 002: ant-like Spanning Tree Coverage\n\n"
         << "Every variant on " << stc.maps.size() << " maps ("
         << (stc.maps.size() > static_cast<std::size_t>(trials.stc_random_maps)
                 ? "the shared MovingAI maps and "
                 : "no shared maps found; ")
         << trials.stc_random_maps
         << " keyed random maps of 64 x 64 sub-cells with 10 % blocked), from the start `antkit "
            "stc` takes, each tour audited by `antkit check stc` (antkit::testing). The paper "
            "reports no numbers: its claim is the task itself.\n\n"
         << "| variant | tours | pass | sub-cells covered (sum) | repeats (sum) |\n"
            "|---|---|---|---|---|\n";
    for (const auto v : stc::kVariants) {
      std::size_t count = 0, pass = 0;
      std::int64_t covered = 0, repeats = 0;
      for (const auto& r : stc.tours)
        if (r.variant == stc::variant_name(v))
          ++count, pass += r.audit_ok, covered += r.covered, repeats += r.repeats;
      body << "| " << stc::variant_name(v) << " | " << count << " | " << pass << " | " << covered
           << " | " << repeats << " |\n";
    }
    body << "\nEvery tour: stc/tours.csv.\n\n";
    // A tour on a real map (den312d when present, else the first map).
    std::string tour_map = stc.maps.empty() ? "" : stc.maps.front();
    for (const auto& m : stc.maps)
      if (m == "den312d.map") tour_map = m;
    if (!tour_map.empty()) {
      const auto grid = stc_experiment_map(stc_params, tour_map);
      if (const auto start = stc::default_start(grid, stc::Variant::AntEdge)) {
        const auto r = stc::run_stc(grid, *start, stc::Variant::AntEdge);
        save_tour_figure(
            grid, r.path, "Paper 002: ant-edge STC on " + tour_map,
            std::to_string(r.reachable_subcells) + " reachable sub-cells, " +
                std::to_string(r.covered) + " covered, " + std::to_string(r.repeats) +
                " repeats, back at the start cell: " + (r.returned_to_start ? "yes" : "no") + ".",
            o.out / "stc/tour.svg", o.out / "stc/tour.png");
        w.added("stc/tour.svg");
        w.added("stc/tour.png");
        body << "### A tour on a real map\n\n" << image("stc/tour", "ant-edge tour");
      }
    }
    if (!stc.noise.empty()) {
      body << "### Marker noise (ours; the paper gives no curve)\n\n"
           << image("stc/noise", "marker noise curve")
           << "| variant | misread probability | coverage | repeats per sub-cell | complete tours "
              "|\n|---|---|---|---|---|\n";
      for (const auto& p : stc.noise)
        body << "| " << p.variant << " | " << number(p.ppm / 1e6) << " | " << fixed(p.coverage, 4)
             << " | " << fixed(p.repeats_per_subcell, 4) << " | " << fixed(p.complete, 2) << " |\n";
      body << '\n';
    }
    report.experiments.push_back(
        {"paper 002, tours and marker noise", stc.hash, reproduce_command(o, {"stc"})});
  }
  if (wants("uniform")) {
    uniform_claims(uniform_rows, disk_rows, uc.runs, report.claims);
    w.text("uniform/uniform_tables.csv", ut::tables_csv(uniform_rows, uc));
    w.text("uniform/uniform_tables.md", ut::tables_markdown(uniform_rows, uc));
    w.text("uniform/disk/uniform_tables.csv", ut::tables_csv(disk_rows, disk_config));
    w.text("uniform/disk/uniform_tables.md", ut::tables_markdown(disk_rows, disk_config));
    w.figure("uniform/coverage", ut::tables_plot(uniform_rows, uc));
    body << "## Paper 004: uniform coverage (RW, PM, A*)\n\n"
         << embed(ut::tables_markdown(uniform_rows, uc)) << "\n### Coverage against movements\n\n"
         << image("uniform/coverage", "coverage against movements")
         << "### The disk-sensor test\n\nThe same runs with a sensor that views every cell within "
            "range, through walls (RW, PM and A* only): uniform/disk/uniform_tables.md. PM's "
            "coverage per row, line of sight / disk / the paper's:\n\n"
            "| density % | robots | PM, line of sight | PM, disk | PM, paper "
            "|\n|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < uniform_rows.size() && i < disk_rows.size(); ++i)
      body << "| " << uniform_rows[i].paper->density_percent << " | "
           << uniform_rows[i].paper->robots << " | " << fixed(uniform_rows[i].coverage[1], 2)
           << " | " << fixed(disk_rows[i].coverage[1], 2) << " | "
           << fixed(uniform_rows[i].paper->coverage[1], 2) << " |\n";
    body << '\n';
    kernel::TraceHash los_digest, disk_digest;
    for (const auto& r : uniform_rows) los_digest.add_u64(r.hash);
    for (const auto& r : disk_rows) disk_digest.add_u64(r.hash);
    report.experiments.push_back({"paper 004, tables 1-4", los_digest.finish(),
                                  "antkit cover-experiment --runs " + std::to_string(uc.runs) +
                                      " --seed " + std::to_string(o.seed) +
                                      " --out DIR (prints this hash)"});
    report.experiments.push_back({"paper 004, tables 1-4, disk sensor", disk_digest.finish(),
                                  "antkit cover-experiment --runs " + std::to_string(uc.runs) +
                                      " --seed " + std::to_string(o.seed) +
                                      " --sensor-model disk --out DIR (prints this hash)"});
  }

  for (auto& c : report.claims)
    if (const auto it = quotes().find(c.id); it != quotes().end()) c.quote = it->second;

  // The report.
  std::size_t holds = 0, partly = 0, not_held = 0;
  for (const auto& c : report.claims)
    (c.verdict == Verdict::Holds ? holds : c.verdict == Verdict::Partly ? partly : not_held)++;
  md << "# The papers, reproduced by antkit\n\n"
     << "`" << reproduce_command(o, o.only) << "` (" << scale << " scale";
  if (o.scale == Scale::Quick)
    md << ": " << trials.buffon << " trials per arena for paper 000 (the paper: 100), "
       << trials.uniform_runs << " runs per row for paper 004 (the paper: 10), "
       << trials.stc_random_maps << " random maps and " << trials.stc_noise_trials
       << " noisy trials per level for paper 002; paper 001 in full. `--full` runs the papers' "
          "counts";
  else
    md << ": the papers' trial counts";
  md << "). Every number below depends only on these options, not on the threads or the MPI "
        "ranks: the trials are the kernel's, bit-exact on every compiler and CPU that "
        "scripts/determinism.sh checks; the reductions (medians, means, Figure 14's fit) are "
        "floating point on the machine that writes the report.\n\n"
     << "## Claims\n\n"
     << holds << " hold, " << partly << " partly, " << not_held
     << " do not hold. Each claim's rule, the figure that decides it and, where it does not "
        "hold, what the runs show:\n\n"
     << claims_markdown(report.claims) << "\nRules, and the papers' own words:\n\n";
  for (const auto& c : report.claims)
    md << "- " << c.id << ": " << c.rule << "."
       << (c.quote.empty() ? std::string(" (A claim of ours beside the paper.)")
                           : " The paper: \"" + c.quote + "\"")
       << '\n';
  md << '\n'
     << body.str() << "## Trace hashes\n\n"
     << "Each experiment's trace hash (every trial's, in trial order) and a command that "
        "reproduces it. This whole report: `"
     << reproduce_command(o, o.only) << "`.\n\n| experiment | hash | command |\n|---|---|---|\n";
  for (const auto& e : report.experiments)
    md << "| " << e.name << " | `" << kernel::hash_hex(e.hash) << "` | `" << e.command << "` |\n";

  nlohmann::json j;
  j["command"] = reproduce_command(o, o.only);
  j["scale"] = scale;
  j["seed"] = o.seed;
  j["trials"] = {{"buffon_per_arena", trials.buffon},
                 {"uniform_runs_per_row", trials.uniform_runs},
                 {"stc_random_maps", trials.stc_random_maps},
                 {"stc_noise_trials", trials.stc_noise_trials}};
  nlohmann::json claims = nlohmann::json::array();
  for (const auto& c : report.claims)
    claims.push_back({{"id", c.id},
                      {"paper", c.paper},
                      {"source", c.source},
                      {"claim", c.text},
                      {"rule", c.rule},
                      {"verdict", verdict_text(c.verdict)},
                      {"measured", c.measured},
                      {"why", c.why},
                      {"quote", c.quote}});
  j["claims"] = std::move(claims);
  nlohmann::json hashes = nlohmann::json::array();
  for (const auto& e : report.experiments)
    hashes.push_back(
        {{"experiment", e.name}, {"hash", kernel::hash_hex(e.hash)}, {"command", e.command}});
  j["experiments"] = std::move(hashes);
  j["summary"] = {{"holds", holds}, {"partly", partly}, {"does_not_hold", not_held}};
  w.text("claims.json", j.dump(2) + "\n");
  w.text("README.md", md.str());
  report.files = w.files();
  return report;
}

} // namespace antkit::experiments
