// Paper 002's claims (Srour, Abboud: ant-like STC): the task, and the box rule. Invariants checked
// on every tour (exact: one failing tour refutes them); the note gives the Clopper-Pearson bound
// on the failure rate the tours allow. One ClaimSpec per claim (claims.hpp).
#include <antkit/experiments/claims.hpp>
#include <cstdio>

namespace antkit::experiments {

namespace {

std::vector<Part> failing_tours(const ClaimInputs& in,
                                std::initializer_list<const char*> variants) {
  std::vector<Part> parts;
  for (const char* v : variants) {
    std::size_t failed = 0;
    for (const auto& r : in.stc->tours) failed += r.variant == v && !r.audit_ok;
    parts.push_back(exact_part(std::string(v) + ": tours failing the audit",
                               static_cast<double>(failed), {Side::Below, 0.5}, Unit::Number, 0));
  }
  return parts;
}

std::string tours_note(const ClaimInputs& in, std::initializer_list<const char*> variants) {
  std::size_t all = 0, failed = 0;
  for (const auto& r : in.stc->tours)
    for (const char* v : variants)
      if (r.variant == v) ++all, failed += !r.audit_ok;
  if (all == 0) return "no tours";
  const auto ci = clopper_pearson(failed, all, 0.95);
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "%zu of %zu tours on %zu maps fail; failure rate at most %.1f %% (95 %%, "
                "Clopper-Pearson)",
                failed, all, in.stc->maps.size(), 100 * ci.hi);
  return buf;
}

std::string failures(const ClaimInputs& in) {
  std::string out;
  for (const auto& r : in.stc->tours)
    if (!r.audit_ok && out.size() < 300)
      out += (out.empty() ? "" : "; ") + r.map + " " + r.variant + ": " + r.audit;
  return out;
}

const std::vector<ClaimSpec> kClaims = {
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
       for (const auto& a : in.stc->tours)
         if (a.variant == "ant")
           for (const auto& e : in.stc->tours)
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
    {"002-full", "stc", "(Full-STC, beside the paper)",
     "Full-STC covers every reachable free sub-cell, repeats allowed.", "",
     "no Full-STC tour fails antkit check stc --coverage", "stc/tours.csv",
     [](const ClaimInputs& in) { return failing_tours(in, {"full"}); },
     [](const ClaimInputs& in, const std::vector<Part>&) { return tours_note(in, {"full"}); },
     [](const ClaimInputs& in, const std::vector<Part>&) { return failures(in); }},
};

} // namespace

const std::vector<ClaimSpec>& claims_002() {
  return kClaims;
}

} // namespace antkit::experiments
