// hwinterp merge: joins the reports of regression shards (hwinterp regress
// --shard K/N --json ...) into one report: the runs' cases back in their
// order, every total recomputed. Merging all N shards gives the unsharded
// run's report (timings aside: a run's seconds are the sum of its shards').
// The merge itself is tb::merge_regress_reports (tb/report/regress_report.h:
// each report's fields checked, then refused: reports of different
// regressions, a shard given twice, a case in two shards); this file reads the
// files and says which shards are missing.
#include <fstream>
#include <iostream>

#include "tb/cli/subcommand.h"
#include "tb/report/regress_report.h"

namespace hwinterp::cli {

namespace {

Json read_report(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError("cannot read report '" + path + "'");
  try {
    return Json::parse(in);
  } catch (const Json::exception& e) {
    throw UsageError("'" + path + "' is not JSON: " + e.what());
  }
}

int run_merge(int argc, char** argv, int first) {
  // The reports are the positional arguments: take them before the options.
  std::vector<std::string> paths;
  int opt = first;
  while (opt < argc && std::string(argv[opt]).rfind("--", 0) != 0) paths.push_back(argv[opt++]);
  Args args("merge",
            "Joins the JSON reports of regression shards into the unsharded run's report.\n"
            "usage: hwinterp merge A.json B.json ... [--json OUT] [--junit OUT.xml]");
  args.option("junit", "FILE", "write the merged JUnit report");
  if (parse_or_help(args, argc, argv, opt)) return kExitOk;
  if (paths.empty())
    throw UsageError("give the shard reports to merge (hwinterp merge A.json B.json ...)");
  stage_outputs(args, {"junit"}, {}, paths, "a shard report");

  std::vector<Json> reports;
  for (const auto& p : paths) reports.push_back(read_report(p));
  std::vector<std::string> missing;
  Json report;
  try {
    report = tb::merge_regress_reports(reports, paths, missing);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  std::cout << "hwinterp merge: " << reports.size() << " report(s), shards";
  for (const auto& s : report["shards"]) std::cout << " " << s.get<std::string>();
  std::cout << "\n" << tb::runs_table(report);
  for (const auto& m : missing) std::cout << "missing shard " << m << "\n";
  const bool ok = report["passed"].get<bool>() && missing.empty();
  std::cout << (ok ? "PASS" : "FAIL") << "\n";
  maybe_write_json(args, report);
  if (args.given("junit")) write_text_file(output_path("junit"), tb::junit_xml(report), "--junit");
  return ok ? kExitOk : kExitCheckFailed;
}

}  // namespace

HWINTERP_SUBCOMMAND("merge", "join the reports of regression shards (regress --shard K/N)", 25,
                    run_merge);

}  // namespace hwinterp::cli
