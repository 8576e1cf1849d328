#include "tb/report/cosim_report.h"

#include <algorithm>
#include <sstream>

#include "tb/base/text_table.h"

namespace hwinterp::tb {

namespace {
std::string point(const models::LatticePoint& p) {
  std::string s;
  for (size_t i = 0; i < p.size(); ++i) s += (i ? "," : "") + std::to_string(p[i]);
  return s;
}
std::string steps(const std::vector<uint64_t>& v) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + std::to_string(v[i]);
  return s;
}
}  // namespace

bool all_passed(const std::vector<CaseResult>& results) {
  return !results.empty() &&
         std::all_of(results.begin(), results.end(), [](const auto& r) { return r.passed(); });
}

std::string case_table(const std::vector<CaseResult>& results) {
  TextTable t({"variant", "mode", "case", "cycles", "cmds", "steps", "end", "path err", "bound",
               "mism", "viol", "sb", "result"});
  for (const auto& r : results) {
    const bool end_ok = r.end_position == r.expected_end_position && !r.end_position.empty();
    t.add_row({r.variant, r.mode, r.name, std::to_string(r.cycles), std::to_string(r.commands),
               steps(r.steps),
               end_ok ? point(r.end_position) + " ok" : point(r.end_position) + " BAD",
               fmt("%.4f", r.max_path_error_steps),
               (r.error_bound_strict ? "<" : "<=") + fmt("%.4f", r.error_bound),
               std::to_string(r.mismatches), std::to_string(r.timing_violation_count),
               std::to_string(r.scoreboard_error_count),
               r.passed() ? "pass" : (r.timed_out ? "FAIL (timeout)" : "FAIL")});
  }
  return t.render();
}

std::string failure_details(const std::vector<CaseResult>& results) {
  std::ostringstream os;
  for (const auto& r : results) {
    if (r.passed()) continue;
    os << r.variant << " " << r.mode << " " << r.name << ":\n";
    if (r.first_mismatch)
      os << "  first mismatch at cycle " << r.first_mismatch->cycle << ": "
         << r.first_mismatch->signal << " hls=" << r.first_mismatch->hls
         << " rtl=" << r.first_mismatch->rtl << "\n";
    for (const auto& v : r.timing_violations)
      os << "  timing: cycle " << v.cycle << " axis " << v.axis << " " << v.rule << " "
         << v.measured << " < " << v.required << " cycles\n";
    if (r.timing_violation_count > r.timing_violations.size())
      os << "  ... " << r.timing_violation_count - r.timing_violations.size()
         << " more timing violations\n";
    for (const auto& e : r.scoreboard_errors) os << "  scoreboard: " << e << "\n";
    if (r.scoreboard_error_count > r.scoreboard_errors.size())
      os << "  ... " << r.scoreboard_error_count - r.scoreboard_errors.size()
         << " more scoreboard errors\n";
    if (r.timed_out) os << "  timed out after " << r.cycles << " cycles (core hung?)\n";
    if (!r.completed && !r.first_mismatch) os << "  did not complete\n";
  }
  return os.str();
}

Json aggregate_json(const std::vector<CaseResult>& results) {
  std::vector<Json> cases;
  for (const auto& r : results) cases.push_back(r.to_json());
  return aggregate_json(cases);
}

Json aggregate_json(const std::vector<Json>& cases) {
  uint64_t cycles = 0, commands = 0, mismatches = 0, violations = 0, sb = 0;
  std::vector<uint64_t> step_sum;
  double worst = 0;
  bool passed = !cases.empty();
  Json first_mismatch, first_abort;
  for (const auto& c : cases) {
    cycles += c["cycles"].get<uint64_t>();
    commands += c["commands"].get<uint64_t>();
    mismatches += c["mismatches"].get<uint64_t>();
    violations += c["timing_violations"].get<uint64_t>();
    sb += c["scoreboard_errors"].get<uint64_t>();
    worst = std::max(worst, c["max_path_error_steps"].get<double>());
    const auto steps = c["steps"].get<std::vector<uint64_t>>();
    step_sum.resize(std::max(step_sum.size(), steps.size()), 0);
    for (size_t i = 0; i < steps.size(); ++i) step_sum[i] += steps[i];
    passed = passed && c["passed"].get<bool>();
    if (first_mismatch.is_null()) first_mismatch = c["first_mismatch"];
    if (first_abort.is_null() && !c["aborts"].empty()) first_abort = c["aborts"][0];
  }
  const Json* last = cases.empty() ? nullptr : &cases.back();
  Json j;
  j["core"] = last ? (*last)["core"] : Json("");
  j["variant"] = last ? (*last)["variant"] : Json("");
  j["mode"] = last ? (*last)["mode"] : Json("");
  j["seed"] = last ? (*last)["seed"] : Json(0);
  j["passed"] = passed;
  j["cycles"] = cycles;
  j["commands"] = commands;
  j["steps"] = step_sum;
  j["end_position"] = last ? (*last)["end_position"] : Json::array();
  j["expected_end_position"] = last ? (*last)["expected_end_position"] : Json::array();
  j["max_path_error_steps"] = worst;
  j["mismatches"] = mismatches;
  j["timing_violations"] = violations;
  j["scoreboard_errors"] = sb;
  j["first_mismatch"] = first_mismatch;
  j["abort"] = first_abort;
  // The cores' own checks: counts add up, maxima over the cases.
  for (const auto& c : cases) {
    if (!c.contains("core_checks")) continue;
    for (const auto& k : c["core_checks"]) {
      const std::string count = k["count_name"].get<std::string>();
      const std::string max = "max_" + k["name"].get<std::string>();
      j[count] = (j.contains(count) ? j[count].get<uint64_t>() : 0) + k["count"].get<uint64_t>();
      j[max] = std::max(j.contains(max) ? j[max].get<double>() : 0.0, k["max"].get<double>());
    }
  }
  j["cases"] = cases;
  return j;
}

}  // namespace hwinterp::tb
