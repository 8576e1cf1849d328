// Fixed-ratio (velocity-synthesis) line generator of paper
// 004_dc68f1177cad466f.txt: one computation per line sets, per axis, a pulse
// generator of fixed frequency v_i = v |d_i| (v: the common velocity factor,
// 5000 in the paper) and a pulse count |d_i|. Both generators start together;
// an axis steps on the mid-period edge of each pulse (Eqs. 9/10: position =
// round(v_i t) with 50 % duty), so axis i takes its k-th step at
//     t_ik = (k - 1/2) / v_i.
// The visited lattice points are the axis positions with the pulses merged in
// time order; pulses of both axes at the same instant make one diagonal move.
//
// Two realisations:
//  - exact frequencies (the paper's analysis): times compared exactly in
//    integers; error <= (|dx| + |dy|) / (2 L) <= sqrt(2)/2; completion in
//    max(|dx|, |dy|) ticks (tick = the shortest pulse period of one axis).
//  - integer clock dividers: a generator clocked at f_clk toggles every
//    H_i = round(f_clk / (2 v_i)) clocks (period 2 H_i); H_i != f_clk/(2 v_i)
//    changes the rate ratio, the axes drift apart and the error grows with the
//    length of the line (3.13 steps on line 1 at 1 MHz). Its bound, stated at
//    its own clock, is fixed_ratio_divider_bound().
#pragma once

#include <array>
#include <cstdint>

#include "models/step_path.h"

namespace hwinterp::models {

// Exact frequencies. One operation (the per-line computation).
StepPath fixed_ratio_line(const LatticePoint& start, const LatticePoint& end);

// Bound of the exact-frequency generator: (|dx| + |dy|) / (2 L), 0 for
// axis-parallel lines (one generator: always on the line).
double fixed_ratio_error_bound(const LatticePoint& start, const LatticePoint& end);

struct DividerPlan {
  double velocity = 0;                   // common factor v (1/s)
  double clock_hz = 0;                   // f_clk
  std::array<int64_t, 2> half_period{};  // H_i in clocks (0 for an idle axis)
  std::array<double, 2> frequency_hz{};  // realised f_clk / (2 H_i)
  int64_t completion_clocks = 0;         // end of the last pulse period of the slower axis
  double tick_clocks = 0;  // shortest pulse period of one axis (paper 004's tick)
};

// Divider settings for a line; throws std::invalid_argument when v or f_clk is
// not positive, or an axis frequency v |d_i| exceeds f_clk (H_i would be 0).
DividerPlan fixed_ratio_divider_plan(const LatticePoint& start, const LatticePoint& end,
                                     double velocity, double clock_hz);

// Integer-divider generator; move times and `ticks` are in clock cycles.
StepPath fixed_ratio_divider_line(const LatticePoint& start, const LatticePoint& end,
                                  double velocity, double clock_hz);

// Bound on the divider generator's normal error at its own clock. With
// r_i = 1/(2 H_i) steps per clock, an axis still stepping is at
// floor(r_i t + 1/2) = r_i t + e_i, e_i in (-1/2, 1/2], so a point's deviation
// x|dy| - y|dx| is t (r_x |dy| - r_y |dx|) + e_x |dy| - e_y |dx|. That holds
// until the first axis takes its last step at t1 = min_i (2|d_i| - 1) H_i;
// afterwards only the other axis moves, towards the line's end, and the error
// shrinks. Hence
//     error <= [ (|dx| + |dy|) / 2 + t1 |r_x |dy| - r_y |dx|| ] / L.
// With exact frequencies the drift term is 0 and this is the bound above.
double fixed_ratio_divider_bound(const LatticePoint& start, const LatticePoint& end,
                                 double velocity, double clock_hz);

}  // namespace hwinterp::models
