// The conformance suite: what every step-emitting core promises through the
// shared port contract, run against every core and variant of
// cmake/cores.cmake (GoogleTest typed tests; a new core joins by being
// declared there). HLS and RTL in lockstep, both against the core's reference
// model, in the direct mode unless a test says otherwise.
//
// SystemC tests elaborate once per process: run them through ctest, which
// gives every test its own process (gtest_discover_tests).
#include <gtest/gtest.h>

#include "lockstep_support.h"
#include "run_hwinterp.h"

namespace hwinterp::tb::testing {
namespace {

template <class V>
class Conformance : public ::testing::Test {
 protected:
  using A = typename V::Adapter;
  using Kind = typename Item<A>::Kind;
  VariantSpec l = V::spec();

  // A command that keeps the core busy for a while (at least `work` engine
  // operations), drawn from the core's own random generator.
  typename A::Command long_command(uint64_t work, uint64_t seed) {
    Rng rng(seed);
    models::LatticePoint at(static_cast<size_t>(l.axes), 0);
    typename A::Command previous{};
    for (int tries = 0; tries < 100000; ++tries) {
      const auto c = A::random_command(rng, l, at, previous);
      if (A::work(c, l) >= work) return c;
      previous = c;
    }
    ADD_FAILURE() << "no command with " << work << " operations";
    return {};
  }

  Case<A> one_command_case(const typename A::Command& cmd) {
    Case<A> c;
    c.name = "one";
    c.start.assign(static_cast<size_t>(l.axes), 0);
    c.settings = default_settings<A>(l);
    c.items.push_back(command_item<A>(cmd));
    return c;
  }

  Item<A> settings_item(const RunSettings<A>& s) {
    Item<A> it;
    it.kind = Kind::kSettings;
    it.settings = s;
    return it;
  }
  Item<A> gap(uint64_t cycles) {
    Item<A> it;
    it.kind = Kind::kGap;
    it.cycles = cycles;
    return it;
  }

