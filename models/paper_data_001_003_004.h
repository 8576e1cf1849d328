// Figures printed in papers 001 (odd-even log interpolation), 003 (inscribed
// chord and PPC) and 004 (fixed ratio and the other fine interpolators),
// transcribed once so the tests and `hwinterp reproduce` compare against the
// same numbers. These are the papers' values, not results of our models.
#pragma once

#include <array>
#include <cstdint>

namespace hwinterp::models::paper {

// ---- 001, Table 1 (D1 = 10 mm, S = 30 deg, C = 5 deg, r = 8 deg, dl = 0.2 mm).
// Columns: point, X, A, PA, ErPA x 1e-4; printed to 4 decimals.
struct LogTableRow {
  int point;
  double x, a, pa, err_e4;
};
inline constexpr std::array<LogTableRow, 20> kLogTable1{{
    {0, 0.0, 0.0, 0.0, 0.0},
    {1, 0.1987, 0.0229, 0.0229, -0.3979},
    {2, 0.3974, 0.0457, 0.0457, -0.0001},
    {3, 0.5961, 0.0685, 0.0685, -0.3926},
    {4, 0.7948, 0.0911, 0.0911, -0.0002},
    {5, 0.9935, 0.1138, 0.1137, -0.3874},
    {6, 1.1922, 0.1363, 0.1363, -0.0003},
    {7, 1.3910, 0.1587, 0.1587, -0.3823},
    {8, 1.5897, 0.1811, 0.1811, -0.0004},
    {9, 1.7885, 0.2034, 0.2033, -0.3773},
    {143, 28.4736, 2.6679, 2.6679, -0.1829},
    {144, 28.6730, 2.6833, 2.6833, -0.0034},
    {145, 28.8724, 2.6986, 2.6986, -0.1813},
    {146, 29.0718, 2.7138, 2.7138, -0.0035},
    {147, 29.2713, 2.7291, 2.7291, -0.1797},
    {148, 29.4707, 2.7443, 2.7443, -0.0035},
    {149, 29.6701, 2.7595, 2.7595, -0.1781},
    {150, 29.8695, 2.7746, 2.7746, -0.0035},
    {151, 30.0689, 2.7897, 2.7897, -0.1765},
    {152, 30.2684, 2.8048, 2.8048, -0.0035},
}};
inline constexpr int kLogPoints02 = 152;
inline constexpr double kLogXLast02 = 30.2684;
inline constexpr double kLogMaxErr02 = 3.9785e-5;      // MaxErPA = MaxErPAo, at point 1
inline constexpr double kLogMaxErrEven02 = 3.5000e-7;  // MaxErPAe, at point 152
inline constexpr int kLogPoints05 = 62;
inline constexpr double kLogXLast05 = 30.8667;
inline constexpr double kLogMaxErr05 = 2.4780e-4;

// ---- 003: PPC line (0,0)->(4,3) and arc (4,0)->(0,4) CCW R = 4 (Figs. 4, 6),
// chord Tables I (r = 1) and II (r = 0.9, printed truncated to 3 decimals).
inline constexpr std::array<std::array<int64_t, 2>, 7> kPpcLine{
    {{1, 0}, {1, 1}, {2, 1}, {2, 2}, {3, 2}, {3, 3}, {4, 3}}};
inline constexpr std::array<std::array<int64_t, 2>, 8> kPpcArc{
    {{3, 0}, {3, 1}, {3, 2}, {3, 3}, {2, 3}, {2, 4}, {1, 4}, {0, 4}}};
inline constexpr std::array<std::array<double, 2>, 5> kChordTable1{
    {{0.8, 0.6}, {1.6, 1.2}, {2.4, 1.8}, {3.2, 2.4}, {4.0, 3.0}}};
inline constexpr std::array<std::array<double, 2>, 7> kChordTable2{{{3.898, 0.894},
                                                                    {3.600, 1.743},
                                                                    {3.119, 2.504},
                                                                    {2.480, 3.138},
                                                                    {1.716, 3.613},
                                                                    {0.864, 3.905},
                                                                    {-0.030, 3.999}}};
// Table III step counts: PPC line, chord line, PPC arc, chord arc.
inline constexpr int kTable3PpcLine = 7, kTable3ChordLine = 5, kTable3PpcArc = 8,
                     kTable3ChordArc = 7;

// ---- 004: the eight test lines (x0, y0, x1, y1), velocity factor 5000,
// PPC's 60 operations on line 1.
inline constexpr std::array<std::array<int64_t, 4>, 8> kRatioLines{{{0, 0, 20, 40},
                                                                    {10, 10, 40, 20},
                                                                    {10, -10, 40, -20},
                                                                    {-10, 10, -40, 20},
                                                                    {-10, -10, -40, -40},
                                                                    {-10, -5, 30, 20},
                                                                    {7, -2, -32, -38},
                                                                    {-10, 20, 30, 20}}};
inline constexpr double kRatioVelocity = 5000;
inline constexpr int kPpcOperationsLine1 = 60;

}  // namespace hwinterp::models::paper
