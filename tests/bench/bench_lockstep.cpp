// Direct-mode lockstep speed of every core and variant (HLS tick() +
// verilator --cc, the scoreboard and the monitors): clocks per second on one
// seeded random stream each. The hot loop is templated over the core's
// adapter (no virtual call per pin per clock): compare variants and commits
// side by side in one run of this benchmark. No main():
// tests/bench_sc_main.cpp runs these.
#include <benchmark/benchmark.h>

#include "../tb/lockstep_support.h"

namespace hwinterp::tb::testing {
namespace {

template <class V>
void BM_Direct(benchmark::State& state) {
  using A = typename V::Adapter;
  const Case<A> c = random_case<A>(V::limits(), 200, 1);
  validate_case(c, V::limits());
  uint64_t cycles = 0;
  bool passed = true;
  for (auto _ : state) {
    BenchOptions o;
    o.mode = "direct";
    Bench<A> bench(V::limits(), {c}, o);
    tb::run_direct<A, typename V::Cfg>(bench);
    cycles += bench.cycles();
    passed = passed && bench.results().at(0).passed();
  }
  if (!passed) state.SkipWithError("the lockstep run failed");
  state.counters["clocks_per_s"] =
      benchmark::Counter(static_cast<double>(cycles), benchmark::Counter::kIsRate);
}

template <class... V>
struct Register;
template <class... V>
struct Register<::testing::Types<V...>> {
  Register() {
    (benchmark::RegisterBenchmark((std::string("BM_Direct/") + V::Cfg::kVariant).c_str(),
                                  BM_Direct<V>)
         ->Unit(benchmark::kMillisecond),
     ...);
  }
};
const Register<AllVariants> registered;

}  // namespace
}  // namespace hwinterp::tb::testing
