// Arcs at the edges of LinuxCNC 2.9's tolerances, each with rs274's verdict
// on this machine: the program is "UNITS F100", "G0 X0 Y0", the arc, "M2".
// Shared by arc_rules_test.cpp (the ngc reader must agree) and
// long/rs274_oracle_test.cpp (rs274 itself must still agree, where it is
// installed).
#pragma once

#include <ostream>

namespace hwinterp::gcode::test {

struct Edge {
  const char* units;  // "G21" or "G20"
  const char* arc;
  bool accepted;  // by rs274
};
inline void PrintTo(const Edge& e, std::ostream* os) {
  *os << e.units << " " << e.arc << (e.accepted ? " (accepted)" : " (refused)");
}

inline const Edge kArcEdges[] = {
    // |r1 - r2| up to 0.0283 mm (2 x 0.01 x sqrt 2) whatever the ratio...
    {"G21", "G2 X20.02828 Y0 I10 J0", true},
    {"G21", "G2 X20.02829 Y0 I10 J0", false},
    {"G21", "G2 X2.002 Y0 I1 J0", true},
    {"G21", "G2 X20.0284 Y0 I10 J0", false},
    // ...above it only within 0.1 % of the radius...
    {"G21", "G2 X200.099 Y0 I100 J0", true},
    {"G21", "G2 X200.1001 Y0 I100 J0", true},
    {"G21", "G2 X200.1002 Y0 I100 J0", false},
    // ...and never above 100 x 0.0283 mm.
    {"G21", "G2 X20002.8 Y0 I10000 J0", true},
    {"G21", "G2 X20002.83 Y0 I10000 J0", false},
    {"G21", "G2 X19997.17 Y0 I10000 J0", false},
    {"G21", "G2 X2002.5 Y0 I1000 J0", false},
    // Inches: 2 x 0.001 x sqrt 2 in.
    {"G20", "G2 X2.002828 Y0 I1 J0", true},
    {"G20", "G2 X2.002829 Y0 I1 J0", false},
    {"G20", "G2 X20.02828 Y0 I10 J0", false},
    // Zero radius: below 0.00127 mm (0.00005 in).
    {"G21", "G2 X0.0026 Y0 I0.0013 J0", true},
    {"G21", "G2 X0 Y0 I0.0013", true},
    {"G21", "G2 X0.002 Y0 I0.001 J0", false},
    {"G21", "G2 X0.001 Y0 I0.0005", false},
    // R: half the chord may exceed |R| by 0.00127 mm (0.00005 in).
    {"G21", "G2 X10 R4.9988", true},
    {"G21", "G2 X10 R-4.9988", true},
    {"G21", "G2 X10 R4.9987", false},
    {"G20", "G2 X10 R4.99996", true},
    {"G20", "G2 X10 R4.99994", false},
    {"G21", "G2 X0 R5", false},
    // P: a whole number of turns within 0.001, at least 1.
    {"G21", "G2 X0 I5 P2.001", true},
    {"G21", "G2 X0 I5 P1.9999", true},
    {"G21", "G2 X0 I5 P2.4", false},
    {"G21", "G2 X0 I5 P0", false},
    {"G21", "G2 X0 I5 P-1", false}};

}  // namespace hwinterp::gcode::test
