// Input a new user gets wrong, and outputs that must never be lost (issue 11,
// found by randomized command lines and mutated job files): every case is
// refused before anything runs, with exit 2 and one line naming the value;
// nothing half-written is left behind.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <fstream>

#include "run_hwinterp.h"
#include "tb/base/json.h"

namespace {

using hwinterp::Json;
using hwinterp::testing::CliResult;
using hwinterp::testing::run_hwinterp;
using hwinterp::testing::scratch_dir;
using hwinterp::testing::slurp;

bool exists(const std::string& path) {
  struct stat st {};
  return stat(path.c_str(), &st) == 0;
}

// Exit 2, exactly one line on stderr naming `named`, nothing simulated.
void expect_refused(const std::string& args, const std::string& named) {
  const CliResult r = run_hwinterp(args);
  EXPECT_EQ(r.code, 2) << args << "\n" << r.out << r.err;
  EXPECT_NE(r.err.find(named), std::string::npos) << args << ": " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  EXPECT_EQ(r.out.find("PASS"), std::string::npos) << args << ": " << r.out;
}

std::string write(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// 1. Coordinates whose difference overflows 64 bits used to run a 1-step
// move and pass; so did a job that walked past INT64_MAX.
TEST(BadInput, CoordinatesThatWouldOverflowAreRefused) {
  const std::string dir = scratch_dir("bad_overflow");
  expect_refused(
      "cosim --core dda_line --mode direct --line -9223372036854775808,0,9223372036854775807,0",
      "-9223372036854775808");
  expect_refused("cosim --core dda_line --mode direct --job " +
                     write(dir + "/a.job", "start 9223372036854775807 0\nmove 1 0\n"),
                 "9223372036854775807");
  expect_refused(
      "cosim --core ppc_line --mode direct --job " +
          write(dir + "/b.job", "move 2305843009213693952 0\nmove 2305843009213693952 0\n"),
      "b.job:2: the position this reaches");
  expect_refused("cosim --core ppc_arc --mode direct --arc 0,0,1,0,-9223372036854775807,0,ccw",
                 "-9223372036854775807");
}

// 2. A NUL byte inside a number ended it silently ("7\0999" ran as 7).
TEST(BadInput, NulInsideANumberIsRefused) {
  const std::string job =
      write(scratch_dir("bad_nul") + "/n.job", std::string("move 7\0999 2\n", 13));
  expect_refused("cosim --core dda_line --mode direct --job " + job, "'7\\x00999'");
}

// 3. An empty output path was ignored (no file, exit 0), an empty --json
// refused only after the simulation.
TEST(BadInput, EmptyValuesAreRefused) {
  for (const char* o : {"--vcd ''", "--fst=", "--path-csv ''", "--dump-frames ''", "--json ''"})
    expect_refused(std::string("cosim --core dda_line --mode direct --line 0,0,3,3 ") + o,
                   "needs a value, got an empty one");
}

// 4. A failed write of a small report went unnoticed (the flush on close).
TEST(BadInput, AReportThatCannotBeWrittenFails) {
  for (const char* cmd : {"plan --law ms --tol 0.0005 --stroke 100 --lift 40", "log"}) {
    const CliResult r = run_hwinterp(std::string(cmd) + " --json /dev/full");
    EXPECT_EQ(r.code, 2) << cmd;
    EXPECT_NE(r.err.find("/dev/full"), std::string::npos) << cmd << ": " << r.err;
  }
}

// 5. A --json or --fst target that cannot be written is refused before the
// run, not after it (a long run lost its result).
TEST(BadInput, UnwritableOutputsAreRefusedBeforeTheRun) {
  const std::string dir = scratch_dir("bad_targets");
  mkdir((dir + "/x.fst").c_str(), 0755);
  const std::string run = "cosim --core dda_line --mode direct --line 0,0,3,3 ";
  expect_refused(run + "--json " + dir, "is a directory");
  expect_refused(run + "--fst " + dir + "/x.fst", "--fst");
  expect_refused(run + "--vcd /no/such/dir/t.vcd", "--vcd");
  expect_refused("regress --json " + dir, "is a directory");
  expect_refused("reproduce --json /no/such/dir/r.json", "/no/such/dir");
}

// 6. A job case name with bytes >= 0x80 made the JSON report invalid UTF-8.
TEST(BadInput, NonUtf8CaseNamesGiveValidJson) {
  const std::string dir = scratch_dir("bad_utf8");
  const std::string job = write(dir + "/u.job", "case caf\xe9\nmove 3 1\n");
  const CliResult r = run_hwinterp("cosim --core dda_line --mode direct --job " + job + " --json " +
                                   dir + "/u.json");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const Json j = Json::parse(slurp(dir + "/u.json"));
  EXPECT_EQ(j["cases"][0]["case"], "caf\xef\xbf\xbd");
}

// 7. --trace-window buffered without bound: a window that would not fit in
// memory is refused up front, and no partial trace is left.
TEST(BadInput, TraceWindowIsBoundedAndLeavesNoPartialFile) {
  const std::string dir = scratch_dir("bad_window");
  expect_refused("cosim --core dda_line --mode direct --random 10 --seed 1 --vcd " + dir +
                     "/w.vcd --trace-window 100000000",
                 "MiB");
  EXPECT_FALSE(exists(dir + "/w.vcd"));
  EXPECT_FALSE(exists(dir + "/w.vcd.partial"));
  // A window that fits: the last N clocks, written whole under the final name.
  const CliResult r =
      run_hwinterp("cosim --core dda_line --mode direct --random 10 --seed 1 --vcd " + dir +
                   "/ok.vcd --trace-window 50");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(exists(dir + "/ok.vcd"));
  EXPECT_FALSE(exists(dir + "/ok.vcd.partial"));
}

// 8. Messages that named the wrong option or no element, or ran over two lines.
TEST(BadInput, MessagesNameTheRightOptionAndElementOnOneLine) {
  expect_refused("cosim --core dda_line --line 0,0,1,1 --feed 0.000001",
                 "--feed: feed fraction 0.000001");
  expect_refused("plan --law ms --tol 0.0005 --rotating --r0 0.0000001 --lift 30 --theta-d 100",
                 "--r0 0.0000001");
  expect_refused("log --spiral 89.9999999", "--spiral");
  expect_refused("cosim --core dda_line --line 131072,-10,,-51",
                 "element 3 of '131072,-10,,-51' is empty");
  expect_refused("cosim --core dda_line --line \"$(printf '1\\n2,3,4')\"", "'1\\n2'");
}

}  // namespace
