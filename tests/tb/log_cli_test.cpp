// `hwinterp log` through the real executable: the command-line contract (exit
// 0 on success, 2 with one line naming the value on bad input) and the JSON
// and CSV outputs. cmd_log.cpp lives in the executable, not in hwinterp_tb,
// so the test runs the binary built beside this one (build/tb/hwinterp), or
// $HWINTERP_EXE.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace {

std::string hwinterp_exe() {
  if (const char* e = std::getenv("HWINTERP_EXE")) return e;
  std::array<char, 4096> buf{};
  const ssize_t n = readlink("/proc/self/exe", buf.data(), buf.size() - 1);
  if (n <= 0) return "";
  std::string self(buf.data(), static_cast<size_t>(n));
  self = self.substr(0, self.rfind('/'));                   // build/tests
  return self.substr(0, self.rfind('/')) + "/tb/hwinterp";  // build/tb/hwinterp
}

struct Result {
  int code = -1;
  std::string err;  // stderr only
};

// Runs `hwinterp <args>`, keeping stderr only.
Result run_hwinterp(const std::string& args) {
  const std::string cmd = hwinterp_exe() + " " + args + " 2>&1 >/dev/null";
  Result r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 512> buf{};
  while (fgets(buf.data(), static_cast<int>(buf.size()), p)) r.err += buf.data();
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

Result run(const std::string& args) { return run_hwinterp("log " + args); }

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

class LogCli : public ::testing::Test {
 protected:
  void SetUp() override {
    if (access(hwinterp_exe().c_str(), X_OK) != 0)
      GTEST_SKIP() << "hwinterp executable not found at " << hwinterp_exe();
    dir_ = ::testing::TempDir() + "log_cli_" + std::to_string(getpid());
    mkdir(dir_.c_str(), 0755);
  }
  std::string dir_;
};

TEST_F(LogCli, PaperCaseJsonAndCsv) {
  const std::string json = dir_ + "/log.json", csv = dir_ + "/log.csv";
  const Result r = run("--d1 10 --spiral 30 --cone 5 --rake 8 --dl 0.2 --x-end 30 --json " + json +
                       " --csv " + csv);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string j = slurp(json);
  for (const char* key :
       {"\"points\": 152", "\"x_last\": 30.268", "\"max_error\": 3.978", "\"max_error_odd\": 3.978",
        "\"max_error_even\": 3.500", "\"max_error_index\": 1", "\"max_error_even_index\": 152"})
    EXPECT_NE(j.find(key), std::string::npos) << key << " in\n" << j;
  std::ifstream f(csv);
  std::string line;
  int rows = 0;
  std::getline(f, line);
  EXPECT_EQ(line, "index,parity,x,y,z,a,pa,error");
  while (std::getline(f, line)) ++rows;
  EXPECT_EQ(rows, 153);  // the start point and 152 interpolated points
}

TEST_F(LogCli, ExactEven) {
  const std::string json = dir_ + "/exact.json";
  const Result r = run("--exact-even --json " + json);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string j = slurp(json);
  EXPECT_NE(j.find("\"even_step\": \"exact\""), std::string::npos) << j;
  EXPECT_NE(j.find("\"max_error_even\": 0"), std::string::npos) << j;
}

// Bad input: exit 2, exactly one line on stderr, naming the value.
TEST_F(LogCli, BadInputOneLineNamingTheValue) {
  const std::pair<const char*, const char*> cases[] = {
      {"--d1 -3", "--d1: -3"},
      {"--d1 0", "--d1: 0"},
      {"--dl 0", "--dl: 0"},
      {"--dl -0.1", "--dl: -0.1"},
      {"--x-end 0", "--x-end: 0"},
      {"--spiral 90", "--spiral: 90"},
      {"--cone 0", "--cone: 0"},
      {"--rake -5", "--rake: -5"},
      {"--cone abc", "abc"},
      {"--dl 1e-7", "dl 1e-07"},
      {"--dl 31", "dl 31"},
      {"--bogus 1", "--bogus"},
      {"--csv /nonexistent-dir/x.csv", "/nonexistent-dir/x.csv"},
  };
  for (const auto& [args, named] : cases) {
    const Result r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_NE(r.err.find(named), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
}

// The reproduction pages of papers 001, 003 and 004 match (exit 0).
TEST_F(LogCli, ReproducePagesMatch) {
  for (const char* paper : {"log", "chord", "ratio"}) {
    const Result r = run_hwinterp(std::string("reproduce --paper ") + paper);
    EXPECT_EQ(r.code, 0) << paper << ": " << r.err;
  }
}

}  // namespace
