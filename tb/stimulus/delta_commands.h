// Stimulus shared by the cores whose command is one signed delta per axis
// (A::Command::delta: dda_line, ppc_line): the `line` and `move` job
// directives, a case for one line, and the eight test lines of
// 004_dc68f1177cad466f.txt.
#pragma once

#include <string>
#include <vector>

#include "models/paper_data_001_003_004.h"
#include "tb/stimulus/stimulus.h"

namespace hwinterp::tb {

// `line X Y ...` (to an absolute point) and `move DX DY ...` (by a delta);
// false for any other directive.
template <class A>
bool delta_job_directive(JobLine<A>& line) {
  const std::string& key = line.words[0];
  if (key != "line" && key != "move") return false;
  const models::LatticePoint v = line.point(1);
  typename A::Command c;
  for (size_t i = 0; i < v.size(); ++i) c.delta[i] = key == "line" ? v[i] - line.at()[i] : v[i];
  line.command(c);
  return true;
}

// Every delta fits an element of cmd_delta_i (its width and signedness from
// the core's payload field list); throws cli::UsageError naming `where`, the
// axis, the value and the limits.
template <class A>
void validate_deltas(const typename A::Command& c, const VariantSpec& l, const std::string& where) {
  for (int i = 0; i < l.axes; ++i)
    l.check_fits("cmd_delta_i", c.delta[static_cast<size_t>(i)], "delta", where,
                 " on axis " + std::to_string(i));
}

// One case: a line from `start` to `end` (given for some leading axes; the
// rest are 0).
template <class A>
Case<A> delta_line_case(const VariantSpec& l, const std::string& name,
                        const std::vector<int64_t>& start, const std::vector<int64_t>& end,
                        const RunSettings<A>& settings) {
  if (start.size() != end.size())
    throw cli::UsageError("line '" + name + "': start and end have different axis counts");
  Case<A> c;
  c.name = name;
  c.start = pad_point(l, start, "line '" + name + "'");
  const models::LatticePoint e = pad_point(l, end, "line '" + name + "'");
  typename A::Command cmd;
  for (size_t i = 0; i < e.size(); ++i) cmd.delta[i] = e[i] - c.start[i];
  c.settings = settings;
  c.items.push_back(command_item<A>(cmd));
  return c;
}

// The eight test lines of 004_dc68f1177cad466f.txt, one case each
// (004_line1 .. 004_line8; axes past the second stay at 0).
template <class A>
std::vector<Case<A>> paper_lines_004(const VariantSpec& l, const RunSettings<A>& settings) {
  std::vector<Case<A>> cases;
  int n = 0;
  for (const auto& p : models::paper::kRatioLines)
    cases.push_back(delta_line_case<A>(l, "004_line" + std::to_string(++n), {p[0], p[1]},
                                       {p[2], p[3]}, settings));
  return cases;
}

// --line X0,Y0,..,X1,Y1,..: start then end coordinates (2k numbers).
template <class A>
Case<A> delta_line_from_option(const cli::Args& args, const VariantSpec& l,
                               const RunSettings<A>& settings) {
  const std::vector<int64_t> v = args.integer_list("line");
  for (const int64_t x : v) check_coordinate(x, "--line");
  if (v.size() < 2 || v.size() % 2)
    throw cli::UsageError("--line: '" + args.str("line") +
                          "' needs start and end coordinates (2k numbers)");
  const auto k = static_cast<std::ptrdiff_t>(v.size() / 2);
  return delta_line_case<A>(l, "line", {v.begin(), v.begin() + k}, {v.begin() + k, v.end()},
                            settings);
}

}  // namespace hwinterp::tb
