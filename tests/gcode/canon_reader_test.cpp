// The canonical-command reader: rs274's line format as it really prints it,
// units, planes, what it ignores and counts, and what it refuses.
#include <gtest/gtest.h>

#include "gcode_test_util.h"

namespace hwinterp::gcode {
namespace {

using test::canon;
using test::canon_error;
using test::mentions;

TEST(CanonReader, ReadsRs274sLines) {
  const auto r = canon(
      "    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)\n"
      "    9 N..... STRAIGHT_TRAVERSE(1.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)\n"
      "   10 N..... SET_FEED_RATE(300.0000)\n"
      "   11 N30    STRAIGHT_FEED(5.0000, 2.0000, 3.0000, 4.5000, -1.0000, 2.0000)\n"
      "   12 N..... ARC_FEED(20.0000, 2.0000, 12.5000, 2.0000, -1, 3.0000, 0.0000, 0.0000, "
      "0.0000)\n");
  ASSERT_EQ(r.moves.size(), 3u);
  EXPECT_EQ(r.moves[0].kind, MoveKind::kTraverse);
  EXPECT_EQ(r.moves[0].end, (std::array<double, 6>{1, 2, 3, 0, 0, 0}));
  EXPECT_EQ(r.moves[0].line, 9u);
  EXPECT_EQ(r.moves[0].feed, 0);
  EXPECT_EQ(r.moves[1].kind, MoveKind::kFeed);
  EXPECT_EQ(r.moves[1].end, (std::array<double, 6>{5, 2, 3, 4.5, -1, 2}));
  EXPECT_EQ(r.moves[1].feed, 300);
  EXPECT_EQ(r.moves[1].line, 11u);
  EXPECT_EQ(r.moves[2].kind, MoveKind::kArc);
  EXPECT_EQ(r.moves[2].end, (std::array<double, 6>{20, 2, 3, 0, 0, 0}));
  EXPECT_EQ(r.moves[2].center, (std::array<double, 2>{12.5, 2}));
  EXPECT_EQ(r.moves[2].rotation, -1);
  EXPECT_EQ(r.moves[2].plane, Plane::kXY);
}

TEST(CanonReader, NFieldsAsRs274PrintsThem) {
  // No N word, N10, a five- and a six-digit N (no space left), N with no
  // digits, N1234567, and a canon line number past 99999.
  const auto r = canon(
      "    7 N..... STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "    8 N10    STRAIGHT_TRAVERSE(2.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "    9 N12345 STRAIGHT_TRAVERSE(3.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "   10 N999999STRAIGHT_TRAVERSE(4.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "   11 N      STRAIGHT_TRAVERSE(5.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "   12 N1234567STRAIGHT_TRAVERSE(6.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "123456 N..... STRAIGHT_TRAVERSE(7.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n");
  ASSERT_EQ(r.moves.size(), 7u);
  for (size_t n = 0; n < 7; ++n) EXPECT_EQ(r.moves[n].end[kX], n + 1.0);
  EXPECT_EQ(r.moves[6].line, 123456u);
}

TEST(CanonReader, TheExecutingBannerOnItsOwnLineOrAfterTheLastCommand) {
  const auto r = canon(
      "executing\n"
      "    1 N..... STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "    2 N..... ON_RESET()executing\n");
  EXPECT_EQ(r.moves.size(), 1u);
  EXPECT_EQ(r.stats.ignored_commands.at("executing"), 2u);
  EXPECT_EQ(r.stats.ignored_commands.at("ON_RESET"), 1u);
}

TEST(CanonReader, InchesConvertLengthsAndFeedsKeepTheirUnits) {
  const auto r = canon(
      "    1 N..... SET_FEED_RATE(100.0000)\n"
      "    2 N..... USE_LENGTH_UNITS(CANON_UNITS_INCHES)\n"
      "    3 N..... STRAIGHT_FEED(1.0000, 0.5000, -0.1000, 90.0000, 0.0000, 0.0000)\n"
      "    4 N..... SET_FEED_RATE(10.0000)\n"
      "    5 N..... ARC_FEED(2.0000, 0.5000, 1.5000, 0.5000, 1, -0.1000, 0.0000, 0.0000, "
      "0.0000)\n"
      "    6 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)\n"
      "    7 N..... STRAIGHT_FEED(10.0000, 0.5000, -0.1000, 90.0000, 0.0000, 0.0000)\n");
  ASSERT_EQ(r.moves.size(), 3u);
  EXPECT_EQ(r.moves[0].end, (std::array<double, 6>{25.4, 0.5 * 25.4, -0.1 * 25.4, 90, 0, 0}));
  EXPECT_EQ(r.moves[0].feed, 100);  // given in mm/min, before the switch
  EXPECT_EQ(r.moves[1].center, (std::array<double, 2>{1.5 * 25.4, 0.5 * 25.4}));
  EXPECT_DOUBLE_EQ(r.moves[1].feed, 254);
  EXPECT_EQ(r.moves[2].end[kX], 10);
  EXPECT_DOUBLE_EQ(r.moves[2].feed, 254);
}

TEST(CanonReader, PlanesMapArcsInCanonOrder) {
  const auto r = canon(
      "    1 N..... SELECT_PLANE(CANON_PLANE_XZ)\n"
      "    2 N..... ARC_FEED(3.0000, 10.0000, 3.0000, 15.0000, -1, 2.0000, 0.0000, 0.0000, "
      "0.0000)\n"
      "    3 N..... SELECT_PLANE(CANON_PLANE_YZ)\n"
      "    4 N..... ARC_FEED(6.0000, 3.0000, 4.0000, 3.0000, 2, 10.0000, 1.0000, 2.0000, "
      "3.0000)\n");
  ASSERT_EQ(r.moves.size(), 2u);
  EXPECT_EQ(r.moves[0].plane, Plane::kXZ);
  EXPECT_EQ(r.moves[0].end, (std::array<double, 6>{10, 2, 3, 0, 0, 0}));  // Z=3, X=10, Y=2
  EXPECT_EQ(r.moves[0].center, (std::array<double, 2>{3, 15}));
  EXPECT_EQ(r.moves[1].plane, Plane::kYZ);
  EXPECT_EQ(r.moves[1].end, (std::array<double, 6>{10, 6, 3, 1, 2, 3}));  // Y=6, Z=3, X=10
  EXPECT_EQ(r.moves[1].rotation, 2);
}

TEST(CanonReader, UvwFormsWithUvwAtZero) {
  const auto r = canon(
      "    1 N..... STRAIGHT_FEED(1.0000, 2.0000, 3.0000, 4.0000, 5.0000, 6.0000, 0.0000, "
      "0.0000, 0.0000)\n"
      "    2 N..... ARC_FEED(1.0000, 0.0000, 0.5000, 0.0000, 1, 3.0000, 4.0000, 5.0000, 6.0000, "
      "0.0000, -0.0000, 0.0000)\n");
  ASSERT_EQ(r.moves.size(), 2u);
  EXPECT_EQ(r.moves[0].end, (std::array<double, 6>{1, 2, 3, 4, 5, 6}));
  EXPECT_TRUE(mentions(
      canon_error("    1 N..... STRAIGHT_FEED(1.0000, 2.0000, 3.0000, 4.0000, 5.0000, 6.0000, "
                  "0.0000, 7.0000, 0.0000)\n"),
      {"t.canon:1:", "V axis", "7.0000"}));
}

TEST(CanonReader, OtherCommandsAreCountedByName) {
  const auto r = canon(
      "    1 N..... COMMENT(\"a (comment), with commas\")\n"
      "    2 N..... SET_SPINDLE_MODE(0 0.0000)\n"
      "    3 N..... SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "    4 N..... SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "    5 N..... SET_XY_ROTATION(0.0000)\n"
      "    6 N..... SET_FEED_MODE(0, 0)\n"
      "    7 N..... COMMENT(\"again\")\n"
      "    8 N..... PROGRAM_END()\n"
      "\n");
  EXPECT_TRUE(r.moves.empty());
  const std::map<std::string, uint64_t> expected = {
      {"COMMENT", 2},         {"SET_SPINDLE_MODE", 1}, {"SET_G5X_OFFSET", 1}, {"SET_G92_OFFSET", 1},
      {"SET_XY_ROTATION", 1}, {"SET_FEED_MODE", 1},    {"PROGRAM_END", 1}};
  EXPECT_EQ(r.stats.ignored_commands, expected);
}

TEST(CanonReader, MalformedLines) {
  struct Case {
    const char* line;
    std::vector<std::string> parts;
  };
  const std::string six = "(1.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)";
  const Case cases[] = {
      {"STRAIGHT_FEED(1.0000)", {"no line number"}},
      {"    1 STRAIGHT_FEED(1.0000)", {"no N field"}},
      {"    1 N..... (1.0000)", {"no command name"}},
      {"    1 N..... STRAIGHT_FEED 1.0000", {"no '('"}},
      {"    1 N..... STRAIGHT_FEED(1.0000, 2.0000", {"no ')'"}},
      {"    1 N..... ON_RESET() trailing", {"text after ')'"}},
      {"    1 N..... STRAIGHT_FEED(1.0000, 2.0000, 3.0000)", {"3 arguments", "6 or 9"}},
      {"    1 N..... STRAIGHT_FEED(1.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000, 1.0000)",
       {"7 arguments"}},
      {"    1 N..... ARC_FEED(1.0000, 2.0000, 3.0000, 0.0000, 1, 0.0000)",
       {"6 arguments", "9 or 12"}},
      {"    1 N..... STRAIGHT_FEED(1.0.0, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)", {"'1.0.0'"}},
      {"    1 N..... STRAIGHT_FEED(nan, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)", {"'nan'"}},
      {"    1 N..... STRAIGHT_FEED(-inf, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)", {"'-inf'"}},
      {"    1 N..... STRAIGHT_FEED(1e5, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)", {"'1e5'"}},
      {"    1 N..... STRAIGHT_FEED(, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)", {"''"}},
      {"    1 N..... STRAIGHT_FEED(1000000001.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)",
       {"1e9"}},
      {"    1 N..... ARC_FEED(0.0010, 0.0000, -nan, -nan, -1, 0.0000, 0.0000, 0.0000, 0.0000)",
       {"'-nan'"}},
      {"    1 N..... ARC_FEED(1.0000, 0.0000, 0.5000, 0.0000, 0, 0.0000, 0.0000, 0.0000, 0.0000)",
       {"rotation", "non-zero"}},
      {"    1 N..... ARC_FEED(1.0000, 0.0000, 0.5000, 0.0000, 1.5, 0.0000, 0.0000, 0.0000, 0.0000)",
       {"rotation", "'1.5'"}},
      {"    1 N..... SET_FEED_RATE(-1.0000)", {"negative feed"}},
      {"    1 N..... USE_LENGTH_UNITS(CANON_UNITS_CM)", {"'CANON_UNITS_CM'"}},
      {"    1 N..... SELECT_PLANE(CANON_PLANE_UV)", {"'CANON_PLANE_UV'"}},
      {"garbage", {"no line number", "'garbage'"}},
  };
  for (const auto& c : cases) {
    auto parts = c.parts;
    parts.push_back("t.canon:2:");
    EXPECT_TRUE(
        mentions(canon_error("    0 N..... ON_RESET()\n" + std::string(c.line) + "\n"), parts))
        << c.line;
  }
}

TEST(CanonReader, RefusesWhatWouldMoveOrShiftThePath) {
  struct Case {
    const char* line;
    const char* word;
  };
  const Case cases[] = {
      {"STRAIGHT_PROBE(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)", "STRAIGHT_PROBE"},
      {"RIGID_TAP(0, 0.0000, 0.0000, -1.0000, 1.0000)", "RIGID_TAP"},
      {"NURBS_G5_FEED(...)", "NURBS_G5_FEED"},
      {"SET_FEED_MODE(0, 1)", "mode 0"},
      {"SET_G92_OFFSET(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)", "SET_G92_OFFSET"},
      {"SET_G5X_OFFSET(2, 0.0000, 5.0000, 0.0000, 0.0000, 0.0000, 0.0000)", "SET_G5X_OFFSET"},
      {"SET_XY_ROTATION(30.0000)", "SET_XY_ROTATION"},
  };
  for (const auto& c : cases)
    EXPECT_TRUE(
        mentions(canon_error(std::string("    3 N..... ") + c.line + "\n"), {"t.canon:1:", c.word}))
        << c.line;
}

TEST(CanonReader, AnEmptyStreamHasNoMoves) {
  const auto r = canon("");
  EXPECT_TRUE(r.moves.empty());
  EXPECT_EQ(r.stats.lines, 0u);
}

}  // namespace
}  // namespace hwinterp::gcode
