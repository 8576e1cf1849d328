// The committed test programs (tests/data/gcode/*.ngc) against LinuxCNC's own
// interpreter: our ngc reader's moves equal the canon reader's moves of the
// .canon file rs274 wrote for the program (regenerated and compared by the
// `long` test rs274_oracle_test.cpp where rs274 is installed).
#include <gtest/gtest.h>

#include <dirent.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "gcode_test_util.h"
#include "tb/gcode/program_file.h"

namespace hwinterp::gcode {
namespace {

struct Program {
  const char* name;
  uint64_t moves, arcs;
  bool inch;  // rs274 printed (some of) it in inches
};

void PrintTo(const Program& p, std::ostream* os) { *os << p.name << ".ngc"; }

// Every committed program with its move counts (so that a changed program or
// reader shows up here too).
const Program kPrograms[] = {
    {"arcs", 35, 26, false},  {"corners", 54, 4, false}, {"engraving", 380, 252, false},
    {"helix", 23, 17, false}, {"inch", 12, 6, true},     {"incremental", 17, 7, false},
    {"modal", 16, 4, true},   {"words", 12, 1, false},
};

std::string path(const std::string& name, const char* ext) {
  return std::string(HWINTERP_GCODE_DATA) + "/" + name + ext;
}

std::vector<Move> all(MoveSource& s) {
  std::vector<Move> out;
  Move m;
  while (s.next(m)) out.push_back(m);
  return out;
}

class Rs274Program : public ::testing::TestWithParam<Program> {};

TEST_P(Rs274Program, NgcReaderMatchesRs274sCanon) {
  const Program& p = GetParam();
  const auto ngc = open_ngc(path(p.name, ".ngc"));
  const auto canon = open_canon(path(p.name, ".canon"));
  const std::vector<Move> a = all(*ngc), b = all(*canon);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.size(), p.moves);
  EXPECT_EQ(ngc->stats().arcs, p.arcs);
  EXPECT_EQ(ngc->stats().traverses, canon->stats().traverses);
  EXPECT_EQ(ngc->stats().feeds, canon->stats().feeds);
  EXPECT_EQ(ngc->stats().arcs, canon->stats().arcs);
  // rs274 prints 4 decimals, in inches where the program was: half a unit
  // of the last digit, converted.
  const double tol = 0.00005 * (p.inch ? kMmPerInch : 1.0) + 1e-9;
  for (size_t n = 0; n < a.size(); ++n) {
    const Move& x = a[n];
    const Move& y = b[n];
    SCOPED_TRACE(std::string(p.name) + ".ngc:" + std::to_string(x.line) +
                 " / .canon:" + std::to_string(y.line));
    ASSERT_EQ(x.kind, y.kind);
    for (int i = 0; i < kAxes; ++i) EXPECT_NEAR(x.end[i], y.end[i], tol) << "axis " << i;
    EXPECT_NEAR(x.feed, y.feed, tol);
    EXPECT_EQ(x.plane, y.plane);
    EXPECT_EQ(x.stop_before, y.stop_before);
    if (x.kind == MoveKind::kArc) {
      EXPECT_NEAR(x.center[0], y.center[0], tol);
      EXPECT_NEAR(x.center[1], y.center[1], tol);
      EXPECT_EQ(x.rotation, y.rotation);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Data, Rs274Program, ::testing::ValuesIn(kPrograms),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Rs274Programs, EveryCommittedProgramHasItsCanonAndIsListed) {
  std::set<std::string> listed;
  for (const auto& p : kPrograms) listed.insert(p.name);
  std::set<std::string> ngc, canon;
  DIR* d = opendir(HWINTERP_GCODE_DATA);
  ASSERT_NE(d, nullptr);
  for (dirent* e; (e = readdir(d));) {
    const std::string f = e->d_name;
    const auto dot = f.rfind('.');
    if (dot == std::string::npos) continue;
    if (f.substr(dot) == ".ngc") ngc.insert(f.substr(0, dot));
    if (f.substr(dot) == ".canon") canon.insert(f.substr(0, dot));
  }
  closedir(d);
  EXPECT_EQ(ngc, listed);
  EXPECT_EQ(canon, listed);
}

TEST(Rs274Programs, TheEngravingIsWhatItsGeneratorWrites) {
  // A few hundred short arcs with IJK, G1 segments, F words, G0 between
  // strokes and Z plunges, within +-100 mm.
  const auto s = open_ngc(path("engraving", ".ngc"));
  const auto moves = all(*s);
  uint64_t plunges = 0;
  double lo = 0, hi = 0;
  for (const auto& m : moves) {
    for (int i = kX; i <= kZ; ++i) lo = std::min(lo, m.end[i]), hi = std::max(hi, m.end[i]);
    if (m.kind == MoveKind::kFeed && m.end[kZ] < 0 && m.feed == 150) ++plunges;
  }
  EXPECT_GE(s->stats().arcs, 200u);
  EXPECT_GE(s->stats().feeds, 50u);
  EXPECT_GE(s->stats().traverses, 50u);
  EXPECT_GE(plunges, 30u);
  EXPECT_GE(lo, -100);
  EXPECT_LE(hi, 100);
}

}  // namespace
}  // namespace hwinterp::gcode
