#include "tb/base/args.h"

#include <gtest/gtest.h>

#include <vector>

namespace hwinterp::cli {
namespace {

// Runs Args::parse over a literal argument list (argv[0] is the subcommand).
void parse(Args& a, std::vector<std::string> words) {
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  a.parse(static_cast<int>(argv.size()), argv.data(), 1);
}

Args make() {
  Args a("t", "test");
  a.option("n", "N", "a count", "3").option("x", "X", "a real").option("line", "L", "coords");
  a.flag("fast", "a flag");
  return a;
}

TEST(CliArgs, ParsesOptionsFlagsAndDefaults) {
  Args a = make();
  parse(a, {"t", "--x", "2.5", "--fast", "--line=1,-2,3"});
  EXPECT_EQ(a.integer("n"), 3);
  EXPECT_DOUBLE_EQ(a.real("x"), 2.5);
  EXPECT_TRUE(a.given("fast"));
  EXPECT_FALSE(a.given("n"));
  EXPECT_EQ(a.integer_list("line"), (std::vector<int64_t>{1, -2, 3}));
}

// Every rejection must name the offending value so the user can fix it.
void expect_usage_error(std::vector<std::string> words, const std::string& named,
                        const std::function<void(const Args&)>& use = nullptr) {
  Args a = make();
  try {
    parse(a, words);
    if (use) use(a);
    FAIL() << "no UsageError for the input naming '" << named << "'";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
  }
}

TEST(CliArgs, RejectsBadInputNamingTheValue) {
  expect_usage_error({"t", "--bogus", "1"}, "--bogus");
  expect_usage_error({"t", "--x"}, "--x");
  expect_usage_error({"t", "stray"}, "stray");
  expect_usage_error({"t", "--n", "1", "--n", "2"}, "--n");
  expect_usage_error({"t", "--n", "12abc"}, "12abc", [](const Args& a) { a.integer("n"); });
  expect_usage_error({"t", "--n", "99"}, "99", [](const Args& a) { a.integer("n", 0, 10); });
  expect_usage_error({"t", "--x", "nan"}, "nan", [](const Args& a) { a.real("x"); });
  expect_usage_error({"t", "--line", "1,,2"}, "--line",
                     [](const Args& a) { a.integer_list("line"); });
  expect_usage_error({"t", "--line", "1,2,"}, "1,2,",
                     [](const Args& a) { a.integer_list("line"); });
  expect_usage_error({"t", "--fast=1"}, "--fast");
}

TEST(CliArgs, HelpListsEveryOption) {
  Args a = make();
  parse(a, {"t", "--help"});
  EXPECT_TRUE(a.help_requested());
  const std::string h = a.help_text();
  for (const char* o : {"--n", "--x", "--line", "--fast", "--json", "--help"})
    EXPECT_NE(h.find(o), std::string::npos) << o;
}

}  // namespace
}  // namespace hwinterp::cli
