// hwinterp merge: joins the reports of regression shards (hwinterp regress
// --shard K/N --json ...) into one report: the runs' cases back in their
// order, every total recomputed. Merging all N shards gives the unsharded
// run's report (timings aside: a run's seconds are the sum of its shards').
// Refuses reports of different regressions (seed, stream length), a shard
// given twice, and a case in two shards; says which shards are missing.
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "tb/cli/subcommand.h"
#include "tb/report/regress_report.h"

namespace hwinterp::cli {

namespace {

Json read_report(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError("cannot read report '" + path + "'");
  try {
    Json j = Json::parse(in);
    for (const char* key : {"seed", "random_commands", "shards", "runs"})
      if (!j.contains(key))
        throw UsageError("'" + path + "' is not a regress report (no \"" + key + "\")");
    return j;
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

  std::vector<Json> reports;
  for (const auto& p : paths) reports.push_back(read_report(p));
  const Json& ref = reports.front();
  std::set<std::string> shards;
  uint64_t n = 0;
  for (size_t i = 0; i < reports.size(); ++i) {
    const Json& r = reports[i];
    if (r["seed"] != ref["seed"] || r["random_commands"] != ref["random_commands"])
      throw UsageError("'" + paths[i] + "' is another regression (seed " + r["seed"].dump() + ", " +
                       r["random_commands"].dump() + " commands) than '" + paths[0] + "'");
    for (const auto& s : r["shards"]) {
      const std::string shard = s.get<std::string>();
      if (!shards.insert(shard).second)
        throw UsageError("'" + paths[i] + "': shard " + shard + " given twice");
      const uint64_t sn = std::stoull(shard.substr(shard.find('/') + 1));
      if (n && sn != n)
        throw UsageError("'" + paths[i] + "': shard " + shard + " is not of " + std::to_string(n));
      n = sn;
    }
  }
  // Every run once (regress_report orders them by their first case), its
  // cases in their run's order.
  std::vector<tb::RegressRun> runs;
  std::map<std::string, size_t> run_index;
  std::map<std::string, std::map<uint64_t, Json>> cases;
  for (size_t i = 0; i < reports.size(); ++i)
    for (const auto& run : reports[i]["runs"]) {
      const std::string key = run["core"].get<std::string>() + " " +
                              run["variant"].get<std::string>() + " " +
                              run["mode"].get<std::string>();
      if (!run_index.count(key)) {
        run_index[key] = runs.size();
        runs.push_back({run["core"], run["variant"], run["mode"], run["first_case"], 0, {}});
      }
      runs[run_index[key]].seconds += run["seconds"].get<double>();
      for (const auto& c : run["cases"])
        if (!cases[key].emplace(c["ordinal"].get<uint64_t>(), c).second)
          throw UsageError("'" + paths[i] + "': case '" + c["case"].get<std::string>() + "' of " +
                           key + " is in two reports");
    }
  for (auto& r : runs)
    for (auto& [ordinal, c] : cases[r.core + " " + r.variant + " " + r.mode]) r.cases.push_back(c);
  std::vector<std::string> missing;
  for (uint64_t k = 1; k <= n; ++k)
    if (!shards.count(std::to_string(k) + "/" + std::to_string(n)))
      missing.push_back(std::to_string(k) + "/" + std::to_string(n));
  const Json report =
      tb::regress_report(runs, ref["seed"].get<uint64_t>(), ref["random_commands"].get<uint64_t>(),
                         {shards.begin(), shards.end()});
  std::cout << "hwinterp merge: " << reports.size() << " report(s), shards";
  for (const auto& s : shards) std::cout << " " << s;
  std::cout << "\n" << tb::runs_table(report);
  for (const auto& m : missing) std::cout << "missing shard " << m << "\n";
  const bool ok = report["passed"].get<bool>() && missing.empty();
  std::cout << (ok ? "PASS" : "FAIL") << "\n";
  maybe_write_json(args, report);
  if (args.given("junit")) write_text_file(args.str("junit"), tb::junit_xml(report), "--junit");
  return ok ? kExitOk : kExitCheckFailed;
}

}  // namespace

HWINTERP_SUBCOMMAND("merge", "join the reports of regression shards (regress --shard K/N)", 25,
                    run_merge);

}  // namespace hwinterp::cli
