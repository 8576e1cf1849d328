// Direct-mode lockstep speed of every core and variant, and where the time
// goes, side by side in one run on one seeded random stream per variant:
//   BM_Rtl/<variant>     the Verilated RTL (verilator --cc) alone
//   BM_Hls/<variant>     the HLS core's tick() alone
//   BM_Checks/<variant>  the lockstep loop (tb::run_direct) fed the recorded
//                        frames, outputs compared and nothing else
//                        (lockstep_clocks_per_s), and the direct mode as
//                        `hwinterp cosim --mode direct` runs it: the same loop
//                        with the stimulus, the scoreboard and the monitors
//                        (full_clocks_per_s). The two alternate, 9 pairs per
//                        variant, each timed in this thread's CPU time (the
//                        time a shared machine gives to others does not
//                        count); `checks` is the median over the pairs of the
//                        full mode's extra time, 1 - lockstep / full.
// The replays apply the input frames the direct mode applied (recorded once,
// through run_direct, so every benchmark sees the same clocks), kept as runs
// of equal frames: a replay reads a few runs from memory, not one frame per
// clock, and pays no memory traffic the direct mode does not.
// The hot loops are templated over the core's adapter (no virtual call per
// pin per clock). No main(): tests/bench_sc_main.cpp runs these.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstring>
#include <ctime>
#include <vector>

#include "../tb/lockstep_support.h"
#include "tb/lockstep/direct.h"

