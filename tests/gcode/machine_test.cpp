// The machine description file: defaults, the sample file, overrides, and
// every kind of bad value named with its key.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "gcode_test_util.h"
#include "tb/gcode/machine.h"

namespace hwinterp::gcode {
namespace {

using test::mentions;

Machine from(const std::string& text) {
  std::istringstream in(text);
  return read_machine(in, "m.json");
}

std::string error_of(const std::string& text) {
  return test::error_of([&] { from(text); });
}

void expect_same(const Machine& a, const Machine& b) {
  EXPECT_EQ(a.has_axis, b.has_axis);
  EXPECT_EQ(a.steps_per_unit, b.steps_per_unit);
  EXPECT_EQ(a.clock_hz, b.clock_hz);
  EXPECT_EQ(a.rapid_mm_per_min, b.rapid_mm_per_min);
  EXPECT_EQ(a.timing.step_len, b.timing.step_len);
  EXPECT_EQ(a.timing.step_space, b.timing.step_space);
  EXPECT_EQ(a.timing.dir_setup, b.timing.dir_setup);
  EXPECT_EQ(a.timing.dir_hold, b.timing.dir_hold);
}

TEST(Machine, DefaultsAreTheProjects) {
  const Machine m;
  EXPECT_EQ(m.axes(), "XYZA");
  EXPECT_EQ(m.steps_per_unit[kX], 1000);
  EXPECT_EQ(m.steps_per_unit[kY], 1000);
  EXPECT_EQ(m.steps_per_unit[kZ], 1000);
  EXPECT_EQ(m.steps_per_unit[kA], 100);
  EXPECT_EQ(m.clock_hz, 50'000'000);
  EXPECT_EQ(m.rapid_mm_per_min, 5000);
  EXPECT_EQ(m.timing.step_len, 2);
  EXPECT_EQ(m.timing.step_space, 2);
  EXPECT_EQ(m.timing.dir_setup, 3);
  EXPECT_EQ(m.timing.dir_hold, 3);
  expect_same(from("{}"), m);
}

TEST(Machine, TheSampleFileSpellsOutTheDefaults) {
  expect_same(load_machine(HWINTERP_GCODE_DATA "/machine_default.json"), Machine{});
}

TEST(Machine, KeysOverrideTheirDefaultsOnly) {
  const Machine m = from(
      R"({"axes": ["X", "Y", "C"], "steps_per_unit": {"X": 400, "C": 50.0},
          "clock_hz": 100e6, "rapid_mm_per_min": 2500.5,
          "timing_clocks": {"dir_hold": 7}})");
  EXPECT_EQ(m.axes(), "XYC");
  EXPECT_EQ(m.steps_per_unit[kX], 400);
  EXPECT_EQ(m.steps_per_unit[kY], 1000);
  EXPECT_EQ(m.steps_per_unit[kC], 50);
  EXPECT_EQ(m.clock_hz, 100'000'000);
  EXPECT_EQ(m.rapid_mm_per_min, 2500.5);
  EXPECT_EQ(m.timing.dir_hold, 7);
  EXPECT_EQ(m.timing.step_len, 2);
}

TEST(Machine, TravelAndLimitsArePerAxisAndUnlimitedWhenUnlisted) {
  const Machine m = from(
      R"({"travel": {"X": [-10, 300.5], "A": [-360, 360]},
          "max_velocity": {"X": 100}, "max_accel": {"X": 2000, "Z": 500},
          "max_jerk": {"Y": 1e5}})");
  EXPECT_EQ(m.travel[kX].min, -10);
  EXPECT_EQ(m.travel[kX].max, 300.5);
  EXPECT_EQ(m.travel[kA].max, 360);
  EXPECT_TRUE(m.travel[kX].limited());
  EXPECT_FALSE(m.travel[kY].limited());
  EXPECT_EQ(m.limits[kX].velocity, 100);
  EXPECT_EQ(m.limits[kX].accel, 2000);
  EXPECT_EQ(m.limits[kZ].accel, 500);
  EXPECT_EQ(m.limits[kY].jerk, 1e5);
  EXPECT_TRUE(std::isinf(m.limits[kY].velocity));
  EXPECT_TRUE(std::isinf(m.limits[kX].jerk));
  EXPECT_FALSE(Machine{}.travel[kZ].limited());
}