  // Steps per axis the reference model expects for the case's commands.
  std::vector<uint64_t> model_steps(const Case<A>& c) {
    std::vector<uint64_t> steps(static_cast<size_t>(l.axes), 0);
    models::LatticePoint at = c.start;
    RunSettings<A> s = c.settings;
    for (const auto& it : c.items) {
      if (it.kind == Kind::kSettings) s = it.settings;
      if (it.kind != Kind::kCommand) continue;
      typename A::Reference ref(at, it.cmd, s.setup, l);
      Move m;
      while (ref.next(m))
        for (size_t i = 0; i < steps.size(); ++i) steps[i] += m.step[i] != 0;
      A::apply(it.cmd, at);
    }
    return steps;
  }
};

TYPED_TEST_SUITE(Conformance, AllVariants, VariantName);

// After reset, and after a reset in the middle of a move, both faces show
// the idle state: ready, no step, dir 0, position 0, not busy, no done. A
// reset is not a safe stop (it cuts a pulse, drops dir to 0), but it counts
// as the end of a pulse and a change of dir: the first step after it keeps
// step_space and dir_setup (here 10 clocks) from the reset, which the
// monitors check on every axis.
TYPED_TEST(Conformance, ResetStateAndResetMidMove) {
  using A = typename TypeParam::Adapter;
  using Cfg = typename TypeParam::Cfg;
  using Core = typename A::template Hls<Cfg>;
  VerilatedContext context;
  typename RtlOf<Cfg>::Cc rtl(&context);
  Core hls;
  typename Core::Inputs in;
  uint64_t payload_serial = ~uint64_t{0};
  Frame<A> f;
  f.feed = this->l.full_feed();
  f.timing = {2, 2, std::min<uint32_t>(10, static_cast<uint32_t>(this->l.tim_max())), 3};
  std::vector<StepdirMonitor> monitors;
  for (int i = 0; i < this->l.axes; ++i) monitors.emplace_back(i);
  std::vector<TimingViolation> violations;
  uint64_t violation_count = 0, cycle = 0;
  OutPins idle;
  idle.cmd_ready = true;
  auto edge = [&] {
    drive_inputs<A, Cfg>(f, rtl, in, payload_serial);
    rtl.clk_i = 1;
    rtl.eval();
    hls.tick(in);
    const OutPins h = read_outputs(hls.outputs()), r = read_outputs<Cfg>(rtl);
    EXPECT_EQ(h, r) << "cycle " << cycle;
    rtl.clk_i = 0;
    rtl.eval();
    ++cycle;
    for (int i = 0; i < this->l.axes; ++i) {
      if (!f.rst_n)
        monitors[static_cast<size_t>(i)].reset(cycle);
      else
        monitors[static_cast<size_t>(i)].observe(cycle, (r.step >> i) & 1, (r.dir >> i) & 1,
                                                 f.timing, violations, violation_count);
    }
    return r;
  };
  f.rst_n = false;
  edge();
  EXPECT_EQ(edge(), idle);
  f.rst_n = true;
  f.cmd_valid = true;
  f.set_cmd(this->long_command(64, 3));
  // Clocks until a few steps are out: a core may compute for a while before
  // its first step (log_stepper's first point takes about 100 clocks).
  int before = 0, after = 0;
  for (int k = 0; k < 20000 && before < 3; ++k) before += edge().step != 0;
  EXPECT_GT(before, 0) << "the command never stepped: the reset below would prove nothing";
  f.rst_n = false;
  EXPECT_EQ(edge(), idle);
  f.rst_n = true;
  for (int k = 0; k < 20000 && after < 3; ++k) after += edge().step != 0;
  for (int k = 0; k < 20; ++k) edge();  // the pulses after the third, watched too
  EXPECT_GT(after, 0) << "no step after the reset: its timing was not exercised";
  EXPECT_EQ(violation_count, 0u) << "first: axis " << violations.front().axis << " "
                                 << violations.front().rule << " " << violations.front().measured
                                 << " < " << violations.front().required << " at cycle "
                                 << violations.front().cycle;
  rtl.final();
  Verilated::threadContextp(Verilated::defaultContextp());
}

// Commands offered back to back at a slow feed: the core pushes back
// (cmd_ready_o low while a command waits) and takes every one, none dropped,
// each completed with one done_o.
TYPED_TEST(Conformance, BackpressureNeverDropsACommand) {
  using A = typename TypeParam::Adapter;
  Case<A> c = random_case<A>(this->l, 60, 21);
  c.name = "back_to_back";
  std::vector<Item<A>> commands;
  for (const auto& it : c.items)
    if (it.kind == Item<A>::Kind::kCommand) commands.push_back(it);
  c.items = commands;
  c.settings.feed = this->l.full_feed() / 3;
  const auto r = run_direct<TypeParam>({c});
  expect_all_pass(r);
  EXPECT_EQ(r[0].commands, 60u);
  EXPECT_GT(r[0].offer_wait_cycles, 100u) << "the stream never met backpressure";
}

// Seeded random streams: exact per-axis step counts (the model's), exact end
// points, every move the model's, no timing violation, over 10^4 clocks.
TYPED_TEST(Conformance, ExactCountsAndEndPointsOnRandomStreams) {
  using A = typename TypeParam::Adapter;
  uint64_t cycles = 0;
  for (const uint64_t seed : {1u, 2u, 3u}) {
    const Case<A> c = random_case<A>(this->l, 80, seed);
    const auto r = run_direct<TypeParam>({c});
    expect_all_pass(r);
    EXPECT_EQ(r[0].steps, this->model_steps(c)) << "seed " << seed;
    cycles += r[0].cycles;
  }
  EXPECT_GT(cycles, 10000u);
  this->RecordProperty("cycles", std::to_string(cycles));
}

// The random streams change the timing settings while the core runs (long
// settings among them); the monitors find nothing. A glitch on the observed
// step_o proves they are watching this core's pins.
TYPED_TEST(Conformance, MonitorsCleanUnderRandomTiming) {
  using A = typename TypeParam::Adapter;
  const Case<A> c = random_case<A>(this->l, 80, 5);
  uint32_t longest = c.settings.timing.step_len;
  for (const auto& it : c.items)
    if (it.kind == Item<A>::Kind::kSettings)
      longest = std::max({longest, it.settings.timing.step_len, it.settings.timing.step_space,
                          it.settings.timing.dir_setup, it.settings.timing.dir_hold});
  EXPECT_GE(longest, 5u) << "the stream never tried a long setting";
  const auto clean = run_direct<TypeParam>({c});
  expect_all_pass(clean);
  EXPECT_EQ(clean[0].timing_violation_count, 0u);
  ASSERT_GT(clean[0].first_step_cycle, 0u);
  BenchOptions o;
  o.faults.glitch_step_at = clean[0].first_step_cycle + 1;  // cuts the first pulse short
  const auto glitched = run_direct<TypeParam>({c}, o);
  EXPECT_GE(glitched[0].timing_violation_count, 1u);
}

// Abort: at random depths into random streams (each followed by a drain),
// the position is a point of the reference path, no step starts on the
// abort edge, busy_o falls within max(step_len, 1) - 1 clocks, the dropped
// commands never step, and the commands after run exactly.
TYPED_TEST(Conformance, AbortStopsOnThePathAndTheCoreGoesOn) {
  using A = typename TypeParam::Adapter;
  size_t aborts = 0, measured = 0;
  for (const uint64_t seed : {11u, 12u}) {
    const Case<A> c = random_case<A>(this->l, 80, seed, {true, false});
    const auto r = run_direct<TypeParam>({c});
    expect_all_pass(r);
    for (const auto& a : r[0].aborts) {
      EXPECT_TRUE(a.on_reference_path);
      if (a.idle_after_clocks >= 0) {
        ++measured;
        EXPECT_LE(static_cast<uint64_t>(a.idle_after_clocks), a.idle_bound);
      }
    }
    aborts += r[0].aborts.size();
  }
  EXPECT_GE(aborts, 5u);
  EXPECT_GE(measured, 5u);
}

// --abort-at in the middle of one long command: one abort, on the path,
// short of the command's end, measured idle within the bound.
TYPED_TEST(Conformance, AbortAtACycleMidCommand) {
  using A = typename TypeParam::Adapter;
  const Case<A> c = this->one_command_case(this->long_command(200, 7));
  const auto clean = run_direct<TypeParam>({c});
  expect_all_pass(clean);
  BenchOptions o;
  o.abort_at = clean[0].first_step_cycle + (clean[0].cycles - clean[0].first_step_cycle) / 2;
  const auto r = run_direct<TypeParam>({c}, o);
  expect_all_pass(r);
  ASSERT_EQ(r[0].aborts.size(), 1u);
  const AbortRecord& a = r[0].aborts[0];
  EXPECT_TRUE(a.on_reference_path);
  EXPECT_NE(a.position, clean[0].end_position);
  EXPECT_EQ(r[0].end_position, a.position);
  ASSERT_GE(a.idle_after_clocks, 0);
  EXPECT_LE(static_cast<uint64_t>(a.idle_after_clocks), a.idle_bound);
  EXPECT_LT(r[0].cycles, clean[0].cycles);
}

// Feed hold: feed 0 in the middle of a move holds it (for at least the hold),
// the feed back resumes it, and it ends exactly; random holds run clean.
TYPED_TEST(Conformance, FeedHoldAndResumeEndsExactly) {
  using A = typename TypeParam::Adapter;
  Case<A> c = this->one_command_case(this->long_command(200, 9));
  const auto clean = run_direct<TypeParam>({c});
  expect_all_pass(clean);
  RunSettings<A> hold = c.settings;
  hold.feed = 0;
  c.items.push_back(this->gap(clean[0].cycles / 2));
  c.items.push_back(this->settings_item(hold));
  c.items.push_back(this->gap(500));
  c.items.push_back(this->settings_item(c.settings));
  const auto held = run_direct<TypeParam>({c});
  expect_all_pass(held);
  EXPECT_EQ(held[0].steps, clean[0].steps);
  EXPECT_GE(held[0].cycles, clean[0].cycles + 495);
  expect_all_pass(run_direct<TypeParam>({random_case<A>(this->l, 60, 13, {false, true})}));
}

// The comparator fails at the injected cycle, naming the signal.
TYPED_TEST(Conformance, InjectedMismatchIsCaughtAtItsCycle) {
  using A = typename TypeParam::Adapter;
  BenchOptions o;
  o.faults.flip_hls_step_at = 77;
  const auto r = run_direct<TypeParam>({random_case<A>(this->l, 20, 9)}, o);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].passed());
  ASSERT_TRUE(r[0].first_mismatch.has_value());
  EXPECT_EQ(r[0].first_mismatch->cycle, 77u);
  EXPECT_EQ(r[0].first_mismatch->signal, "step_o[0]");
  EXPECT_EQ(r[0].cycles, 77u);
}

