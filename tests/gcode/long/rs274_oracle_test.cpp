// LinuxCNC's interpreter itself as the oracle, where `rs274` is on PATH
// (linuxcnc-uspace; not in CI: label `long`, skipped with a message when
// rs274 is missing):
//  - every committed tests/data/gcode/*.ngc, run through `rs274 -g` into a
//    temporary directory, gives exactly the committed .canon file;
//  - every arc edge of arc_edges.h gets from rs274 the verdict the table
//    records (and the ngc reader is checked against the table by
//    arc_rules_test.cpp).
#include <dirent.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "../arc_edges.h"

namespace hwinterp::gcode {
namespace {

bool rs274_on_path() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::istringstream dirs(path);
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && access((dir + "/rs274").c_str(), X_OK) == 0) return true;
  return false;
}

std::string slurp(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

class Rs274 : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!rs274_on_path())
      GTEST_SKIP() << "rs274 (LinuxCNC) is not on PATH: nothing to compare with";
    const char* tmp = std::getenv("TMPDIR");
    std::string templ = std::string(tmp != nullptr ? tmp : "/tmp") + "/hwinterp_rs274_XXXXXX";
    ASSERT_NE(mkdtemp(templ.data()), nullptr);
    dir_ = templ;
  }
  void TearDown() override {
    if (!dir_.empty()) (void)std::system(("rm -rf '" + dir_ + "'").c_str());
  }
  // Runs `rs274 -g in out`; its exit status.
  int run(const std::string& in, const std::string& out) const {
    const std::string cmd =
        "rs274 -g '" + in + "' '" + out + "' </dev/null >'" + dir_ + "/log' 2>&1";
    return std::system(cmd.c_str());
  }
  std::string dir_;
};

TEST_F(Rs274, RegeneratesEveryCommittedCanonFile) {
  DIR* d = opendir(HWINTERP_GCODE_DATA);
  ASSERT_NE(d, nullptr);
  int programs = 0;
  for (dirent* e; (e = readdir(d));) {
    const std::string f = e->d_name;
    if (f.size() < 5 || f.substr(f.size() - 4) != ".ngc") continue;
    const std::string name = f.substr(0, f.size() - 4);
    const std::string data = std::string(HWINTERP_GCODE_DATA) + "/" + name;
    const std::string out = dir_ + "/" + name + ".canon";
    EXPECT_EQ(run(data + ".ngc", out), 0) << name << ": " << slurp(dir_ + "/log");
    EXPECT_EQ(slurp(out), slurp(data + ".canon"))
        << name << ".canon differs from what rs274 writes now";
    ++programs;
  }
  closedir(d);
  EXPECT_GE(programs, 6);
}

TEST_F(Rs274, AgreesWithEveryArcEdgeVerdict) {
  for (const auto& e : test::kArcEdges) {
    const std::string ngc = dir_ + "/edge.ngc";
    std::ofstream(ngc) << e.units << " F100\nG0 X0 Y0\n" << e.arc << "\nM2\n";
    const bool accepted = run(ngc, dir_ + "/edge.canon") == 0;
    EXPECT_EQ(accepted, e.accepted) << e.units << " " << e.arc << ": " << slurp(dir_ + "/log");
  }
}

}  // namespace
}  // namespace hwinterp::gcode
