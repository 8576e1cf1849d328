// The report of `hwinterp regress`, built from the cases' JSON, so that
// `hwinterp merge` builds the very same report from the reports of
// regression shards (--shard K/N): merging every shard gives the unsharded
// run's report, timings aside. Also its JUnit form and its summary table.
#pragma once

#include <string>
#include <vector>

#include "tb/base/json.h"

namespace hwinterp::tb {

// One lockstep run of one variant in one mode.
struct RegressRun {
  std::string core, variant, mode;
  uint64_t first_case = 0;  // the number of its first case, all runs' cases numbered in order
  double seconds = 0;       // wall time (SystemC runs: the shared elaboration's)
  std::vector<Json> cases;  // CaseResult::to_json, ordered by "ordinal"
};

// {seed, random_commands, shards, passed, cores: {core: {passed, runs, cases,
// cycles}}, runs: [aggregate_json(cases) + first_case, seconds,
// cycles_per_second]}, the runs in the order of their first_case;
// `shards` lists the shards it holds ("1/1" for an unsharded run).
Json regress_report(const std::vector<RegressRun>& runs, uint64_t seed, uint64_t commands,
                    const std::vector<std::string>& shards);

// Checks that `report` has every field `hwinterp merge` and the report's
// readers take, of the type they take (regress_report's top level, each run,
// each case's fields aggregate_json and junit_xml read, shards as "K/N").
// Throws std::invalid_argument naming the field ("runs[0].cases[2].cycles:
// missing, an unsigned integer").
void check_regress_report(const Json& report);

// The merged report of regression shards (each checked by
// check_regress_report; `names[i]`, a file name, names `reports[i]` in
// messages): every run once, its cases in their order, the totals recomputed.
// `missing` gets the shards "K/N" not given. Throws std::invalid_argument
// naming the report and the field: reports of different regressions (seed,
// stream length), a shard given twice or of another count, a case in two
// reports.
Json merge_regress_reports(const std::vector<Json>& reports, const std::vector<std::string>& names,
                           std::vector<std::string>& missing);

// JUnit XML of a regress report: a testsuite per run, a testcase per case
// (with a failure element for a failed one).
std::string junit_xml(const Json& report);

// One row per run: core, variant, mode, cases, cycles, seconds, clocks/s, result.
std::string runs_table(const Json& report);

}  // namespace hwinterp::tb