namespace hwinterp::tb::testing {
namespace {

constexpr uint64_t kCommands = 200;
constexpr uint64_t kSeed = 1;
constexpr int kPairs = 9;  // BM_Checks: lockstep/full pairs per variant

template <class A>
Case<A> stream(const VariantSpec& l) {
  Case<A> c = random_case<A>(l, kCommands, kSeed);
  validate_case(c, l);
  return c;
}

// A run of `count` equal input frames.
template <class A>
struct FrameRun {
  Frame<A> frame;
  uint64_t count;
};

// A Bench<A> that keeps every frame it hands out, as runs of equal frames.
// Frames are compared bytewise: they are copies of one object, so padding
// compares equal too, and a false difference would only split a run.
template <class A>
struct RecordingBench {
  Bench<A>& bench;
  std::vector<FrameRun<A>> runs;
  bool finished() const { return bench.finished(); }
  const Frame<A>& next_frame() {
    const Frame<A>& f = bench.next_frame();
    if (!runs.empty() && std::memcmp(&runs.back().frame, &f, sizeof f) == 0)
      ++runs.back().count;
    else
      runs.push_back({f, 1});
    return f;
  }
  void observe(const OutPins& hls, const OutPins& rtl) { bench.observe(hls, rtl); }
};

// The input frames of the variant's stream, recorded once per process.
template <class V>
const std::vector<FrameRun<typename V::Adapter>>& frames() {
  using A = typename V::Adapter;
  static const std::vector<FrameRun<A>> recorded = [] {
    BenchOptions o;
    o.mode = "direct";
    Bench<A> bench(V::spec(), {stream<A>(V::spec())}, o, flatten<V>());
    RecordingBench<A> rec{bench, {}};
    tb::run_direct<A, typename V::Cfg>(rec);
    if (!bench.results().at(0).passed()) throw std::runtime_error("the recorded run failed");
    return std::move(rec.runs);
  }();
  return recorded;
}

// The lockstep without checks: run_direct itself (the same loop as the full
// mode, so the same code runs the two DUTs) fed the recorded frames, with
// observe() comparing the outputs and nothing else.
template <class A>
struct ReplayBench {
  const std::vector<FrameRun<A>>& runs;
  size_t run = 0;
  uint64_t in_run = 0, clocks = 0, differ = 0;
  bool finished() const { return run == runs.size(); }
  const Frame<A>& next_frame() {
    const Frame<A>& f = runs[run].frame;
    if (++in_run == runs[run].count) {
      ++run;
      in_run = 0;
    }
    return f;
  }
  void observe(const OutPins& hls, const OutPins& rtl) {
    differ += !(hls == rtl);
    ++clocks;
  }
};

void report(benchmark::State& state, uint64_t clocks) {
  state.counters["clocks_per_s"] =
      benchmark::Counter(static_cast<double>(clocks), benchmark::Counter::kIsRate);
}

// What the replays run: the RTL or the HLS core.
enum class Replay { kRtl, kHls };

// One replay of the recorded frames, one of the two alone; returns the clocks run.
template <class V, Replay R>
uint64_t replay() {
  using A = typename V::Adapter;
  using Cfg = typename V::Cfg;
  using Core = typename A::template Hls<Cfg>;
  using Rtl = typename RtlOf<Cfg>::Cc;
  uint64_t clocks = 0;
  VerilatedContext context;
  Rtl rtl(&context);
  Core hls;
  typename Core::Inputs in;
  uint64_t payload_serial = ~uint64_t{0};
  rtl.clk_i = 0;
  rtl.rst_ni = 0;
  rtl.eval();
  for (const FrameRun<A>& run : frames<V>()) {
    for (uint64_t n = 0; n < run.count; ++n) {
      drive_inputs<A, Cfg>(run.frame, rtl, in, payload_serial);
      if constexpr (R == Replay::kRtl) {
        rtl.clk_i = 1;
        rtl.eval();
        rtl.clk_i = 0;
        rtl.eval();
      } else {
        hls.tick(in);
        benchmark::DoNotOptimize(hls.outputs());
      }
    }
    clocks += run.count;
  }
  rtl.final();
  Verilated::threadContextp(Verilated::defaultContextp());
  return clocks;
}

template <class V, Replay R>
void BM_Replay(benchmark::State& state) {
  frames<V>();  // recorded before the timing starts
  uint64_t clocks = 0;
  for (auto _ : state) clocks += replay<V, R>();
  report(state, clocks);
}

// CPU time of this thread, in seconds: time the shared machine gives to
// other processes does not count.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The lockstep replay and the full direct mode, alternating, each timed (CPU time); the
// rates are the totals', `checks` the median over the iterations of each
// pair's 1 - lockstep time / full time (a burst of load on a shared machine
// moves one pair, not the median).
template <class V>
void BM_Checks(benchmark::State& state) {
  using A = typename V::Adapter;
  const Case<A> c = stream<A>(V::spec());
  frames<V>();
  uint64_t lock_clocks = 0, full_clocks = 0, differ = 0;
  double lock_s = 0, full_s = 0;
  std::vector<double> shares;
  bool passed = true;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    ReplayBench<A> lockstep{frames<V>()};
    tb::run_direct<A, typename V::Cfg>(lockstep);
    lock_clocks += lockstep.clocks;
    differ += lockstep.differ;
    const double t1 = thread_seconds();
    BenchOptions o;
    o.mode = "direct";
    Bench<A> bench(V::spec(), {c}, o, flatten<V>());
    tb::run_direct<A, typename V::Cfg>(bench);
    const double t2 = thread_seconds();
    full_clocks += bench.cycles();
    passed = passed && bench.results().at(0).passed();
    const double lock = t1 - t0, full = t2 - t1;
    lock_s += lock;
    full_s += full;
    shares.push_back(1.0 - lock / full);
  }
  if (differ != 0) state.SkipWithError("the replayed HLS core and RTL differ");
  if (!passed) state.SkipWithError("the lockstep run failed");
  std::sort(shares.begin(), shares.end());
  state.counters["lockstep_clocks_per_s"] = static_cast<double>(lock_clocks) / lock_s;
  state.counters["full_clocks_per_s"] = static_cast<double>(full_clocks) / full_s;
  state.counters["checks"] = shares[shares.size() / 2];
  state.counters["clocks"] = static_cast<double>(full_clocks) / static_cast<double>(shares.size());
}

template <class... V>
struct Register;
template <class... V>
struct Register<::testing::Types<V...>> {
  static void one(const std::string& name, void (*fn)(benchmark::State&)) {
    benchmark::RegisterBenchmark(name.c_str(), fn)->Unit(benchmark::kMillisecond);
  }
  Register() {
    (one(std::string("BM_Rtl/") + V::Cfg::kVariant, BM_Replay<V, Replay::kRtl>), ...);
    (one(std::string("BM_Hls/") + V::Cfg::kVariant, BM_Replay<V, Replay::kHls>), ...);
    // A fixed count of pairs for the median, whatever each one takes.
    (benchmark::RegisterBenchmark((std::string("BM_Checks/") + V::Cfg::kVariant).c_str(),
                                  BM_Checks<V>)
         ->Unit(benchmark::kMillisecond)
         ->Iterations(kPairs),
     ...);
  }
};
const Register<AllVariants> registered;

}  // namespace
}  // namespace hwinterp::tb::testing