// Through the command line: the printed replay command reproduces the
// failure (same cycle, same signal) and writes the trace window.
TYPED_TEST(Conformance, PrintedReplayCommandReproducesTheMismatch) {
  using hwinterp::testing::run_hwinterp;
  using hwinterp::testing::scratch_dir;
  const std::string dir = scratch_dir(std::string("replay_") + TypeParam::Cfg::kVariant);
  const std::string base = std::string("cosim --core ") + TypeParam::Cfg::kCore + " --variant " +
                           TypeParam::Cfg::kVariant + " --random 20 --seed 9 --mode direct";
  const auto first = run_hwinterp(base + " --inject mismatch@77 --json " + dir + "/a.json");
  ASSERT_EQ(first.code, 1) << first.out << first.err;
  const Json a = Json::parse(hwinterp::testing::slurp(dir + "/a.json"));
  ASSERT_TRUE(a.contains("replay"));
  std::string replay = a["replay"].get<std::string>();
  ASSERT_EQ(replay.rfind("hwinterp cosim ", 0), 0u) << replay;
  const std::string vcd = "--vcd mismatch.vcd";
  ASSERT_NE(replay.find(vcd), std::string::npos) << replay;
  replay.replace(replay.find(vcd), vcd.size(), "--vcd " + dir + "/m.vcd");
  const auto again = run_hwinterp(replay.substr(9) + " --json " + dir + "/b.json");
  ASSERT_EQ(again.code, 1) << again.out << again.err;
  const Json b = Json::parse(hwinterp::testing::slurp(dir + "/b.json"));
  EXPECT_EQ(b["first_mismatch"], a["first_mismatch"]);
  EXPECT_EQ(b["first_mismatch"]["cycle"], 77);
  EXPECT_NE(hwinterp::testing::slurp(dir + "/m.vcd").find("\n#770\n"), std::string::npos);
}

