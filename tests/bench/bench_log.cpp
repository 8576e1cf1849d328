// Reference-model speed: the odd-even log interpolation (paper case at
// dl = 0.2 and 0.5, and with exact even steps), the inscribed chord and the
// fine line/arc sequences. No main(): tests/bench_sc_main.cpp runs these.
#include <benchmark/benchmark.h>

#include <cmath>

#include "models/fixed_ratio.h"
#include "models/inscribed_chord.h"
#include "models/log_curve.h"
#include "models/ppc.h"

namespace hwinterp::models {
namespace {

void BM_LogPaper(benchmark::State& state) {
  LogCurveParams p;
  p.dl_mm = static_cast<double>(state.range(0)) / 10;
  size_t points = 0;
  for (auto _ : state) {
    const LogRun run = run_log_interpolation(p);
    points = run.count();
    benchmark::DoNotOptimize(run.max_all.abs);
  }
  state.counters["points"] = static_cast<double>(points);
  state.counters["points_per_s"] = benchmark::Counter(
      static_cast<double>(points * state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_LogPaper)->Arg(2)->Arg(5)->ArgName("dl_x10")->Unit(benchmark::kMicrosecond);

void BM_LogExactEven(benchmark::State& state) {
  const LogCurveParams p;
  for (auto _ : state) {
    const LogRun run = run_log_interpolation(p, EvenStep::kExact);
    benchmark::DoNotOptimize(run.max_even.abs);
  }
}
BENCHMARK(BM_LogExactEven)->Unit(benchmark::kMicrosecond);

void BM_ChordArcTable2(benchmark::State& state) {
  for (auto _ : state) {
    const ChordResult r = inscribed_chord_arc({0, 0}, {4, 0}, {0, 4}, true, 0.9);
    benchmark::DoNotOptimize(r.overshoot);
  }
}
BENCHMARK(BM_ChordArcTable2);

// The general root finder on the same arc given as a PlanarCurve.
void BM_ChordArcGeneral(benchmark::State& state) {
  const ArcCurve arc({0, 0}, 4, 0, M_PI / 2);
  for (auto _ : state) {
    const ChordResult r = inscribed_chord(arc, 0.9);
    benchmark::DoNotOptimize(r.overshoot);
  }
}
BENCHMARK(BM_ChordArcGeneral)->Unit(benchmark::kMicrosecond);

void BM_PpcLine1(benchmark::State& state) {
  for (auto _ : state) {
    const StepPath p = ppc_line({0, 0}, {20, 40});
    benchmark::DoNotOptimize(p.moves.data());
  }
}
BENCHMARK(BM_PpcLine1);

void BM_PpcFullCircleR1000(benchmark::State& state) {
  for (auto _ : state) {
    const StepPath p = ppc_arc({0, 0}, {1000, 0}, {1000, 0}, true);
    benchmark::DoNotOptimize(p.moves.data());
  }
  state.counters["steps"] = 8000;
}
BENCHMARK(BM_PpcFullCircleR1000)->Unit(benchmark::kMicrosecond);

void BM_FixedRatioLine1(benchmark::State& state) {
  for (auto _ : state) {
    const StepPath p = fixed_ratio_line({0, 0}, {20, 40});
    benchmark::DoNotOptimize(p.moves.data());
  }
}
BENCHMARK(BM_FixedRatioLine1);

}  // namespace
}  // namespace hwinterp::models
