// Long regressions of every core and variant (ctest label `long`, skipped by
// CI; run with `ctest --test-dir build -L long`). The conformance checks on
// longer streams and more seeds, with aborts and feed holds, in both modes.
#include <gtest/gtest.h>

#include "../tb/lockstep_support.h"

namespace hwinterp::tb::testing {
namespace {

template <class V>
class Soak : public ::testing::Test {};
TYPED_TEST_SUITE(Soak, AllVariants, VariantName);

// Ten seeds x 2500 commands, plain and with aborts and holds: about 10^7
// clocks per variant in the direct mode.
TYPED_TEST(Soak, DirectManySeeds) {
  using A = typename TypeParam::Adapter;
  uint64_t cycles = 0;
  for (uint64_t seed = 100; seed < 110; ++seed) {
    const auto r = run_direct<TypeParam>(
        {random_case<A>(TypeParam::spec(), 2500, seed),
         random_case<A>(TypeParam::spec(), 2500, seed, {seed % 2 == 0, seed % 2 == 1})});
    expect_all_pass(r);
    cycles += total_cycles(r);
  }
  this->RecordProperty("cycles", std::to_string(cycles));
}

// One long stream in the SystemC mode.
TYPED_TEST(Soak, SystemcLongStream) {
  using A = typename TypeParam::Adapter;
  expect_all_pass(run_systemc<TypeParam>({random_case<A>(TypeParam::spec(), 3000, 77, {true, true})}));
}

}  // namespace
}  // namespace hwinterp::tb::testing