// The SystemC mode is the same machine: one stimulus, identical cycles,
// steps, end points and errors. Elaborates SystemC (own process).
TYPED_TEST(Conformance, SystemcMatchesDirect) {
  using A = typename TypeParam::Adapter;
  std::vector<Case<A>> cases = A::regression_cases(this->l, 60, 42);
  const auto direct = run_direct<TypeParam>(cases);
  const auto sc = run_systemc<TypeParam>(cases);
  expect_all_pass(sc);
  ASSERT_EQ(direct.size(), sc.size());
  for (size_t i = 0; i < direct.size(); ++i) {
    EXPECT_EQ(direct[i].cycles, sc[i].cycles) << direct[i].name;
    EXPECT_EQ(direct[i].steps, sc[i].steps) << direct[i].name;
    EXPECT_EQ(direct[i].end_position, sc[i].end_position) << direct[i].name;
    EXPECT_DOUBLE_EQ(direct[i].max_path_error_steps, sc[i].max_path_error_steps) << direct[i].name;
  }
}

// Behind a feed profile with random limits (issue 25; tb/lockstep/case_profile.h),
// every core visits the lattice points of the same case at constant feed words,
// in the same order, and ends exactly; the bench checks the step stream's
// speed (and, for the line cores, acceleration and jerk) against the profile's
// limits, and a case fails otherwise. (SystemcMatchesDirect runs the
// regression's "random_profile" case in both modes.)
TYPED_TEST(Conformance, FeedProfileKeepsTheLatticePathWithinRandomLimits) {
  using A = typename TypeParam::Adapter;
  BenchOptions o;
  o.record_path = true;
  for (const uint64_t seed : {11u, 12u}) {
    const Case<A> profiled = random_profile_case<A>(this->l, 40, seed);
    Case<A> flat = profiled;
    flat.profile.reset();
    const auto rp = run_direct<TypeParam>({profiled}, o);
    const auto rf = run_direct<TypeParam>({flat}, o);
    expect_all_pass(rp);
    expect_all_pass(rf);
    EXPECT_EQ(rp[0].visited, rf[0].visited) << "seed " << seed;
    EXPECT_GT(rp[0].cycles, rf[0].cycles) << "seed " << seed;
    // The limit checks ran: windows were measured.
    bool checked = false;
    for (const auto& cc : rp[0].core_checks)
      if (cc.name == "profile_axis_speed_steps_per_clock") checked = cc.count > 3 && cc.max > 0;
    EXPECT_TRUE(checked) << describe(rp[0]);
  }
}

