// Optimal linear interpolation planner on every case of the OLI paper's
// Table 1 (Cam 1) and Table 3 (Cam 2): split at inflections, Process I and
// II per interval. The paper's Fortran needed up to 0.5 s per case; the
// target here is under 5 ms. Counters: segments and achieved error.
// Run: build/tests/bench_planner [--benchmark_filter=Cam2]
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "models/cam_profile.h"
#include "models/optimal_linear.h"
#include "models/polyline_verifier.h"

namespace {

using namespace hwinterp::models;

const TranslatingCam kCam1(CamLaw::kModifiedSine, 100, 40);
const RotatingCam kCam2(CamLaw::kModifiedSine, 40, 30, 100 * M_PI / 180);

void plan(benchmark::State& state, const PlanarCurve* cam, double tol) {
  OliPlan p;
  for (auto _ : state) {
    p = plan_optimal_linear(*cam, tol);
    benchmark::DoNotOptimize(p.vertices.data());
  }
  state.counters["segments"] = p.segments;
  state.counters["error_mm"] = p.error;
}

// The independent verifier on the same polylines (not part of the target).
void verify(benchmark::State& state, const PlanarCurve* cam, double tol) {
  const OliPlan p = plan_optimal_linear(*cam, tol);
  PolylineCheck c;
  for (auto _ : state) {
    c = verify_polyline(*cam, p.vertices);
    benchmark::DoNotOptimize(c.max_abs_error);
  }
  state.counters["segments"] = p.segments;
}

const int kRegistered = [] {
  const double table1[] = {0.1,    0.05,    0.02,   0.01,   0.005,   0.002,   0.001,
                           0.0005, 0.00025, 0.0002, 0.0001, 0.00005, 0.00002, 0.00001};
  const double table3[] = {0.1,   0.05,   0.02,    0.01,   0.005,  0.002,
                           0.001, 0.0005, 0.00025, 0.0002, 0.0001, 0.00005};
  for (double tol : table1)
    benchmark::RegisterBenchmark(("Plan/Cam1/E=" + std::to_string(tol)).c_str(), plan, &kCam1, tol)
        ->Unit(benchmark::kMillisecond);
  for (double tol : table3)
    benchmark::RegisterBenchmark(("Plan/Cam2/E=" + std::to_string(tol)).c_str(), plan, &kCam2, tol)
        ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("Verify/Cam1/E=0.000010", verify, &kCam1, 0.00001)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("Verify/Cam2/E=0.000050", verify, &kCam2, 0.00005)
      ->Unit(benchmark::kMillisecond);
  return 0;
}();

}  // namespace
