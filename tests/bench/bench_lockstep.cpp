// Direct-mode lockstep speed of every core and variant, and where the time
// goes, side by side in one run on one seeded random stream per variant:
//   BM_Rtl/<variant>        the Verilated RTL (verilator --cc) alone
//   BM_Hls/<variant>        the HLS core's tick() alone
//   BM_NoChecks/<variant>   both in lockstep, outputs compared, nothing else
//   BM_Direct/<variant>     the direct mode as `hwinterp cosim --mode direct`
//                           runs it: lockstep + scoreboard + monitors
// The first three replay the input frames BM_Direct applied (recorded once,
// through run_direct, so every benchmark sees the same clocks); the checks'
// share of the lockstep time is 1 - NoChecks / Direct in clocks per second.
// The hot loops are templated over the core's adapter (no virtual call per
// pin per clock). No main(): tests/bench_sc_main.cpp runs these.
#include <benchmark/benchmark.h>

#include <vector>

#include "../tb/lockstep_support.h"
#include "tb/lockstep/direct.h"

namespace hwinterp::tb::testing {
namespace {

constexpr uint64_t kCommands = 200;
constexpr uint64_t kSeed = 1;

template <class A>
Case<A> stream(const CoreLimits& l) {
  Case<A> c = random_case<A>(l, kCommands, kSeed);
  validate_case(c, l);
  return c;
}

// A Bench<A> that keeps a copy of every frame it hands out.
template <class A>
struct RecordingBench {
  Bench<A>& bench;
  std::vector<Frame<A>> frames;
  bool finished() const { return bench.finished(); }
  const Frame<A>& next_frame() {
    frames.push_back(bench.next_frame());
    return frames.back();
  }
  void observe(const OutPins& hls, const OutPins& rtl) { bench.observe(hls, rtl); }
};

// The input frames of the variant's stream, recorded once per process.
template <class V>
const std::vector<Frame<typename V::Adapter>>& frames() {
  using A = typename V::Adapter;
  static const std::vector<Frame<A>> recorded = [] {
    BenchOptions o;
    o.mode = "direct";
    Bench<A> bench(V::limits(), {stream<A>(V::limits())}, o);
    RecordingBench<A> rec{bench, {}};
    tb::run_direct<A, typename V::Cfg>(rec);
    if (!bench.results().at(0).passed()) throw std::runtime_error("the recorded run failed");
    return std::move(rec.frames);
  }();
  return recorded;
}

template <class V>
void report(benchmark::State& state, uint64_t clocks) {
  state.counters["clocks_per_s"] =
      benchmark::Counter(static_cast<double>(clocks), benchmark::Counter::kIsRate);
}

// What the replays run: the RTL, the HLS core, or both compared.
enum class Replay { kRtl, kHls, kBoth };

template <class V, Replay R>
void BM_Replay(benchmark::State& state) {
  using A = typename V::Adapter;
  using Cfg = typename V::Cfg;
  using Core = typename A::template Hls<Cfg>;
  using Rtl = typename RtlOf<Cfg>::Cc;
  const auto& in_frames = frames<V>();
  uint64_t clocks = 0, differ = 0;
  for (auto _ : state) {
    VerilatedContext context;
    Rtl rtl(&context);
    Core hls;
    typename Core::Inputs in;
    rtl.clk_i = 0;
    rtl.rst_ni = 0;
    rtl.eval();
    for (const Frame<A>& f : in_frames) {
      drive_inputs<A, Cfg>(f, rtl, in);
      if constexpr (R != Replay::kHls) {
        rtl.clk_i = 1;
        rtl.eval();
      }
      if constexpr (R != Replay::kRtl) hls.tick(in);
      if constexpr (R == Replay::kBoth)
        differ += !(read_outputs(hls.outputs()) == read_outputs<Cfg>(rtl));
      if constexpr (R == Replay::kHls) benchmark::DoNotOptimize(hls.outputs());
      if constexpr (R != Replay::kHls) {
        rtl.clk_i = 0;
        rtl.eval();
      }
    }
    rtl.final();
    clocks += in_frames.size();
  }
  Verilated::threadContextp(Verilated::defaultContextp());
  if (differ != 0) state.SkipWithError("the replayed HLS core and RTL differ");
  report<V>(state, clocks);
}

template <class V>
void BM_Direct(benchmark::State& state) {
  using A = typename V::Adapter;
  const Case<A> c = stream<A>(V::limits());
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
  report<V>(state, cycles);
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
    (one(std::string("BM_NoChecks/") + V::Cfg::kVariant, BM_Replay<V, Replay::kBoth>), ...);
    (one(std::string("BM_Direct/") + V::Cfg::kVariant, BM_Direct<V>), ...);
  }
};
const Register<AllVariants> registered;

}  // namespace
}  // namespace hwinterp::tb::testing
