// Shared by the dda_line test suites (unit and long): run a bench in the
// direct mode, and the pass conditions every clean run must meet.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dda_line_cosim.h"

namespace hwinterp::tb {

inline std::vector<CaseResult> run_direct(const std::string& variant,
                                          std::vector<DdaLineCase> cases, BenchOptions o = {}) {
  o.mode = "direct";
  DdaLineBench bench(dda_line_limits(variant), std::move(cases), o);
  run_dda_line_direct(variant, bench);
  return bench.results();
}

inline void expect_all_pass(const std::vector<CaseResult>& results) {
  ASSERT_FALSE(results.empty());
  for (const auto& r : results) {
    EXPECT_TRUE(r.passed()) << r.variant << " " << r.mode << " " << r.name << ": "
                            << r.to_json().dump();
    EXPECT_EQ(r.commands, r.commands_offered) << r.name;
    EXPECT_EQ(r.end_position, r.expected_end_position) << r.name;
  }
}

}  // namespace hwinterp::tb
