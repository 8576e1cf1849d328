#include "tb/base/case_result.h"

namespace hwinterp::tb {

Json to_json(const Mismatch& m) {
  return {{"cycle", m.cycle},
          {"signal", m.signal},
          {"hls", m.hls},
          {"rtl", m.rtl},
          {"inputs", m.inputs}};
}

Json to_json(const AbortRecord& a) {
  return {{"cycle", a.cycle},
          {"position", a.position},
          {"idle_after_clocks", a.idle_after_clocks >= 0 ? Json(a.idle_after_clocks) : Json()},
          {"idle_bound_clocks", a.idle_bound},
          {"on_reference_path", a.on_reference_path}};
}

Json CoreCheck::to_json() const {
  return {{"name", name},
          {"count_name", count_name},
          {"count", count},
          {"max", max},
          {"limit", limit >= 0 ? Json(limit) : Json()}};
}

Json CaseResult::to_json() const {
  Json j;
  j["core"] = core;
  j["variant"] = variant;
  j["case"] = name;
  j["ordinal"] = ordinal;
  j["mode"] = mode;
  j["seed"] = seed;
  j["passed"] = passed();
  j["cycles"] = cycles;
  j["commands"] = commands;
  j["offer_wait_cycles"] = offer_wait_cycles;
  j["first_step_cycle"] = first_step_cycle;
  j["steps"] = steps;
  j["start_position"] = start;
  j["end_position"] = end_position;
  j["expected_end_position"] = expected_end_position;
  j["max_path_error_steps"] = max_path_error_steps;
  j["path_error_bound"] = {{"value", error_bound}, {"strict", error_bound_strict}};
  j["mismatches"] = mismatches;
  j["first_mismatch"] = first_mismatch ? tb::to_json(*first_mismatch) : Json();
  j["timing_violations"] = timing_violation_count;
  Json tv = Json::array();
  for (const auto& v : timing_violations)
    tv.push_back({{"cycle", v.cycle},
                  {"axis", v.axis},
                  {"rule", v.rule},
                  {"measured", v.measured},
                  {"required", v.required}});
  j["timing_violation_list"] = std::move(tv);
  j["scoreboard_errors"] = scoreboard_error_count;
  j["scoreboard_error_list"] = scoreboard_errors;
  Json ab = Json::array();
  for (const auto& a : aborts) ab.push_back(tb::to_json(a));
  j["aborts"] = std::move(ab);
  Json checks = Json::array();
  for (const auto& c : core_checks) {
    j[c.count_name] = c.count;
    j["max_" + c.name] = c.max;
    checks.push_back(c.to_json());
  }
  j["core_checks"] = std::move(checks);
  j["timed_out"] = timed_out;
  j["completed"] = completed;
  j["seconds"] = seconds;
  return j;
}

}  // namespace hwinterp::tb
