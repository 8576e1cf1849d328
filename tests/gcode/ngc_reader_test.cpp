// The RS274/NGC reader on what it accepts: each word, modal motion, the
// distance and unit modes, comments, '%' and the program's end.
#include <gtest/gtest.h>

#include "gcode_test_util.h"

namespace hwinterp::gcode {
namespace {

using test::mentions;
using test::ngc;
using test::ngc_error;

TEST(NgcReader, OneMoveOfEachKind) {
  const auto r = ngc("G0 X1 Y2 Z3\nG1 X4 F300\nG2 X6 Y2 I1 J0\nM2\n");
  ASSERT_EQ(r.moves.size(), 3u);
  EXPECT_EQ(r.moves[0].kind, MoveKind::kTraverse);
  EXPECT_EQ(r.moves[0].end, (std::array<double, 6>{1, 2, 3, 0, 0, 0}));
  EXPECT_EQ(r.moves[0].line, 1u);
  EXPECT_EQ(r.moves[1].kind, MoveKind::kFeed);
  EXPECT_EQ(r.moves[1].end, (std::array<double, 6>{4, 2, 3, 0, 0, 0}));
  EXPECT_EQ(r.moves[1].feed, 300);
  EXPECT_EQ(r.moves[2].kind, MoveKind::kArc);
  EXPECT_EQ(r.moves[2].end, (std::array<double, 6>{6, 2, 3, 0, 0, 0}));
  EXPECT_EQ(r.moves[2].center, (std::array<double, 2>{5, 2}));
  EXPECT_EQ(r.moves[2].rotation, -1);
  EXPECT_EQ(r.moves[2].plane, Plane::kXY);
  EXPECT_EQ(r.moves[2].line, 3u);
  EXPECT_EQ(r.stats.traverses, 1u);
  EXPECT_EQ(r.stats.feeds, 1u);
  EXPECT_EQ(r.stats.arcs, 1u);
  EXPECT_EQ(r.stats.lines, 4u);
}

TEST(NgcReader, SeveralWordsOnALineInAnyOrder) {
  const auto r = ngc("N10 G1 X1 Y2 F300\nN20 Y5 F250 X3 G1\nM2\n");
  ASSERT_EQ(r.moves.size(), 2u);
  EXPECT_EQ(r.moves[1].end[kX], 3);
  EXPECT_EQ(r.moves[1].end[kY], 5);
  EXPECT_EQ(r.moves[1].feed, 250);
  EXPECT_EQ(r.stats.words.at("N"), 2u);
}

TEST(NgcReader, StartsWhereRs274Starts) {
  // Every axis at 0, absolute, XY plane, incremental centres, mm.
  const auto r = ngc("G1 Y1 F100\nG2 X1 Y0 I0 J-1\nM2\n");
  ASSERT_EQ(r.moves.size(), 2u);
  EXPECT_EQ(r.moves[0].end, (std::array<double, 6>{0, 1, 0, 0, 0, 0}));
  EXPECT_EQ(r.moves[1].center, (std::array<double, 2>{0, 0}));
  EXPECT_EQ(r.moves[1].plane, Plane::kXY);
  // No motion mode yet: axis words alone are refused, as rs274 does.
  EXPECT_TRUE(mentions(ngc_error("X1\nM2\n"), {"t.ngc:1:", "without a motion mode"}));
}

TEST(NgcReader, AxisWordsAloneRepeatTheMotionMode) {
  const auto r = ngc("G1 X1 F100\nY2\nG0 Z3\nX4\nM2\n");
  ASSERT_EQ(r.moves.size(), 4u);
  EXPECT_EQ(r.moves[1].kind, MoveKind::kFeed);
  EXPECT_EQ(r.moves[1].end, (std::array<double, 6>{1, 2, 0, 0, 0, 0}));
  EXPECT_EQ(r.moves[3].kind, MoveKind::kTraverse);
  EXPECT_EQ(r.moves[3].end, (std::array<double, 6>{4, 2, 3, 0, 0, 0}));
}

TEST(NgcReader, ArcModeRepeatsWithAxisOrCentreWordsOnly) {
  const auto r = ngc("G3 X10 I5 F100\nX0 I-5\nI5\nM2\n");
  ASSERT_EQ(r.moves.size(), 3u);
  for (const auto& m : r.moves) EXPECT_EQ(m.kind, MoveKind::kArc);
  EXPECT_EQ(r.moves[1].center, (std::array<double, 2>{5, 0}));
  EXPECT_EQ(r.moves[2].end[kX], 0);  // a full circle
  EXPECT_EQ(r.moves[2].center, (std::array<double, 2>{5, 0}));
  // R alone is not enough (LinuxCNC: "R word with no g code that uses it").
  EXPECT_TRUE(mentions(ngc_error("G3 X10 I5 F100\nR5\nM2\n"), {"t.ngc:2:", "'R5'"}));
}

TEST(NgcReader, AMotionWordAloneIsAMoveToWhereTheToolIs) {
  const auto r = ngc("G0 X1\nG1 F100\nG0\nM2\n");
  ASSERT_EQ(r.moves.size(), 3u);
  EXPECT_EQ(r.moves[1].kind, MoveKind::kFeed);
  EXPECT_EQ(r.moves[1].end[kX], 1);
  EXPECT_EQ(r.moves[2].kind, MoveKind::kTraverse);
}

TEST(NgcReader, G80EndsTheMotionMode) {
  const auto r = ngc("G1 X1 F100\nG80\nG0 X2\nM2\n");
  EXPECT_EQ(r.moves.size(), 2u);
  EXPECT_EQ(r.stats.words.at("G80"), 1u);
  EXPECT_TRUE(mentions(ngc_error("G1 X1 F100\nG80\nX2\nM2\n"), {"t.ngc:3:", "motion mode"}));
  EXPECT_TRUE(mentions(ngc_error("G80 X2\nM2\n"), {"t.ngc:1:", "G80"}));
}

TEST(NgcReader, AG80BesideAMotionWordIsIgnored) {
  const auto r = ngc("G0 X1 G80 Y2\nG80 G1 X3 F100\nX4\nM2\n");
  ASSERT_EQ(r.moves.size(), 3u);
  EXPECT_EQ(r.moves[0].kind, MoveKind::kTraverse);
  EXPECT_EQ(r.moves[2].kind, MoveKind::kFeed);
  EXPECT_EQ(r.stats.words.at("G80"), 2u);
}

TEST(NgcReader, G94SetsTheFeedToZeroAsLinuxCncDoes) {
  const auto r = ngc("G1 X1 F50\nG94 F200 X2\nM2\n");
  ASSERT_EQ(r.moves.size(), 2u);
  EXPECT_EQ(r.moves[1].feed, 200);
  EXPECT_TRUE(mentions(ngc_error("G1 X1 F50\nG94\nX2\nM2\n"), {"t.ngc:3:", "zero feed"}));
}

TEST(NgcReader, G91MovesEveryAxisByItsWord) {
  const auto r = ngc("G0 X1 Y1 Z1 A10\nG91 G1 X1 Y-2 Z0.5 A5 B1 C-1 F100\nX1\nG90 X0\nM2\n");
  ASSERT_EQ(r.moves.size(), 4u);
  EXPECT_EQ(r.moves[1].end, (std::array<double, 6>{2, -1, 1.5, 15, 1, -1}));
  EXPECT_EQ(r.moves[2].end, (std::array<double, 6>{3, -1, 1.5, 15, 1, -1}));
  EXPECT_EQ(r.moves[3].end, (std::array<double, 6>{0, -1, 1.5, 15, 1, -1}));
}

TEST(NgcReader, G91_1CentresAreRelativeAndDefaultToZero) {
  const auto r = ngc("G0 X2 Y3\nG91.1 G2 X6 Y3 I2 F100\nG3 X6 Y7 J2\nM2\n");
  ASSERT_EQ(r.moves.size(), 3u);
  EXPECT_EQ(r.moves[1].center, (std::array<double, 2>{4, 3}));
  EXPECT_EQ(r.moves[2].center, (std::array<double, 2>{6, 5}));
}

TEST(NgcReader, G90_1CentresAreAbsoluteAndNeedBothWords) {
  const auto r = ngc("G0 X2 Y3\nG90.1 G2 X6 Y3 I4 J3 F100\nG91 G3 X-4 Y0 I4 J3\nM2\n");
  ASSERT_EQ(r.moves.size(), 3u);
  EXPECT_EQ(r.moves[1].center, (std::array<double, 2>{4, 3}));
  EXPECT_EQ(r.moves[2].end[kX], 2);  // G91 axis words, G90.1 centre
  EXPECT_EQ(r.moves[2].center, (std::array<double, 2>{4, 3}));
  EXPECT_TRUE(mentions(ngc_error("G90.1 G2 X2 I1 F100\nM2\n"), {"t.ngc:1:", "G90.1", "I and J"}));
}

TEST(NgcReader, G20ConvertsLengthsAndFeedsAt25_4Exactly) {
  const auto r = ngc("G20\nG1 X1 Y-0.5 Z0.1 A90 F10\nG2 X3 Y-0.5 I1 J0\nM2\n");
  ASSERT_EQ(r.moves.size(), 2u);
  EXPECT_EQ(r.moves[0].end, (std::array<double, 6>{25.4, -12.7, 0.1 * 25.4, 90, 0, 0}));
  EXPECT_DOUBLE_EQ(r.moves[0].feed, 254);
  EXPECT_EQ(r.moves[1].end[kX], 3 * 25.4);
  EXPECT_EQ(r.moves[1].center, (std::array<double, 2>{2 * 25.4, -0.5 * 25.4}));
}

TEST(NgcReader, AnFBeforeG20OnItsLineIsInTheUnitsBefore) {
  // LinuxCNC's order of execution: F, then G20/G21, then the motion.
  const auto r = ngc("G20 F100 G1 X0.5\nF10 X1\nG21 X30\nM2\n");
  ASSERT_EQ(r.moves.size(), 3u);
  EXPECT_EQ(r.moves[0].feed, 100);  // mm/min: G21 was in force when F ran
  EXPECT_EQ(r.moves[0].end[kX], 12.7);
  EXPECT_DOUBLE_EQ(r.moves[1].feed, 254);  // in/min
  EXPECT_DOUBLE_EQ(r.moves[2].feed, 254);  // a unit change keeps the feed
  EXPECT_EQ(r.moves[2].end[kX], 30);
}

TEST(NgcReader, AUnitChangeKeepsThePosition) {
  const auto r = ngc("G0 X25.4 Y10\nG20 G0 Z1\nG21 G0 Z2\nM2\n");
  ASSERT_EQ(r.moves.size(), 3u);
  EXPECT_DOUBLE_EQ(r.moves[1].end[kX], 25.4);
  EXPECT_DOUBLE_EQ(r.moves[1].end[kY], 10);
  EXPECT_DOUBLE_EQ(r.moves[2].end[kY], 10);
}

TEST(NgcReader, HelixMovesTheThirdAxisAndRotariesToTheirEnds) {
  const auto r = ngc("G2 X0 Y0 Z-3 A90 C5 I5 J0 F100\nM2\n");
  ASSERT_EQ(r.moves.size(), 1u);
  EXPECT_EQ(r.moves[0].end, (std::array<double, 6>{0, 0, -3, 90, 0, 5}));
}

TEST(NgcReader, PlanesGiveTheirCentresInCanonOrder) {
  const auto r =
      ngc("G0 X10 Y1 Z2\nG18 G2 X30 Z2 I10 K0 F100\nG19 G0 X0 Y0 Z0\nG3 Y0 Z10 J0 K5\nM2\n");
  ASSERT_EQ(r.moves.size(), 4u);
  EXPECT_EQ(r.moves[1].plane, Plane::kXZ);
  EXPECT_EQ(r.moves[1].center, (std::array<double, 2>{2, 20}));  // (Z, X)
  EXPECT_EQ(r.moves[3].plane, Plane::kYZ);
  EXPECT_EQ(r.moves[3].center, (std::array<double, 2>{0, 5}));  // (Y, Z)
  EXPECT_EQ(r.moves[3].rotation, 1);
}

TEST(NgcReader, EveryNonPathWordIsCounted) {
  const auto r =
      ngc("%\n(words) ; and more\n; alone\nN1 G40 G49 G54 G80 G94 T1 M6\nS100 M3 M8\nM4 M7\nM5 M9\n"
          "G64 P0.01 Q0.005\nG61\nG61.1\nG4 P1\nG55\nG56\nG57\nG58\nG59\nM0\nM1\nF100\nM30\n");
  EXPECT_TRUE(r.moves.empty());
  const std::map<std::string, uint64_t> expected = {
      {"%", 1},     {"comment", 3}, {"N", 1},   {"G40", 1}, {"G49", 1}, {"G54", 1}, {"G80", 1},
      {"G94", 1},   {"T", 1},       {"M6", 1},  {"S", 1},   {"M3", 1},  {"M8", 1},  {"M4", 1},
      {"M7", 1},    {"M5", 1},      {"M9", 1},  {"G64", 1}, {"P", 2},   {"Q", 1},   {"G61", 1},
      {"G61.1", 1}, {"G4", 1},      {"G55", 1}, {"G56", 1}, {"G57", 1}, {"G58", 1}, {"G59", 1},
      {"M0", 1},    {"M1", 1},      {"F", 1},   {"M30", 1}};
  EXPECT_EQ(r.stats.words, expected);
}

TEST(NgcReader, CaseSpacesAndCrlfAreLinuxCncs) {
  const auto r = ngc("g 1 x 1 . 5 y-.5 z+2 f 1 0 0\r\n\tG1\tX1 2\r\nM2\r\n");
  ASSERT_EQ(r.moves.size(), 2u);
  EXPECT_EQ(r.moves[0].end, (std::array<double, 6>{1.5, -0.5, 2, 0, 0, 0}));
  EXPECT_EQ(r.moves[0].feed, 100);
  EXPECT_EQ(r.moves[1].end[kX], 12);  // spaces are removed inside numbers too
}

TEST(NgcReader, CommentsOfBothKinds) {
  const auto r = ngc("G0 X1 (to x1) Y2 ; the rest (is a comment\n(only a comment)\nM2\n");
  ASSERT_EQ(r.moves.size(), 1u);
  EXPECT_EQ(r.moves[0].end[kY], 2);
  EXPECT_EQ(r.stats.words.at("comment"), 3u);
}

TEST(NgcReader, PercentLinesOpenAndCloseTheProgram) {
  const auto r = ngc("\n  %  \nG0 X1\n%\nthis is not read ***\nG0 X5\n");
  ASSERT_EQ(r.moves.size(), 1u);
  EXPECT_EQ(r.stats.words.at("%"), 2u);
  EXPECT_EQ(r.stats.lines_after_end, 2u);
  EXPECT_EQ(r.stats.lines, 6u);
}

TEST(NgcReader, M2AndM30EndTheProgram) {
  for (const char* end : {"M2", "M30", "G0 X3 M2"}) {
    const auto r = ngc(std::string("G0 X1\n") + end + "\nG0 X5\n(not read)\n");
    EXPECT_EQ(r.moves.back().end[kX], std::string(end).size() > 3 ? 3 : 1) << end;
    EXPECT_EQ(r.stats.lines_after_end, 2u) << end;
  }
}

TEST(NgcReader, AProgramMustEnd) {
  EXPECT_TRUE(mentions(ngc_error("G0 X1\nG0 X2\n"), {"t.ngc:2:", "M2, M30"}));
  EXPECT_TRUE(mentions(ngc_error("%\nG0 X1\nM5\n"), {"t.ngc:3:", "closing '%'"}));
  EXPECT_TRUE(mentions(ngc_error(""), {"t.ngc:0:", "M2"}));
}

TEST(NgcReader, LinesUpTo252Characters) {
  const std::string ok = "G0 X1 (" + std::string(252 - 8, 'a') + ")";
  ASSERT_EQ(ok.size(), 252u);
  EXPECT_EQ(ngc(ok + "\nM2\n").moves.size(), 1u);
  EXPECT_TRUE(mentions(ngc_error("M3\n" + ok + "a\nM2\n"), {"t.ngc:2:", "252"}));
  // Lines after the end are not read, whatever their length.
  EXPECT_EQ(ngc("M2\n" + std::string(100000, 'x') + "\n").stats.lines_after_end, 1u);
}

TEST(NgcReader, PTurnsAndTheirRounding) {
  const auto r = ngc("G2 I5 P2 F100\nG3 I5 P3.0004\nM2\n");
  ASSERT_EQ(r.moves.size(), 2u);
  EXPECT_EQ(r.moves[0].rotation, -2);
  EXPECT_EQ(r.moves[1].rotation, 3);
  EXPECT_TRUE(mentions(ngc_error("G2 I5 P1.5 F100\nM2\n"), {"t.ngc:1:", "'P1.5'"}));
  EXPECT_TRUE(mentions(ngc_error("G2 I5 P0 F100\nM2\n"), {"t.ngc:1:", "'P0'"}));
}

TEST(NgcReader, FullCircleWithCentreWords) {
  const auto r = ngc("G0 X10\nG3 X10 Y0 I-10 J0 F100\nG2 J10\nM2\n");
  ASSERT_EQ(r.moves.size(), 3u);
  EXPECT_EQ(r.moves[1].end[kX], 10);
  EXPECT_EQ(r.moves[1].center, (std::array<double, 2>{0, 0}));
  EXPECT_EQ(r.moves[1].rotation, 1);
  EXPECT_EQ(r.moves[2].center, (std::array<double, 2>{10, 10}));
}

TEST(NgcReader, RadiusArcsPickTheShorterOrTheLongerSide) {
  // From (10, 0) to (0, 10) with radius 10: the centre is (0, 0) or (10, 10).
  const auto r =
      ngc("G0 X10\nG2 X0 Y10 R10 F100\nG3 X10 Y0 R10\nG2 X0 Y10 R-10\nG3 X10 Y0 R-10\nM2\n");
  ASSERT_EQ(r.moves.size(), 5u);
  const auto near = [](const Move& m, double x, double y) {
    return std::abs(m.center[0] - x) < 1e-12 && std::abs(m.center[1] - y) < 1e-12;
  };
  EXPECT_TRUE(near(r.moves[1], 10, 10));  // G2 R>0: shorter, clockwise
  EXPECT_TRUE(near(r.moves[2], 10, 10));  // G3 R>0 back: shorter, counter-clockwise
  EXPECT_TRUE(near(r.moves[3], 0, 0));    // G2 R<0: the longer way round
  EXPECT_TRUE(near(r.moves[4], 0, 0));
  EXPECT_EQ(r.moves[3].rotation, -1);
  EXPECT_EQ(r.moves[4].rotation, 1);
}

// M0 and M1 stop the machine after their line's move: the next move is
// marked stop_before (the feed profile plans an exact stop there), as rs274
// prints PROGRAM_STOP / OPTIONAL_PROGRAM_STOP between the two; the canon
// reader marks the same moves.
TEST(ProgramStops, MarkTheMoveAfterThemInBothReaders) {
  const std::string program = "G21 G90\nG1 X1 F600\nM0\nG1 X2\nG1 X3 M1\nG1 Y1\nM2\n";
  const std::string rs274 =
      "    1 N..... SET_FEED_RATE(600.0000)\n"
      "    2 N..... STRAIGHT_FEED(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "    3 N..... PROGRAM_STOP()\n"
      "    4 N..... STRAIGHT_FEED(2.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "    5 N..... STRAIGHT_FEED(3.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "    6 N..... OPTIONAL_PROGRAM_STOP()\n"
      "    7 N..... STRAIGHT_FEED(3.0000, 1.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "    8 N..... PROGRAM_END()\n";
  for (const auto& r : {ngc(program), test::canon(rs274)}) {
    ASSERT_EQ(r.moves.size(), 4u);
    EXPECT_FALSE(r.moves[0].stop_before);
    EXPECT_TRUE(r.moves[1].stop_before);
    EXPECT_FALSE(r.moves[2].stop_before);
    EXPECT_TRUE(r.moves[3].stop_before);
  }
}

}  // namespace
}  // namespace hwinterp::gcode
