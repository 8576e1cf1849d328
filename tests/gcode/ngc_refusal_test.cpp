// The RS274/NGC reader on what it refuses: words outside the subset (with
// the --canon hint), unreadable lines, and what LinuxCNC refuses too. Every
// refusal is a one-line cli::UsageError naming the file, the line and the
// offending text.
#include <gtest/gtest.h>

#include "gcode_test_util.h"

namespace hwinterp::gcode {
namespace {

using test::mentions;
using test::ngc_error;

struct Refused {
  const char* line;  // on line 2, after "G0 X1"
  const char* word;  // what the message must name
};
void PrintTo(const Refused& c, std::ostream* os) { *os << "'" << c.line << "'"; }

class NgcOutsideSubset : public ::testing::TestWithParam<Refused> {};

TEST_P(NgcOutsideSubset, NamesTheWordAndPointsToCanon) {
  const Refused& c = GetParam();
  const std::string msg = ngc_error(std::string("G0 X1\n") + c.line + "\nM2\n");
  EXPECT_TRUE(mentions(msg, {"t.ngc:2: ", "word '" + std::string(c.word) + "'",
                             "changes the path and is not in the supported subset",
                             "--canon (rs274 -g t.ngc out.canon)"}));
}

INSTANTIATE_TEST_SUITE_P(
    Words, NgcOutsideSubset,
    ::testing::Values(
        Refused{"#1=5", "#1=5"}, Refused{"G1 X#1 F100", "X#1"},
        Refused{"#<depth> = 2", "#<DEPTH>=2"}, Refused{"G1 X[1+2] F100", "X[1+2]"},
        Refused{"O100 sub", "O100"}, Refused{"o<probe> call", "O<PROBE>"}, Refused{"G41 D1", "G41"},
        Refused{"G42", "G42"}, Refused{"G41.1 D2", "G41.1"}, Refused{"G43 H1", "G43"},
        Refused{"G92 X0", "G92"}, Refused{"G92.1", "G92.1"}, Refused{"G28", "G28"},
        Refused{"G30", "G30"}, Refused{"G33 Z-1 K1", "G33"}, Refused{"G38.2 Z-1 F10", "G38.2"},
        Refused{"G73 Z-1 R1 Q1", "G73"}, Refused{"G76 P1", "G76"}, Refused{"G81 Z-1 R1", "G81"},
        Refused{"G83 Z-1 R1 Q1", "G83"}, Refused{"G89 Z-1 R1 P1", "G89"}, Refused{"G93", "G93"},
        Refused{"G95", "G95"}, Refused{"G5 X1 Y1 I1 J0 P1 Q0", "G5"}, Refused{"G5.2 X1 Y1", "G5.2"},
        Refused{"G7", "G7"}, Refused{"G8", "G8"}, Refused{"G10 L2 P1 X1", "G10"},
        Refused{"G53 G0 X0", "G53"}, Refused{"G59.1", "G59.1"}, Refused{"G17.1", "G17.1"},
        Refused{"G96 S100", "G96"}, Refused{"G1 U1 F10", "U1"}, Refused{"G1 W1 F10", "W1"},
        Refused{"M60", "M60"}, Refused{"M98", "M98"}, Refused{"M100", "M100"},
        Refused{"M48", "M48"}, Refused{"E1", "E1"}, Refused{"L1", "L1"}, Refused{"H1", "H1"},
        Refused{"D1", "D1"}, Refused{"/G1 X2 F100", "/G1"}, Refused{"G1 @1 ^90 F100", "@1^90"},
        Refused{"G200", "G200"}),
    [](const auto& info) { return test::test_name(info.index, info.param.word); });

struct Garbage {
  const char* line;
  const char* shows;  // what the message must quote
};
void PrintTo(const Garbage& c, std::ostream* os) { *os << "'" << c.line << "'"; }

class NgcGarbage : public ::testing::TestWithParam<Garbage> {};

TEST_P(NgcGarbage, NamesFileLineAndText) {
  const Garbage& c = GetParam();
  const std::string msg = ngc_error(std::string("G0 X1\n") + c.line + "\nM2\n");
  EXPECT_TRUE(mentions(msg, {"t.ngc:2: ", c.shows}));
  EXPECT_EQ(msg.find("--canon"), std::string::npos) << msg;  // not a subset question
}

INSTANTIATE_TEST_SUITE_P(
    Lines, NgcGarbage,
    ::testing::Values(
        Garbage{"G1 X1..2 F100", "'X1..2'"}, Garbage{"G1 X", "letter 'X'"},
        Garbage{"G1 X- F100", "'X-'"}, Garbage{"G1 X--1 F100", "'X--1'"},
        Garbage{"G1 X. F100", "'X.'"}, Garbage{"G1 X1 * F100", "'X1*'"}, Garbage{"1 G1 X2", "'1'"},
        Garbage{"G1 X2 = 3", "'X2=3'"}, Garbage{"G1.55 X2", "'G1.55'"}, Garbage{"G-1 X2", "'G-1'"},
        Garbage{"M3.5", "'M3.5'"}, Garbage{"G1 X2 F100 %", "'F100%'"}, Garbage{"%", "'%'"},
        Garbage{"G1 X2\x01", "\\x01"}, Garbage{"G1 X\xc3\xa9", "\\xc3"},
        Garbage{"G1 X1 (a (b) c)", "inside a comment"}, Garbage{"G1 X1 (open", "without ')'"},
        Garbage{"G0 X1 N5", "'N5'"}, Garbage{"N-5 G0 X1", "'N-5'"}),
    [](const auto& info) { return test::test_name(info.index, info.param.line); });

TEST(NgcRefusal, WhatLinuxCncRefusesOnALine) {
  struct Case {
    const char* program;
    std::vector<std::string> parts;
  };
  const Case cases[] = {
      {"G0 X1\nG0 G1 X2\n", {"t.ngc:2:", "'G0' and 'G1'", "modal group"}},
      {"G17 G18\n", {"t.ngc:1:", "'G17' and 'G18'"}},
      {"G90 G91\n", {"t.ngc:1:", "'G90' and 'G91'"}},
      {"G20 G21\n", {"t.ngc:1:", "'G20' and 'G21'"}},
      {"G54 G55\n", {"t.ngc:1:", "'G54' and 'G55'"}},
      {"M3 M4\n", {"t.ngc:1:", "'M3' and 'M4'"}},
      {"M7 M8\n", {"t.ngc:1:", "'M7' and 'M8'"}},
      {"M2 M30\n", {"t.ngc:1:", "'M2' and 'M30'"}},
      {"G0 X1 X2\n", {"t.ngc:1:", "two X words", "'X1' and 'X2'"}},
      {"G1 X1 F1 F2\n", {"t.ngc:1:", "two F words"}},
      {"G1 X1 F100 I2\n", {"t.ngc:1:", "'I2' without G2 or G3"}},
      {"G0 X1 R2\n", {"t.ngc:1:", "'R2' without G2 or G3"}},
      {"G1 X1 P2 F100\n", {"t.ngc:1:", "'P2' without G2, G3, G4 or G64"}},
      {"G61 Q1\n", {"t.ngc:1:", "'Q1' without G64"}},
      {"G4\n", {"t.ngc:1:", "G4 without P"}},
      {"G4 P1 G2 X2 I1 F100\n", {"t.ngc:1:", "G4 beside 'G2'"}},
      {"G1 X1\n", {"t.ngc:1:", "G1 with a zero feed rate"}},
      {"G1 X1 F0\n", {"t.ngc:1:", "G1 with a zero feed rate"}},
      {"G2 X2 I1\n", {"t.ngc:1:", "arc with a zero feed rate"}},
      {"G1 X1 F-3\n", {"t.ngc:1:", "'F-3'", "negative feed"}},
      {"S-100 M3\n", {"t.ngc:1:", "'S-100'"}},
      {"T1.5 M6\n", {"t.ngc:1:", "'T1.5'"}},
      {"T-1\n", {"t.ngc:1:", "'T-1'"}},
      {"G1 X1 Y1E5 F100\n", {"t.ngc:1:", "'E5'"}},
      {"G1 X1e9 F100\n", {"t.ngc:1:", "'E9'"}},
      {"G1 X1000000001 F100\n", {"t.ngc:1:", "'X1000000001'", "1e9"}},
  };
  for (const auto& c : cases)
    EXPECT_TRUE(mentions(ngc_error(std::string(c.program) + "M2\n"), c.parts)) << c.program;
}

TEST(NgcRefusal, ArcsLinuxCncRefuses) {
  struct Case {
    const char* line;
    std::vector<std::string> parts;
  };
  const Case cases[] = {
      {"G2 X10 F100", {"t.ngc:1:", "without its centre", "R or I/J"}},
      {"G2 X10 I5 R5 F100", {"t.ngc:1:", "R together with I/J"}},
      {"G2 X10 I5 K3 F100", {"t.ngc:1:", "'K3'", "XY plane"}},
      {"G18 G2 X10 I5 J1 F100", {"t.ngc:1:", "'J1'", "XZ plane"}},
      {"G19 G2 Y10 J5 I1 F100", {"t.ngc:1:", "'I1'", "YZ plane"}},
      {"G2 X0 R5 F100", {"t.ngc:1:", "ends where it starts", "'G2 X0 R5 F100'"}},
      {"G2 X10 R0 F100", {"t.ngc:1:", "zero-radius", "'R0'"}},
      {"G2 X10 R4.9987 F100", {"t.ngc:1:", "'R4.9987' too small", "5.0000 mm"}},
      {"G2 X0.002 I0.001 F100", {"t.ngc:1:", "zero-radius", "0.0010 mm"}},
      {"G2 X20.0284 I10 F100", {"t.ngc:1:", "off its circle", "10.0284 mm", "0.0283 mm"}},
      {"G20 G2 X20.0284 I10 F100", {"t.ngc:1:", "off its circle", "in to the end", "0.0028 in"}},
  };
  for (const auto& c : cases)
    EXPECT_TRUE(mentions(ngc_error(std::string(c.line) + "\nM2\n"), c.parts)) << c.line;
}

TEST(NgcRefusal, ErrorsComeInProgramOrderAfterTheMovesBefore) {
  // Streaming: the moves before a bad line are delivered, then the error.
  std::istringstream in("G0 X1\nG0 X2\nG41\nM2\n");
  NgcReader r(in, "p.ngc");
  Move m;
  EXPECT_TRUE(r.next(m));
  EXPECT_TRUE(r.next(m));
  EXPECT_TRUE(mentions(test::error_of([&] { r.next(m); }), {"p.ngc:3:", "'G41'"}));
}

}  // namespace
}  // namespace hwinterp::gcode
