#include "cosim_result.h"

namespace hwinterp::tb {

Json to_json(const Mismatch& m) {
  Json j = Json::object();
  j.set("cycle", m.cycle);
  j.set("signal", m.signal);
  j.set("hls", m.hls);
  j.set("rtl", m.rtl);
  return j;
}

Json CaseResult::to_json() const {
  Json j = Json::object();
  j.set("core", core);
  j.set("variant", variant);
  j.set("case", name);
  j.set("mode", mode);
  j.set("seed", seed);
  j.set("passed", passed());
  j.set("cycles", cycles);
  j.set("commands", commands);
  j.set("first_step_cycle", first_step_cycle);
  j.set("steps", Json::array_of(steps));
  j.set("start_position", Json::array_of(start));
  j.set("end_position", Json::array_of(end_position));
  j.set("expected_end_position", Json::array_of(expected_end_position));
  j.set("max_path_error_steps", max_path_error_steps);
  Json bound = Json::object();
  bound.set("value", error_bound);
  bound.set("strict", error_bound_strict);
  j.set("path_error_bound", std::move(bound));
  j.set("mismatches", mismatches);
  j.set("first_mismatch", first_mismatch ? tb::to_json(*first_mismatch) : Json());
  j.set("timing_violations", timing_violation_count);
  Json tv = Json::array();
  for (const auto& v : timing_violations) {
    Json o = Json::object();
    o.set("cycle", v.cycle);
    o.set("axis", v.axis);
    o.set("rule", v.rule);
    o.set("measured", v.measured);
    o.set("required", v.required);
    tv.push(std::move(o));
  }
  j.set("timing_violation_list", std::move(tv));
  j.set("scoreboard_errors", scoreboard_error_count);
  j.set("scoreboard_error_list", Json::array_of(scoreboard_errors));
  j.set("timed_out", timed_out);
  j.set("completed", completed);
  j.set("seconds", seconds);
  return j;
}

}  // namespace hwinterp::tb