// The limit check is not idle: the same commands at full feed, with no
// profile, break the acceleration limit of a slow profile on some axis, as
// the same estimator measures it.
TYPED_TEST(Conformance, WithoutTheProfileTheSameCommandsBreakItsLimits) {
  using A = typename TypeParam::Adapter;
  Case<A> flat = random_profile_case<A>(this->l, 40, 11);
  flat.profile.reset();
  for (auto& it : flat.items)
    if (it.kind == Item<A>::Kind::kSettings) it.settings.feed = this->l.full_feed();
  flat.settings.feed = this->l.full_feed();
  const ProfileClockLimits slow = profile_clock_limits({1.0 / 256, 8});
  struct Watch : MoveObserver {
    KinematicsMonitor kin;
    uint64_t last = 0;
    Watch(int axes, uint64_t window) : kin(axes, std::vector<double>(axes, 1.0), window) {}
    void move(const models::LatticePoint&, uint64_t) override {}
    void done(uint64_t, const models::LatticePoint&) override {}
    void pulses(uint64_t clock, uint32_t rising, uint32_t dir) override {
      kin.pulses(clock, rising, dir);
      last = clock;
    }
  } watch(this->l.axes, 4 << kProfileTickW);
  BenchOptions o;
  o.observer = &watch;
  expect_all_pass(run_direct<TypeParam>({flat}, o));
  watch.kin.finish(watch.last + 1);
  double accel = 0;
  for (int i = 0; i < this->l.axes; ++i) accel = std::max(accel, watch.kin.axis(i).accel.value);
  EXPECT_GT(accel, slow.accel + 2 * watch.kin.tolerance().accel.value);
}

// The SystemC-mode comparator fails at the injected cycle too.
TYPED_TEST(Conformance, SystemcInjectedMismatchIsCaught) {
  using A = typename TypeParam::Adapter;
  BenchOptions o;
  o.faults.flip_hls_step_at = 123;
  const auto r = run_systemc<TypeParam>({random_case<A>(this->l, 20, 5)}, o);
  ASSERT_EQ(r.size(), 1u);
  ASSERT_TRUE(r[0].first_mismatch.has_value());
  EXPECT_EQ(r[0].first_mismatch->cycle, 123u);
  EXPECT_FALSE(r[0].passed());
}

}  // namespace
}  // namespace hwinterp::tb::testing
