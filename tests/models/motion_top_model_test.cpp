// motion_top's reference model (models/motion_top_model.h): lines are the
// DDA's moves, arcs PPC rule M's on the plane's axes, the slaved axes'
// Bresenham ends exactly with at most one step per operation, and the
// deviation bound holds on every visited point (exhaustively on small arcs
// and helices in every plane, and on thousands of random commands).
#include "models/motion_top_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

namespace hwinterp::models {
namespace {

int64_t uniform(std::mt19937_64& rng, int64_t lo, int64_t hi) {
  return std::uniform_int_distribution<int64_t>(lo, hi)(rng);
}

MotionCommand line(std::array<int64_t, kMotionMaxAxes> delta) {
  MotionCommand c;
  c.kind = MotionKind::kLine;
  c.delta = delta;
  return c;
}

MotionCommand arc(int plane, std::array<int64_t, 2> center, std::array<int64_t, 2> end, bool ccw,
                  std::array<int64_t, kMotionMaxAxes> slaved = {}) {
  MotionCommand c;
  c.kind = MotionKind::kArc;
  c.plane = plane;
  c.center = center;
  c.end = end;
  c.ccw = ccw;
  c.delta = slaved;
  c.ops = motion_arc_ops(center, end, ccw);
  return c;
}

// The axis of the plane's third direction (the helix axis).
int third_axis(int plane) {
  const auto p = motion_plane_axes(plane);
  return 3 - p[0] - p[1];
}

// Everything the checks below gather over one command.
struct CommandRun {
  uint64_t moves = 0;
  double worst = 0;        // largest deviation seen
  double worst_ratio = 0;  // largest deviation / bound
  double worst_lag = 0;    // largest |S_j|
  bool within = true;
  LatticePoint end;
};

// Runs one command from `start`: every move's op strictly increases (so no
// axis steps twice on one operation), each slaved axis's step count follows
// the closed form, the end is start + displacement, every visited point is
// within the bound.
CommandRun run_checked(const LatticePoint& start, const MotionCommand& c, int axes) {
  CommandRun r;
  MotionMoveStream s(start, c, axes);
  const MotionIdeal ideal(start, c, axes);
  const ErrorBound b = ideal.bound();
  const auto disp = motion_displacement(c);
  // Axes that step one way only: every axis of a line, the slaved axes of
  // an arc (the plane's axes go back and forth).
  std::array<bool, kMotionMaxAxes> one_way{};
  for (int i = 0; i < axes; ++i) one_way[static_cast<size_t>(i)] = true;
  if (c.kind == MotionKind::kArc)
    for (const int a : motion_plane_axes(c.plane)) one_way[static_cast<size_t>(a)] = false;
  std::array<uint64_t, kMotionMaxAxes> taken{};
  uint64_t last_op = 0;
  MotionMove m;
  LatticePoint at = start;
  while (s.next(m)) {
    ++r.moves;
    EXPECT_GT(m.op, last_op);
    last_op = m.op;
    for (int i = 0; i < axes; ++i) {
      const auto a = static_cast<size_t>(i);
      EXPECT_TRUE(m.step[a] >= -1 && m.step[a] <= 1);
      if (m.step[a] != 0 && one_way[a]) {
        EXPECT_EQ(m.step[a], disp[a] < 0 ? -1 : 1) << "axis " << i << " against its delta";
        ++taken[a];
      }
      at[a] += m.step[a];
    }
    EXPECT_EQ(at, m.point);
    if (c.kind == MotionKind::kArc) {
      const auto pl = motion_plane_axes(c.plane);
      for (int j = 0; j < axes; ++j) {
        const auto a = static_cast<size_t>(j);
        if (j == pl[0] || j == pl[1] || c.delta[a] == 0) continue;
        const uint64_t mag = static_cast<uint64_t>(std::llabs(c.delta[a]));
        const auto want = static_cast<uint64_t>((static_cast<unsigned __int128>(c.ops / 2) +
                                                 static_cast<unsigned __int128>(m.op) * mag) /
                                                c.ops);
        EXPECT_EQ(taken[a], want) << "slaved axis " << j << " after op " << m.op;
        r.worst_lag = std::max(r.worst_lag, std::abs(ideal.slaved_lag(m.point, j, m.op)));
      }
    }
    const double e = ideal.error(m.point, m.op);
    r.worst = std::max(r.worst, e);
    r.worst_ratio = std::max(r.worst_ratio, b.value > 0 ? e / b.value : (e > 0 ? 1e9 : 0));
    if (!within_bound(e, b)) r.within = false;
  }
  if (c.kind == MotionKind::kArc) {
    EXPECT_LE(last_op, c.ops);
  }
  for (int i = 0; i < axes; ++i) {
    const auto a = static_cast<size_t>(i);
    if (one_way[a]) {
      EXPECT_EQ(taken[a], static_cast<uint64_t>(std::llabs(disp[a]))) << "axis " << i;
    }
    EXPECT_EQ(at[a], start[a] + disp[a]) << "axis " << i;
  }
  r.end = at;
  return r;
}

TEST(MotionTopModel, LinesAreTheDdaMoveStream) {
  std::mt19937_64 rng(11);
  for (int n = 0; n < 400; ++n) {
    const int axes = n % 2 ? 4 : 3;
    std::array<int64_t, kMotionMaxAxes> d{};
    const int64_t mag = n % 5 == 0 ? 5000 : 60;
    for (int i = 0; i < axes; ++i) d[static_cast<size_t>(i)] = uniform(rng, -mag, mag);
    if (n % 7 == 0) d[1] = 0;
    LatticePoint start(static_cast<size_t>(axes));
    for (auto& v : start) v = uniform(rng, -1000000, 1000000);
    const MotionCommand c = line(d);
    MotionMoveStream s(start, c, axes);
    DdaMoveStream ref(start, std::vector<int64_t>(d.begin(), d.begin() + axes), Preload::kZero);
    MotionMove m;
    DdaMove want;
    while (ref.next(want)) {
      ASSERT_TRUE(s.next(m));
      ASSERT_EQ(m.op, want.iteration);
      for (int i = 0; i < axes; ++i)
        ASSERT_EQ(m.step[static_cast<size_t>(i)], want.step[static_cast<size_t>(i)]);
      ASSERT_EQ(m.point, want.point);
    }
    EXPECT_FALSE(s.next(m));
    EXPECT_EQ(motion_operations(c), dda_iterations(std::vector<int64_t>(d.begin(), d.end())));
    const CommandRun r = run_checked(start, c, axes);
    EXPECT_TRUE(r.within) << "line " << n << " worst " << r.worst;
  }
}

TEST(MotionTopModel, ArcsArePpcArcStreamOnThePlaneAxes) {
  std::mt19937_64 rng(12);
  for (int n = 0; n < 600; ++n) {
    const int plane = n % 3;
    const int axes = 3 + n % 2;
    const int64_t r = n % 4 == 0 ? 300 : 20;
    const std::array<int64_t, 2> cen{uniform(rng, -r, r), uniform(rng, -r, r)};
    const std::array<int64_t, 2> end{uniform(rng, -2 * r, 2 * r), uniform(rng, -2 * r, 2 * r)};
    const bool ccw = n % 5 < 2;
    const MotionCommand c = arc(plane, cen, end, ccw);
    LatticePoint start(static_cast<size_t>(axes));
    for (auto& v : start) v = uniform(rng, -100000, 100000);
    MotionMoveStream s(start, c, axes);
    PpcArcStream ref({cen[0], cen[1]}, {0, 0}, {end[0], end[1]}, ccw);
    const auto pl = motion_plane_axes(plane);
    MotionMove m;
    StepMove want;
    while (ref.next(want)) {
      ASSERT_TRUE(s.next(m));
      ASSERT_EQ(m.op, static_cast<uint64_t>(want.time));
      for (int i = 0; i < axes; ++i) {
        const int w = i == pl[0] ? want.step[0] : i == pl[1] ? want.step[1] : 0;
        ASSERT_EQ(m.step[static_cast<size_t>(i)], w) << "axis " << i;
      }
      ASSERT_EQ(m.point[static_cast<size_t>(pl[0])],
                start[static_cast<size_t>(pl[0])] + want.point[0]);
      ASSERT_EQ(m.point[static_cast<size_t>(pl[1])],
                start[static_cast<size_t>(pl[1])] + want.point[1]);
    }
    EXPECT_FALSE(s.next(m));
    EXPECT_EQ(c.ops, ref.operations());
    EXPECT_EQ(motion_operations(c), ref.operations());
    const CommandRun run = run_checked(start, c, axes);
    EXPECT_TRUE(run.within) << "arc " << n << " worst " << run.worst;
  }
}

TEST(MotionTopModel, PlanesMapToLinuxCncCanonOrder) {
  EXPECT_EQ(motion_plane_axes(0), (std::array<int, 2>{0, 1}));  // G17: X, Y
  EXPECT_EQ(motion_plane_axes(1), (std::array<int, 2>{2, 0}));  // G18: Z, X
  EXPECT_EQ(motion_plane_axes(2), (std::array<int, 2>{1, 2}));  // G19: Y, Z
  // A quarter circle CCW in the ZX plane from the start, centre at engine
  // (x, y) = (-4, 0), i.e. Z - 4: ends at Z - 4, X + 4.
  const MotionCommand c = arc(1, {-4, 0}, {-4, 4}, true);
  const CommandRun r = run_checked({10, 20, 30}, c, 3);
  EXPECT_EQ(r.end, (LatticePoint{14, 20, 26}));
  EXPECT_EQ(motion_displacement(c), (std::array<int64_t, kMotionMaxAxes>{4, 0, -4, 0, 0, 0}));
}

TEST(MotionTopModel, HelixSlavedAxesEndExactlyOneStepPerOperationAtMost) {
  std::mt19937_64 rng(13);
  for (int n = 0; n < 600; ++n) {
    const int plane = n % 3;
    const int axes = 4;
    const int64_t r = n % 3 == 0 ? 200 : 15;
    const std::array<int64_t, 2> cen{uniform(rng, -r, r), uniform(rng, -r, r)};
    const std::array<int64_t, 2> end{uniform(rng, -r, r), uniform(rng, -r, r)};
    const bool ccw = n % 2 == 0;
    const uint64_t ops = motion_arc_ops(cen, end, ccw);
    const auto big = static_cast<int64_t>(ops);
    std::array<int64_t, kMotionMaxAxes> d{};
    const int h = third_axis(plane);
    // The steepest helix (one step every operation), a random one, none.
    d[static_cast<size_t>(h)] = n % 4 == 0 ? (n % 8 ? big : -big) : uniform(rng, -big, big);
    d[3] = n % 5 == 0 ? 0 : uniform(rng, -big, big);
    const MotionCommand c = arc(plane, cen, end, ccw, d);
    LatticePoint start{uniform(rng, -500, 500), uniform(rng, -500, 500), uniform(rng, -500, 500),
                       uniform(rng, -500, 500)};
    const CommandRun run = run_checked(start, c, axes);
    EXPECT_TRUE(run.within) << "helix " << n << " worst " << run.worst;
    EXPECT_LE(run.worst_lag, 0.5 + 1e-12);
    // The plane's moves are still PPC rule M's, op for op.
    MotionMoveStream s(start, c, axes);
    PpcArcStream ref({cen[0], cen[1]}, {0, 0}, {end[0], end[1]}, ccw);
    const auto pl = motion_plane_axes(plane);
    MotionMove m;
    StepMove want;
    while (ref.next(want)) {
      do {
        ASSERT_TRUE(s.next(m));
      } while (m.step[static_cast<size_t>(pl[0])] == 0 && m.step[static_cast<size_t>(pl[1])] == 0);
      ASSERT_EQ(m.op, static_cast<uint64_t>(want.time));
      ASSERT_EQ(m.step[static_cast<size_t>(pl[0])], want.step[0]);
      ASSERT_EQ(m.step[static_cast<size_t>(pl[1])], want.step[1]);
    }
  }
}

TEST(MotionTopModel, SlavedLagReachesOneHalfAndNoMore) {
  // N even: the lag reaches +1/2 (a step half an operation-share early).
  const MotionCommand c = arc(0, {-10, 0}, {-10, 10}, true, {0, 0, 7, 0});
  ASSERT_EQ(c.ops % 2, 0u);
  const CommandRun r = run_checked({0, 0, 0, 0}, c, 4);
  EXPECT_LE(r.worst_lag, 0.5 + 1e-12);
  // delta = N / 2: the first step comes on operation 1 with lag 1/2.
  const auto half = static_cast<int64_t>(c.ops / 2);
  const MotionCommand h = arc(0, {-10, 0}, {-10, 10}, true, {0, 0, half, 0});
  MotionMoveStream s({0, 0, 0, 0}, h, 4);
  MotionMove m;
  ASSERT_TRUE(s.next(m));
  EXPECT_EQ(m.op, 1u);
  EXPECT_EQ(m.step[2], 1);
  EXPECT_DOUBLE_EQ(MotionIdeal({0, 0, 0, 0}, h, 4).slaved_lag(m.point, 2, 1), 0.5);
}

TEST(MotionTopModel, DegenerateArcStepsSlavedAxesOnOperationsWithoutPlaneSteps) {
  // Start one step from the centre, end on the start: a full circle the PPC
  // engine cannot turn (R^2 < 2): the switch and a zero-length line, two
  // operations, no plane step. A slaved delta of 2 steps on both.
  const MotionCommand c = arc(0, {1, 0}, {0, 0}, true, {0, 0, -2, 0});
  ASSERT_EQ(c.ops, 2u);
  MotionMoveStream s({5, 5, 5, 5}, c, 4);
  MotionMove m;
  ASSERT_TRUE(s.next(m));
  EXPECT_EQ(m.op, 1u);
  EXPECT_EQ(m.step, (std::array<int8_t, kMotionMaxAxes>{0, 0, -1, 0, 0, 0}));
  ASSERT_TRUE(s.next(m));
  EXPECT_EQ(m.op, 2u);
  EXPECT_EQ(m.point, (LatticePoint{5, 5, 3, 5}));
  EXPECT_FALSE(s.next(m));
  // An arc with nothing slaved and no plane steps has no moves at all.
  MotionMoveStream none({0, 0, 0}, arc(0, {1, 0}, {0, 0}, true), 3);
  EXPECT_FALSE(none.next(m));
}

// Every lattice start and end within radius 5 of the centre, both
// directions, the planes in turn, with slaved deltas at the extremes
// (+-N on two axes, N - 1, N / 2, 1) and at random: every end exact, every
// visited point within sqrt((1 + |re - rs|)^2 + m / 4).
TEST(MotionTopModel, BoundHoldsOnEverySmallArcAndHelix) {
  std::mt19937_64 rng(14);
  std::vector<std::array<int64_t, 2>> disc;
  for (int64_t x = -5; x <= 5; ++x)
    for (int64_t y = -5; y <= 5; ++y)
      if (x * x + y * y <= 25) disc.push_back({x, y});
  uint64_t commands = 0, points = 0;
  double worst_ratio = 0, helix_ratio = 0;
  int index = 0;
  for (const auto& s : disc) {
    for (const auto& e : disc) {
      for (const bool ccw : {true, false}) {
        // Centre at the origin: centre - start = -s, end - start = e - s.
        const std::array<int64_t, 2> cen{-s[0], -s[1]}, end{e[0] - s[0], e[1] - s[1]};
        const uint64_t ops = motion_arc_ops(cen, end, ccw);
        const auto n = static_cast<int64_t>(ops);
        const int plane = index++ % 3;
        const auto h = static_cast<size_t>(third_axis(plane));
        const int64_t pick[][2] = {{0, 0},
                                   {n, -n},
                                   {-(n - 1), n / 2},
                                   {1, -1},
                                   {uniform(rng, -n, n), uniform(rng, -n, n)}};
        for (const auto& p : pick) {
          std::array<int64_t, kMotionMaxAxes> d{};
          d[h] = p[0];
          d[3] = p[1];
          const MotionCommand c = arc(plane, cen, end, ccw, d);
          const CommandRun r = run_checked({3, -2, 7, 1}, c, 4);
          ASSERT_TRUE(r.within) << "s (" << s[0] << "," << s[1] << ") e (" << e[0] << "," << e[1]
                                << ") " << (ccw ? "ccw" : "cw") << " plane " << plane << " d "
                                << p[0] << "," << p[1] << ": " << r.worst;
          worst_ratio = std::max(worst_ratio, r.worst_ratio);
          if (p[0] != 0 || p[1] != 0) helix_ratio = std::max(helix_ratio, r.worst_ratio);
          ++commands;
          points += r.moves;
        }
      }
    }
  }
  std::printf(
      "[ motion ] %llu small arcs and helices, %llu points, worst deviation / bound %.4f "
      "(helices %.4f)\n",
      static_cast<unsigned long long>(commands), static_cast<unsigned long long>(points),
      worst_ratio, helix_ratio);
  EXPECT_LE(worst_ratio, 1 + 1e-12);
  EXPECT_GT(worst_ratio, 0.9);  // the bound is close to reached (on-circle arcs reach it)
}

// Thousands of random commands, lines and arcs with helices, on 3 and 4
// axes, radii to 3000 steps, one after the other from where the last ended.
TEST(MotionTopModel, RandomCommandStreamEndsExactlyWithinBound) {
  std::mt19937_64 rng(15);
  for (const int axes : {3, 4}) {
    LatticePoint at(static_cast<size_t>(axes), 0);
    double worst_ratio = 0;
    for (int n = 0; n < 2000; ++n) {
      MotionCommand c;
      if (n % 3 == 0) {
        std::array<int64_t, kMotionMaxAxes> d{};
        for (int i = 0; i < axes; ++i) d[static_cast<size_t>(i)] = uniform(rng, -3000, 3000);
        c = line(d);
      } else {
        const int plane = static_cast<int>(uniform(rng, 0, 2));
        const int64_t r = n % 10 == 0 ? 3000 : 100;
        const std::array<int64_t, 2> cen{uniform(rng, -r, r), uniform(rng, -r, r)};
        const int64_t k = n % 4 == 0 ? 3 : r / 3;
        // Ends on or near the circle through the start, or anywhere.
        std::array<int64_t, 2> end{uniform(rng, -2 * r, 2 * r), uniform(rng, -2 * r, 2 * r)};
        if (n % 2 == 0) {
          const double rad = std::hypot(static_cast<double>(cen[0]), static_cast<double>(cen[1]));
          const double a = std::uniform_real_distribution<double>(0, 6.283185307)(rng);
          end = {cen[0] + std::llround(rad * std::cos(a)) + uniform(rng, -k, k) / 8,
                 cen[1] + std::llround(rad * std::sin(a)) + uniform(rng, -k, k) / 8};
        }
        const bool ccw = uniform(rng, 0, 1) == 1;
        const auto ops = static_cast<int64_t>(motion_arc_ops(cen, end, ccw));
        std::array<int64_t, kMotionMaxAxes> d{};
        for (int j = 0; j < axes; ++j) {
          if (j == motion_plane_axes(plane)[0] || j == motion_plane_axes(plane)[1]) continue;
          d[static_cast<size_t>(j)] = uniform(rng, 0, 2) == 0 ? 0 : uniform(rng, -ops, ops);
        }
        c = arc(plane, cen, end, ccw, d);
      }
      const CommandRun r = run_checked(at, c, axes);
      ASSERT_TRUE(r.within) << "command " << n << " on " << axes << " axes: " << r.worst;
      worst_ratio = std::max(worst_ratio, r.worst_ratio);
      at = r.end;
    }
    std::printf("[ motion ] %d axes: 2000 random commands, worst deviation / bound %.4f\n", axes,
                worst_ratio);
  }
}

TEST(MotionTopModel, RejectsMalformedCommands) {
  MotionCommand c = arc(0, {-10, 0}, {-10, 10}, true);
  const auto n = static_cast<int64_t>(c.ops);
  // A slaved axis that would need two steps on one operation.
  c.delta[2] = n + 1;
  EXPECT_THROW(MotionMoveStream({0, 0, 0}, c, 3), std::invalid_argument);
  c.delta[2] = -(n + 1);
  EXPECT_THROW(MotionMoveStream({0, 0, 0}, c, 3), std::invalid_argument);
  c.delta[2] = n;
  EXPECT_NO_THROW(MotionMoveStream({0, 0, 0}, c, 3));
  // ops that is not the PPC arc's count.
  MotionCommand w = c;
  w.ops = c.ops + 1;
  EXPECT_THROW(MotionMoveStream({0, 0, 0}, w, 3), std::invalid_argument);
  // A plane axis with a delta of its own.
  w = c;
  w.delta[0] = 1;
  EXPECT_THROW(MotionMoveStream({0, 0, 0}, w, 3), std::invalid_argument);
  // A delta on an axis the core does not have; axes out of range; a bad plane.
  w = line({1, 2, 3, 4});
  EXPECT_THROW(MotionMoveStream({0, 0, 0}, w, 3), std::invalid_argument);
  EXPECT_THROW(MotionMoveStream({0, 0}, line({1, 2}), 2), std::invalid_argument);
  EXPECT_THROW(MotionMoveStream({0, 0, 0}, line({1, 2}), 4), std::invalid_argument);
  w = c;
  w.plane = 3;
  EXPECT_THROW(MotionMoveStream({0, 0, 0}, w, 3), std::invalid_argument);
  // Coordinates beyond the PPC model's 2^30.
  MotionCommand far;
  far.kind = MotionKind::kArc;
  far.center = {int64_t{1} << 31, 0};
  far.ops = 1;
  EXPECT_THROW(MotionMoveStream({0, 0, 0}, far, 3), std::invalid_argument);
}

TEST(MotionTopModel, LineBoundCountsTheMovingAxes) {
  EXPECT_EQ(MotionIdeal({0, 0, 0, 0}, line({40, 0, 0, 0}), 4).bound().value, 0);
  EXPECT_DOUBLE_EQ(MotionIdeal({0, 0, 0, 0}, line({40, 3, 0, 0}), 4).bound().value, 1);
  EXPECT_DOUBLE_EQ(MotionIdeal({0, 0, 0, 0}, line({40, 1, 1, 1}), 4).bound().value, std::sqrt(3.0));
  // README: (40, 1, 1, 1) lags three minor axes by almost a step at once.
  const CommandRun r = run_checked({0, 0, 0, 0}, line({40, 1, 1, 1}), 4);
  EXPECT_GT(r.worst, 1);
  EXPECT_TRUE(r.within);
}

}  // namespace
}  // namespace hwinterp::models
