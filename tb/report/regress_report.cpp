#include "tb/report/regress_report.h"

#include <algorithm>
#include <sstream>

#include "tb/base/text_table.h"
#include "tb/report/cosim_report.h"

namespace hwinterp::tb {

Json regress_report(const std::vector<RegressRun>& runs, uint64_t seed, uint64_t commands,
                    const std::vector<std::string>& shards) {
  Json report;
  report["seed"] = seed;
  report["random_commands"] = commands;
  report["shards"] = shards;
  Json cores = Json::object(), jruns = Json::array();
  bool ok = !runs.empty();
  std::vector<const RegressRun*> ordered;
  for (const auto& r : runs) ordered.push_back(&r);
  std::stable_sort(ordered.begin(), ordered.end(),
                   [](const auto* a, const auto* b) { return a->first_case < b->first_case; });
  for (const RegressRun* rp : ordered) {
    const RegressRun& r = *rp;
    Json j = aggregate_json(r.cases);
    j["core"] = r.core;
    j["variant"] = r.variant;
    j["mode"] = r.mode;
    j["first_case"] = r.first_case;
    j["seconds"] = r.seconds;
    const double cycles = j["cycles"].get<double>();
    j["cycles_per_second"] = r.seconds > 0 ? cycles / r.seconds : 0.0;
    const bool pass = j["passed"].get<bool>();
    ok = ok && pass;
    Json& c = cores[r.core];
    if (c.is_null()) c = {{"passed", true}, {"runs", 0}, {"cases", 0}, {"cycles", 0}};
    c["passed"] = c["passed"].get<bool>() && pass;
    c["runs"] = c["runs"].get<uint64_t>() + 1;
    c["cases"] = c["cases"].get<uint64_t>() + r.cases.size();
    c["cycles"] = c["cycles"].get<uint64_t>() + j["cycles"].get<uint64_t>();
    jruns.push_back(std::move(j));
  }
  report["cores"] = std::move(cores);
  report["runs"] = std::move(jruns);
  report["passed"] = ok;
  return report;
}

namespace {

std::string xml(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

std::string junit_xml(const Json& report) {
  std::ostringstream os;
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"hwinterp regress\">\n";
  for (const auto& run : report["runs"]) {
    const std::string suite =
        run["variant"].get<std::string>() + "." + run["mode"].get<std::string>();
    size_t failures = 0;
    for (const auto& c : run["cases"]) failures += !c["passed"].get<bool>();
    os << "  <testsuite name=\"" << xml(suite) << "\" tests=\"" << run["cases"].size()
       << "\" failures=\"" << failures << "\">\n";
    for (const auto& c : run["cases"]) {
      os << "    <testcase classname=\"" << xml(suite) << "\" name=\""
         << xml(c["case"].get<std::string>()) << "\" time=\"" << c["seconds"].get<double>() << "\"";
      if (c["passed"].get<bool>()) {
        os << "/>\n";
        continue;
      }
      os << ">\n      <failure message=\""
         << xml(std::to_string(c["mismatches"].get<uint64_t>()) + " mismatches, " +
                std::to_string(c["timing_violations"].get<uint64_t>()) + " timing violations, " +
                std::to_string(c["scoreboard_errors"].get<uint64_t>()) + " scoreboard errors")
         << "\">" << xml(dump_json(c)) << "</failure>\n    </testcase>\n";
    }
    os << "  </testsuite>\n";
  }
  os << "</testsuites>\n";
  return os.str();
}

std::string runs_table(const Json& report) {
  TextTable t({"core", "variant", "mode", "cases", "cycles", "seconds", "cycles/s", "result"});
  for (const auto& r : report["runs"])
    t.add_row({r["core"].get<std::string>(), r["variant"].get<std::string>(),
               r["mode"].get<std::string>(), std::to_string(r["cases"].size()),
               std::to_string(r["cycles"].get<uint64_t>()), fmt("%.2f", r["seconds"].get<double>()),
               fmt("%.3g", r["cycles_per_second"].get<double>()),
               r["passed"].get<bool>() ? "pass" : "FAIL"});
  return t.render();
}

}  // namespace hwinterp::tb