TEST(Machine, BadValuesNameTheirKey) {
  struct Case {
    const char* json;
    std::vector<std::string> parts;
  };
  const Case cases[] = {
      {R"({"spindle": 1})", {"spindle", "unknown key"}},
      {R"({"profile": "smooth"})", {"profile", "'smooth'", "scurve, trapezoid or off"}},
      {R"({"profile": 1})", {"profile", "not \"scurve\""}},
      {R"({"clock_hz": "fast"})", {"clock_hz", "\"fast\"", "not a number"}},
      {R"({"clock_hz": true})", {"clock_hz", "true", "not a number"}},
      {R"({"clock_hz": 0})", {"clock_hz", "= 0", "outside"}},
      {R"({"clock_hz": -5})", {"clock_hz", "-5", "outside"}},
      {R"({"clock_hz": 1.5e11})", {"clock_hz", "outside"}},
      {R"({"clock_hz": 1000000.5})", {"clock_hz", "not an integer"}},
      {R"({"clock_hz": 18446744073709551615})", {"clock_hz", "outside"}},
      {R"({"rapid_mm_per_min": 0})", {"rapid_mm_per_min", "outside"}},
      {R"({"rapid_mm_per_min": -1})", {"rapid_mm_per_min", "outside"}},
      {R"({"rapid_mm_per_min": null})", {"rapid_mm_per_min", "null", "not a number"}},
      {R"({"steps_per_unit": {"X": 1000.5}})", {"steps_per_unit.X", "1000.5", "not an integer"}},
      {R"({"steps_per_unit": {"Y": 0}})", {"steps_per_unit.Y", "outside"}},
      {R"({"steps_per_unit": {"Z": -100}})", {"steps_per_unit.Z", "-100", "outside"}},
      {R"({"steps_per_unit": {"Q": 100}})", {"steps_per_unit.Q", "not an axis"}},
      {R"({"steps_per_unit": {"B": 100}})", {"steps_per_unit.B", "no B axis", "XYZA"}},
      {R"({"steps_per_unit": [1000]})", {"steps_per_unit", "not an object"}},
      {R"({"axes": []})", {"axes", "non-empty"}},
      {R"({"axes": "XYZ"})", {"axes", "non-empty list"}},
      {R"({"axes": ["X", "X"]})", {"axes", "listed twice"}},
      {R"({"axes": ["x"]})", {"axes", "not an axis"}},
      {R"({"axes": [1]})", {"axes", "not an axis name"}},
      {R"({"timing_clocks": {"step_len": 0}})", {"timing_clocks.step_len", "outside"}},
      {R"({"timing_clocks": {"dir_setup": 2.5}})", {"timing_clocks.dir_setup", "not an integer"}},
      {R"({"timing_clocks": {"step_ns": 20}})", {"timing_clocks.step_ns", "unknown key"}},
      {R"({"timing_clocks": {"dir_hold": 65536}})", {"timing_clocks.dir_hold", "outside"}},
      {R"({"comment": 3})", {"comment", "not a string"}},
      {R"({"travel": {"X": [5, 5]}})", {"travel.X", "[5,5]", "not min < max"}},
      {R"({"travel": {"X": [5]}})", {"travel.X", "not [min, max]"}},
      {R"({"travel": {"X": ["a", 1]}})", {"travel.X", "not [min, max]"}},
      {R"({"travel": {"B": [0, 1]}})", {"travel.B", "no B axis"}},
      {R"({"travel": [0, 1]})", {"travel", "not an object"}},
      {R"({"max_velocity": {"X": 0}})", {"max_velocity.X", "outside"}},
      {R"({"max_accel": {"Y": -1}})", {"max_accel.Y", "-1", "outside"}},
      {R"({"max_jerk": {"Z": "x"}})", {"max_jerk.Z", "not a number"}},
      {R"({"max_jerk": {"Q": 1}})", {"max_jerk.Q", "not an axis"}},
      {R"({"clock_hz": 1, "clock_hz": 2})", {"'clock_hz' given twice"}},
      {R"({"timing_clocks": {"step_len": 1, "step_len": 2}})", {"'step_len' given twice"}},
      {R"([1, 2])", {"not a JSON object"}},
      {R"({"clock_hz": 5)", {"not a JSON machine description"}},
      {"", {"not a JSON machine description"}},
      {R"({"comment": [[[[[[[[[[1]]]]]]]]]]})", {"nested deeper"}},
  };
  for (const auto& c : cases) {
    auto parts = c.parts;
    parts.push_back("m.json: ");
    EXPECT_TRUE(mentions(error_of(c.json), parts)) << c.json;
  }
}

TEST(Machine, AMissingFileIsAUsageError) {
  EXPECT_TRUE(mentions(test::error_of([] { load_machine("/nonexistent/m.json"); }),
                       {"--machine", "/nonexistent/m.json"}));
}

}  // namespace
}  // namespace hwinterp::gcode
