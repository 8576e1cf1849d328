// dda_line's long lines (ctest label `long`): 2^20 + 1 steps on one axis
// (2^21 iterations, the wide end of the normaliser), odd ratios on the
// others, both preloads.
#include <gtest/gtest.h>

#include "../tb/lockstep_support.h"
#include "tb/stimulus/delta_commands.h"

namespace hwinterp::tb::testing {
namespace {

using A = cores::dda_line::Adapter;

template <class V>
void long_lines() {
  const VariantSpec l = V::spec();
  for (const bool half : {false, true}) {
    RunSettings<A> s = default_settings<A>(l);
    s.setup.half_preload = half;
    s.timing = {1, 1, 1, 1};
    std::vector<int64_t> end(static_cast<size_t>(l.axes), 0);
    end[0] = (int64_t{1} << 20) + 1;
    end[1] = -333333;
    if (l.axes > 2) end[2] = 7;
    expect_all_pass(run_direct<V>(
        {delta_line_case<A>(l, "long", std::vector<int64_t>(end.size(), 0), end, s)}));
  }
}

TEST(DdaLineSoak, DirectLongLines) {
  long_lines<Variant<A, dda_line_n2_cfg>>();
  long_lines<Variant<A, dda_line_n4_cfg>>();
}

}  // namespace
}  // namespace hwinterp::tb::testing
