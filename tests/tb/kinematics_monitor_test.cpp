// The kinematics estimator (tb/monitor/kinematics.h) on synthetic step
// streams whose motion is known: it finds each motion's speed,
// acceleration and jerk within its stated tolerance, and never reports more
// than the motion's highest plus the tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "tb/monitor/kinematics.h"

namespace hwinterp::tb {
namespace {

// Feeds the monitor the pulses of position x(clock) (steps, truncated to
// the lattice toward -infinity) on axis 0, and y(clock) on axis 1, for
// `clocks` clocks.
KinematicsMonitor run(const std::function<double(double)>& x,
                      const std::function<double(double)>& y, uint64_t clocks, uint64_t window,
                      std::vector<double> unit = {1, 1}) {
  KinematicsMonitor m(2, std::move(unit), window);
  long long px = 0, py = 0;
  for (uint64_t c = 1; c <= clocks; ++c) {
    const long long nx = static_cast<long long>(std::floor(x(static_cast<double>(c))));
    const long long ny = static_cast<long long>(std::floor(y(static_cast<double>(c))));
    // at most one step per axis per clock in these motions
    uint32_t rising = 0, dir = 0;
    if (nx != px) rising |= 1, dir |= nx < px ? 1 : 0;
    if (ny != py) rising |= 2, dir |= ny < py ? 2 : 0;
    px += nx > px ? 1 : nx < px ? -1 : 0;
    py += ny > py ? 1 : ny < py ? -1 : 0;
    if (rising) m.pulses(c, rising, dir);
  }
  m.finish(clocks);
  return m;
}

TEST(KinematicsMonitor, AConstantSpeedHasNoAccelerationBeyondTheTolerance) {
  const uint64_t w = 1000;
  const auto m =
      run([](double c) { return 0.3 * c; }, [](double c) { return -0.05 * c; }, 50'000, w);
  const auto tol = m.tolerance();
  EXPECT_EQ(m.windows(), 50u);
  EXPECT_NEAR(m.axis(0).speed.value, 0.3, tol.speed.value);
  EXPECT_NEAR(m.axis(1).speed.value, 0.05, tol.speed.value);
  EXPECT_LE(m.axis(0).accel.value, tol.accel.value);
  EXPECT_LE(m.axis(0).jerk.value, tol.jerk.value);
  EXPECT_NEAR(m.path().speed.value, std::hypot(0.3, 0.05), 2 * tol.speed.value);
}

TEST(KinematicsMonitor, AConstantAccelerationIsFoundWithinTheTolerance) {
  // x = a c^2 / 2 up to 0.5 steps/clock: a = 1e-6 steps/clock^2.
  const double a = 1e-6;
  const uint64_t w = 2000, clocks = 400'000;
  const auto m =
      run([&](double c) { return a * c * c / 2; }, [](double) { return 0.0; }, clocks, w);
  const auto tol = m.tolerance();
  EXPECT_NEAR(m.axis(0).speed.value, a * clocks, a * w + tol.speed.value);
  EXPECT_NEAR(m.axis(0).accel.value, a, tol.accel.value);
  EXPECT_LE(m.axis(0).jerk.value, tol.jerk.value);
  EXPECT_EQ(m.axis(1).speed.value, 0);
}

TEST(KinematicsMonitor, AJerkLimitedStartStaysWithinItsLimitsPlusTheTolerance) {
  // S-curve from rest: jerk J for T clocks, then constant acceleration.
  const double j = 1e-10, T = 50'000;
  auto x = [&](double c) {
    if (c <= T) return j * c * c * c / 6;
    const double a = j * T, v = j * T * T / 2, p = j * T * T * T / 6, d = c - T;
    return p + v * d + a * d * d / 2;
  };
  const uint64_t w = 5000;
  const auto m = run(
      x, [](double) { return 0.0; }, 120'000, w);
  const auto tol = m.tolerance();
  EXPECT_LE(m.axis(0).jerk.value, j + tol.jerk.value);
  EXPECT_GE(m.axis(0).jerk.value, j - tol.jerk.value);
  EXPECT_LE(m.axis(0).accel.value, j * T + tol.accel.value);
  EXPECT_GE(m.axis(0).accel.value, j * T - j * w - tol.accel.value);
}

TEST(KinematicsMonitor, AStartFromRestAtFullSpeedShowsAsAJump) {
  // What the cores do today without a profile: 0.5 steps/clock at once.
  const uint64_t w = 1000;
  const auto m = run([](double c) { return c > 3000 ? 0.5 * (c - 3000) : 0.0; },
                     [](double) { return 0.0; }, 20'000, w);
  // From 0 to 0.5 steps/clock between two windows: 0.5/w per clock.
  EXPECT_NEAR(m.axis(0).accel.value, 0.5 / static_cast<double>(w), m.tolerance().accel.value);
  EXPECT_EQ(m.axis(0).accel.clock, 3999u);  // the window of clocks 3000..3999
}

TEST(KinematicsMonitor, RotaryAxesAreNotOnThePath) {
  const auto m = run([](double c) { return 0.2 * c; }, [](double c) { return 0.4 * c; }, 10'000,
                     500, {0.001, 0.0});
  EXPECT_NEAR(m.path().speed.value, 0.2 * 0.001, 1e-5);
}

}  // namespace
}  // namespace hwinterp::tb
