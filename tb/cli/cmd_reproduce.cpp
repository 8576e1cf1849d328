// hwinterp reproduce [--paper KEY|all]: runs the registered paper reproductions.
#include <algorithm>
#include <iostream>

#include "tb/cli/subcommand.h"
#include "tb/reproduce/reproduce.h"

namespace hwinterp::cli {

std::vector<Paper>& papers() {
  static std::vector<Paper> all;
  return all;
}

namespace {

int run_reproduce(int argc, char** argv, int first) {
  auto list = papers();
  std::sort(list.begin(), list.end(),
            [](const Paper& a, const Paper& b) { return a.order < b.order; });
  std::vector<std::string> keys{"all"};
  std::string key_help;
  for (const auto& p : list) {
    keys.push_back(p.key);
    key_help += "\n    " + p.key + ": " + p.title;
  }
  Args args("reproduce",
            "Reproduce the papers' tables, the paper's figure beside ours." + key_help);
  args.option("paper", "KEY", "which paper (all, or one of the keys above)", "all");
  if (parse_or_help(args, argc, argv, first)) return kExitOk;
  const std::string which = args.choice("paper", keys);

  Json report = Json::object();
  Json results = Json::array();
  bool all_ok = true;
  for (const auto& p : list) {
    if (which != "all" && which != p.key) continue;
    std::cout << "== " << p.key << ": " << p.title << "\n";
    PaperReproduction r = p.run();
    std::cout << r.text << (r.ok ? "-> all rows match\n\n" : "-> MISMATCH: see rows marked NO\n\n");
    r.json["paper"] = p.key;
    r.json["ok"] = r.ok;
    results.push_back(std::move(r.json));
    all_ok = all_ok && r.ok;
  }
  report["papers"] = std::move(results);
  report["ok"] = all_ok;
  maybe_write_json(args, report);
  return all_ok ? kExitOk : kExitCheckFailed;
}

}  // namespace

HWINTERP_SUBCOMMAND("reproduce", "reproduce the papers' tables beside ours", 30, run_reproduce);

}  // namespace hwinterp::cli
