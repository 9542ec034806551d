// Paper 002's claims (Srour, Abboud: ant-like STC): the task and the box rule, invariants checked
// on every tour (exact: one failing tour refutes them; the note gives the Clopper-Pearson bound on
// the failure rate the tours allow); and two on its robot's hardware, read from the rendered
// robot on its floor (experiments/stc_floor.hpp): the rotation calibration and the fading limit.
// One ClaimSpec per claim (claims.hpp).
#include <antkit/experiments/claims.hpp>
#include <cstdio>

namespace antkit::experiments {

namespace {

std::vector<Part> failing_tours(const ClaimInputs& in,
                                std::initializer_list<const char*> variants) {
  std::vector<Part> parts;
  for (const char* v : variants) {
    std::size_t failed = 0;
    for (const auto& r : in.get<StcTours>()->tours) failed += r.variant == v && !r.audit_ok;
    parts.push_back(exact_part(std::string(v) + ": tours failing the audit",
                               static_cast<double>(failed), {Side::Below, 0.5}, Unit::Number, 0));
  }
  return parts;
}

std::string tours_note(const ClaimInputs& in, std::initializer_list<const char*> variants) {
  std::size_t all = 0, failed = 0;
  for (const auto& r : in.get<StcTours>()->tours)
    for (const char* v : variants)
      if (r.variant == v) ++all, failed += !r.audit_ok;
  if (all == 0) return "no tours";
  const auto ci = clopper_pearson(failed, all, 0.95);
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "%zu of %zu tours on %zu maps fail; failure rate at most %.1f %% (95 %%, "
                "Clopper-Pearson)",
                failed, all, in.get<StcTours>()->maps.size(), 100 * ci.hi);
  return buf;
}

std::string failures(const ClaimInputs& in) {
  std::string out;
  for (const auto& r : in.get<StcTours>()->tours)
    if (!r.audit_ok && out.size() < 300)
      out += (out.empty() ? "" : "; ") + r.map + " " + r.variant + ": " + r.audit;
  return out;
}

const std::vector<ClaimSpec> kPaper002Claims = {
    {"002-1", "stc", "Task description, the ant-like STC algorithm",
     "Ant-like STC passes exactly once over every sub-cell and returns to the cell where it "
     "started.",
     "The Robot's task is to cover the floor, passing exactly once over each sub-cell and to "
     "return to the same cell where it started.",
     "no tour of ant and ant-edge (nor of offline and online STC) fails antkit check stc: each "
     "reachable sub-cell entered exactly once, 4-adjacent free moves, back to the start cell",
     "stc/tours.csv",
     [](const ClaimInputs& in) {
       return failing_tours(in, {"ant", "ant-edge", "offline", "online"});
     },
     [](const ClaimInputs& in, const std::vector<Part>&) {
       return tours_note(in, {"ant", "ant-edge", "offline", "online"});
     },
     [](const ClaimInputs& in, const std::vector<Part>&) { return failures(in); }},
    {"002-box", "stc", "The ant-like STC algorithm, boxes",
     "A cell's sub-cells are visited exactly when the paper's five boxes say so (\"1 iff box 1 or "
     "5; 2 iff box 2 or 3; 3 iff box 4\"), so the robot needs no sub-cell marks.",
     "sub-cell 1 is visited iff one of the boxes 1 and 5 is lit. sub-cell 2 is visited iff one "
     "of the boxes 2 and 3 is lit. sub-cell 3 is visited iff box 4 is lit.",
     "ant-edge (which reads only the boxes) takes on every map the same tour as ant (which "
     "marks every sub-cell): no map where their tours' lengths, coverage or repeats differ, and "
     "no ant-edge tour fails the audit",
     "stc/tours.csv",
     [](const ClaimInputs& in) {
       std::size_t differ = 0;
       for (const auto& a : in.get<StcTours>()->tours)
         if (a.variant == "ant")
           for (const auto& e : in.get<StcTours>()->tours)
             if (e.variant == "ant-edge" && e.map == a.map)
               differ +=
                   e.positions != a.positions || e.covered != a.covered || e.repeats != a.repeats;
       auto parts = failing_tours(in, {"ant-edge"});
       parts.push_back(exact_part("maps where ant-edge's tour differs from ant's",
                                  static_cast<double>(differ), {Side::Below, 0.5}, Unit::Number,
                                  0));
       return parts;
     },
     [](const ClaimInputs& in, const std::vector<Part>&) { return tours_note(in, {"ant-edge"}); },
     [](const ClaimInputs& in, const std::vector<Part>&) { return failures(in); }},
    {"002-rotation", "stc", "Rotation and Calibration",
     "The rotation calibration (T <- 90/d T after every turn) keeps a weakening battery's turns "
     "right: the robot covers more of its board with it than without.",
     "Because of the battery decay, and the fact that the robot is built from Lego, a 90 degree "
     "turn, wasn't actually 90 degree, so we needed an algorithm to detect the current angle, and "
     "to fix the rotation in case it was not truly 90 degree rotation.",
     "on the same keyed boards at a turn drift of 2 000 ppm a minute, the mean coverage (the "
     "reachable sub-cells the body entered) with the calibration minus without it, paired by "
     "board: above 0 (coverage rather than exact tours: a tour that closes is a coarse 0 or 1, "
     "and 20 of them rarely decide)",
     "stc/floor_curves.csv",
     [](const ClaimInputs& in) {
       const FloorPoint *with = nullptr, *without = nullptr;
       for (const auto& p : in.get<FloorCurves>()->points)
         (p.factor == "drift" ? with : without) = &p;
       return std::vector<Part>{bootstrap_part(
           "coverage, calibrated - uncalibrated", {with->coverage_runs, without->coverage_runs}, 0,
           [](const Samples& s) { return mean(s[0]) - mean(s[1]); }, {Side::Above, 0},
           Unit::Percent, 1)};
     },
     [](const ClaimInputs& in, const std::vector<Part>&) {
       std::string out;
       for (const auto& p : in.get<FloorCurves>()->points) {
         char buf[160];
         std::snprintf(buf, sizeof buf, "%s%s: %.0f %% of %zu tours exact, coverage %.1f %%",
                       out.empty() ? "" : "; ", p.factor == "drift" ? "calibrated" : "uncalibrated",
                       100 * p.exact, p.coverage_runs.size(), 100 * p.coverage);
         out += buf;
       }
       return out + ". The calibration corrects each turn against the frame before it, so the "
                    "errors left within its tolerance still add up (results/stc_floor)";
     }},
    {"002-fading", "stc", "Conclusions",
     "With marks that the camera loses after about a minute, the robot cannot cover a large "
     "board.",
     "the web camera we used could not identify the light traces after less than a minute. Thus, "
     "it was not possible to run the robot on a large board.",
     "marks of a 30 s half-life (lost at about 2.3 half-lives, some 70 s): the largest open "
     "board whose tour closes exactly is below 4 x 4 cells (the paper does not say what large "
     "is; ours: 4 x 4 cells, 64 sub-cells, and up)",
     "stc/floor_boards.csv",
     [](const ClaimInputs& in) {
       const auto& b = in.get<FloorCurves>()->boards.front();
       return std::vector<Part>{exact_part("largest exact board, cells a side",
                                           static_cast<double>(b.largest), {Side::Below, 4},
                                           Unit::Number, 0)};
     },
     [](const ClaimInputs& in, const std::vector<Part>&) {
       const auto& b = in.get<FloorCurves>()->boards.front();
       char buf[200];
       if (b.largest == 0) return std::string("not even a 2 x 2 board closes");
       std::snprintf(buf, sizeof buf,
                     "%d x %d cells close, in %.1f min; the next size does not: a mark is read "
                     "last when the tour comes back past it",
                     b.largest, b.largest, b.tour_minutes);
       return std::string(buf);
     }},
    {"002-full", "stc", "(Full-STC, beside the paper)",
     "Full-STC covers every reachable free sub-cell, repeats allowed.", "",
     "no Full-STC tour fails antkit check stc --coverage", "stc/tours.csv",
     [](const ClaimInputs& in) { return failing_tours(in, {"full"}); },
     [](const ClaimInputs& in, const std::vector<Part>&) { return tours_note(in, {"full"}); },
     [](const ClaimInputs& in, const std::vector<Part>&) { return failures(in); }},
};

} // namespace

const std::vector<ClaimSpec>& claims_002() {
  return kPaper002Claims;
}

} // namespace antkit::experiments
