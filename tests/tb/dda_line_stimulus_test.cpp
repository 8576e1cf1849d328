// dda_line stimulus: job files, the random generator, and the checks that
// refuse what would overflow the datapath before anything is simulated.
#include "dda_line_stimulus.h"

#include <gtest/gtest.h>

#include <fstream>

#include "cli_args.h"
#include "dda_line_cosim.h"
#include "run_hwinterp.h"

namespace hwinterp::tb {
namespace {

DdaLineLimits n2() { return dda_line_limits(dda_line_variant_for_axes(2)); }

std::string write_job(const std::string& name, const std::string& text) {
  const std::string path = hwinterp::testing::scratch_dir("job") + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(DdaLineStimulus, JobFileCasesCommandsAndSettings) {
  const DdaLineLimits l = n2();
  const auto cases = parse_job(write_job("ok.job",
                                         "# two cases\n"
                                         "case first\n"
                                         "start 10 10\n"
                                         "preload half\n"
                                         "step_len 5\n"
                                         "line 40 20      # absolute\n"
                                         "move -5 0\n"
                                         "feed 0.5\n"
                                         "dir_hold 7\n"
                                         "gap 3\n"
                                         "drain\n"
                                         "case second\n"
                                         "move 0 -4\n"),
                               l, default_settings(l));
  ASSERT_EQ(cases.size(), 2u);
  const DdaLineCase& a = cases[0];
  EXPECT_EQ(a.name, "first");
  EXPECT_EQ(a.start, (models::LatticePoint{10, 10}));
  EXPECT_TRUE(a.settings.half_preload);
  EXPECT_EQ(a.settings.timing.step_len, 5u);
  ASSERT_EQ(a.items.size(), 5u);
  EXPECT_EQ(a.items[0].delta, (std::vector<int64_t>{30, 10}));
  EXPECT_EQ(a.items[1].delta, (std::vector<int64_t>{-5, 0}));
  // Consecutive setting lines make one settings item, carrying what was in force.
  EXPECT_EQ(a.items[2].kind, DdaLineItem::Kind::kSettings);
  EXPECT_EQ(a.items[2].settings.feed, l.full_feed() / 2);
  EXPECT_EQ(a.items[2].settings.timing.dir_hold, 7u);
  EXPECT_EQ(a.items[2].settings.timing.step_len, 5u);
  EXPECT_EQ(a.items[3].kind, DdaLineItem::Kind::kGap);
  EXPECT_EQ(a.items[4].kind, DdaLineItem::Kind::kDrain);
  EXPECT_EQ(cases[1].items.at(0).delta, (std::vector<int64_t>{0, -4}));
}

void expect_job_error(const std::string& text, const std::string& named) {
  const DdaLineLimits l = n2();
  try {
    const auto cases = parse_job(write_job("bad.job", text), l, default_settings(l));
    for (const auto& c : cases) validate_case(c, l);
    FAIL() << "accepted: " << text;
  } catch (const cli::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
  }
}

TEST(DdaLineStimulus, BadJobLinesNameFileLineAndValue) {
  expect_job_error("move 1 2\nfrobnicate 3\n", "bad.job:2: unknown directive 'frobnicate'");
  expect_job_error("move 1 2x\n", "bad.job:1: '2x' is not an integer");
  expect_job_error("move 1 2 3\n", "3 coordinates given");
  expect_job_error("step_len 70000\nmove 1 1\n", "step_len 70000 is outside");
  expect_job_error("preload full\nmove 1 1\n", "'full'");
  expect_job_error("feed 1.5\nmove 1 1\n", "feed fraction 1.5");
  expect_job_error("move 1 1\nstart 3 3\n", "'start' must come before");
  expect_job_error("# nothing\n", "has no commands");
  expect_job_error("move 3000000000 0\n", "delta 3000000000 on axis 0 is wider than the 32-bit");
  // pos_o counts from reset: two moves that add up past 2^31 - 1 overflow it.
  expect_job_error("move 2147483647 0\nmove 1 0\n", "past the 32-bit position counter");
  expect_job_error("feed 0\nmove 1 1\n", "feed 0 never advances");
}

TEST(DdaLineStimulus, RandomCaseIsReproducibleAndCoversTheSpace) {
  const DdaLineLimits l = dda_line_limits(dda_line_variant_for_axes(4));
  const DdaLineCase a = random_case(l, 400, 99), b = random_case(l, 400, 99),
                    c = random_case(l, 400, 100);
  ASSERT_EQ(a.items.size(), b.items.size());
  for (size_t i = 0; i < a.items.size(); ++i) EXPECT_EQ(a.items[i].delta, b.items[i].delta);
  bool differs = a.items.size() != c.items.size();
  for (size_t i = 0; !differs && i < a.items.size(); ++i)
    differs = a.items[i].delta != c.items[i].delta;
  EXPECT_TRUE(differs);
  // All 16 sign patterns of the four axes, zero moves, single-axis moves,
  // reversals, gaps, drains and setting changes all occur.
  std::vector<bool> octant(16, false);
  int zero = 0, single = 0, reversal = 0, gaps = 0, drains = 0, settings = 0;
  std::vector<int64_t> prev(4, 0);
  for (const auto& it : a.items) {
    gaps += it.kind == DdaLineItem::Kind::kGap;
    drains += it.kind == DdaLineItem::Kind::kDrain;
    settings += it.kind == DdaLineItem::Kind::kSettings;
    if (it.kind != DdaLineItem::Kind::kCommand) continue;
    int nonzero = 0, pattern = 0;
    bool reversed = true;
    for (size_t i = 0; i < 4; ++i) {
      nonzero += it.delta[i] != 0;
      pattern |= (it.delta[i] < 0) << i;
      reversed = reversed && it.delta[i] == -prev[i];
    }
    if (nonzero == 4) octant[static_cast<size_t>(pattern)] = true;
    zero += nonzero == 0;
    single += nonzero == 1;
    reversal += reversed && nonzero > 0;
    prev = it.delta;
  }
  for (size_t p = 0; p < 16; ++p) EXPECT_TRUE(octant[p]) << "sign pattern " << p;
  EXPECT_GT(zero, 0);
  EXPECT_GT(single, 0);
  EXPECT_GT(reversal, 0);
  EXPECT_GT(gaps, 0);
  EXPECT_GT(drains, 0);
  EXPECT_GT(settings, 0);
  EXPECT_NO_THROW(validate_case(a, l));
}

}  // namespace
}  // namespace hwinterp::tb
