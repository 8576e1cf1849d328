// Long dda_line regressions (ctest label `long`, skipped by CI; run with
// `ctest --test-dir build -L long`). Same checks as the unit suite, longer
// streams, more seeds, and lines long enough to reach the wide end of the
// normaliser (bit lengths up to 21).
#include <gtest/gtest.h>

#include <memory>

#include "../tb/dda_line_test_support.h"
#include "dda_line_cosim.h"

namespace hwinterp::tb {
namespace {

// About 3 * 10^7 cycles per variant in the direct mode.
TEST(DdaLineSoak, DirectManySeeds) {
  for (const std::string& v : dda_line_variants()) {
    for (uint64_t seed = 100; seed < 110; ++seed) {
      expect_all_pass(run_direct(v, {random_case(dda_line_limits(v), 2500, seed)}));
    }
  }
}

// Both variants side by side in one SystemC elaboration.
TEST(DdaLineSoak, SystemcLongStreams) {
  std::vector<std::unique_ptr<DdaLineBench>> benches;
  std::vector<std::pair<std::string, DdaLineBench*>> sc;
  for (const std::string& v : dda_line_variants()) {
    benches.push_back(std::make_unique<DdaLineBench>(
        dda_line_limits(v), std::vector<DdaLineCase>{random_case(dda_line_limits(v), 3000, 77)},
        BenchOptions{"systemc", 77}));
    sc.emplace_back(v, benches.back().get());
  }
  run_dda_line_systemc(sc);
  for (const auto& b : benches) expect_all_pass(b->results());
}

// Long lines: 2^20 + 1 steps on one axis (2^21 iterations), odd ratios on
// the others, both preloads.
TEST(DdaLineSoak, DirectLongLines) {
  for (const std::string& v : dda_line_variants()) {
    const DdaLineLimits l = dda_line_limits(v);
    for (const bool half : {false, true}) {
      DdaLineSettings s = default_settings(l);
      s.half_preload = half;
      s.timing = {1, 1, 1, 1};
      std::vector<int64_t> end(static_cast<size_t>(l.axes), 0);
      end[0] = (int64_t{1} << 20) + 1;
      end[1] = -333333;
      if (l.axes > 2) end[2] = 7;
      expect_all_pass(
          run_direct(v, {line_case(l, "long", std::vector<int64_t>(end.size(), 0), end, s)}));
    }
  }
}

}  // namespace
}  // namespace hwinterp::tb
