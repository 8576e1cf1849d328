#include "tb/report/regress_report.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

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

namespace hwinterp::tb {

namespace {

// What a field must be, for the messages and the checks.
enum class Kind { kString, kUnsigned, kNumber, kBool, kArray, kObject, kAny };

const char* kind_text(Kind k) {
  switch (k) {
    case Kind::kString:
      return "a string";
    case Kind::kUnsigned:
      return "an unsigned integer";
    case Kind::kNumber:
      return "a number";
    case Kind::kBool:
      return "true or false";
    case Kind::kArray:
      return "an array";
    case Kind::kObject:
      return "an object";
    case Kind::kAny:
      break;
  }
  return "a value";
}

bool is_kind(const Json& v, Kind k) {
  switch (k) {
    case Kind::kString:
      return v.is_string();
    case Kind::kUnsigned:
      return v.is_number_unsigned() || (v.is_number_integer() && v.get<int64_t>() >= 0);
    case Kind::kNumber:
      return v.is_number();
    case Kind::kBool:
      return v.is_boolean();
    case Kind::kArray:
      return v.is_array();
    case Kind::kObject:
      return v.is_object();
    case Kind::kAny:
      return true;
  }
  return false;
}

struct Field {
  const char* name;
  Kind kind;
};

// The fields the readers take, listed once: the report's, a run's, a case's
// (those aggregate_json, junit_xml and merge read), a core check's.
const Field kReportFields[] = {{"seed", Kind::kUnsigned},
                               {"random_commands", Kind::kUnsigned},
                               {"shards", Kind::kArray},
                               {"runs", Kind::kArray}};
const Field kRunFields[] = {{"core", Kind::kString},    {"variant", Kind::kString},
                            {"mode", Kind::kString},    {"first_case", Kind::kUnsigned},
                            {"seconds", Kind::kNumber}, {"cases", Kind::kArray}};
const Field kCaseFields[] = {{"core", Kind::kString},
                             {"variant", Kind::kString},
                             {"mode", Kind::kString},
                             {"case", Kind::kString},
                             {"ordinal", Kind::kUnsigned},
                             {"seed", Kind::kAny},
                             {"passed", Kind::kBool},
                             {"cycles", Kind::kUnsigned},
                             {"commands", Kind::kUnsigned},
                             {"steps", Kind::kArray},
                             {"end_position", Kind::kAny},
                             {"expected_end_position", Kind::kAny},
                             {"max_path_error_steps", Kind::kNumber},
                             {"mismatches", Kind::kUnsigned},
                             {"timing_violations", Kind::kUnsigned},
                             {"scoreboard_errors", Kind::kUnsigned},
                             {"first_mismatch", Kind::kAny},
                             {"aborts", Kind::kArray},
                             {"seconds", Kind::kNumber}};
const Field kCoreCheckFields[] = {{"count_name", Kind::kString},
                                  {"name", Kind::kString},
                                  {"count", Kind::kUnsigned},
                                  {"max", Kind::kNumber}};

template <size_t N>
void check_fields(const Json& j, const std::string& where, const Field (&fields)[N]) {
  if (!j.is_object())
    throw std::invalid_argument((where.empty() ? "the report" : where) + ": not an object");
  for (const Field& f : fields) {
    const std::string at = where.empty() ? f.name : where + "." + f.name;
    if (!j.contains(f.name)) throw std::invalid_argument(at + ": missing, " + kind_text(f.kind));
    if (!is_kind(j[f.name], f.kind))
      throw std::invalid_argument(at + ": " + dump_json(j[f.name]).substr(0, 40) + " is not " +
                                  kind_text(f.kind));
  }
}

// "K/N" with 1 <= K <= N: its N; else 0.
uint64_t shard_count(const std::string& s) {
  const size_t slash = s.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == s.size() || s.size() > 41) return 0;
  uint64_t k = 0, n = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    if (i == slash) continue;
    if (s[i] < '0' || s[i] > '9') return 0;
    uint64_t& v = i < slash ? k : n;
    if (v > (UINT64_MAX - 9) / 10) return 0;
    v = v * 10 + static_cast<uint64_t>(s[i] - '0');
  }
  return k >= 1 && k <= n ? n : 0;
}

}  // namespace

void check_regress_report(const Json& report) {
  check_fields(report, "", kReportFields);
  const Json& shards = report["shards"];
  for (size_t i = 0; i < shards.size(); ++i)
    if (!shards[i].is_string() || !shard_count(shards[i].get<std::string>()))
      throw std::invalid_argument("shards[" + std::to_string(i) +
                                  "]: " + dump_json(shards[i]).substr(0, 40) +
                                  " is not a shard K/N (1 <= K <= N)");
  const Json& runs = report["runs"];
  for (size_t r = 0; r < runs.size(); ++r) {
    const std::string run = "runs[" + std::to_string(r) + "]";
    check_fields(runs[r], run, kRunFields);
    const Json& cases = runs[r]["cases"];
    for (size_t c = 0; c < cases.size(); ++c) {
      const std::string at = run + ".cases[" + std::to_string(c) + "]";
      check_fields(cases[c], at, kCaseFields);
      for (const auto& s : cases[c]["steps"])
        if (!is_kind(s, Kind::kUnsigned))
          throw std::invalid_argument(at + ".steps: " + dump_json(s).substr(0, 40) +
                                      " is not an unsigned integer");
      if (cases[c].contains("core_checks")) {
        const Json& k = cases[c]["core_checks"];
        if (!k.is_array()) throw std::invalid_argument(at + ".core_checks: not an array");
        for (size_t i = 0; i < k.size(); ++i)
          check_fields(k[i], at + ".core_checks[" + std::to_string(i) + "]", kCoreCheckFields);
      }
    }
  }
}

Json merge_regress_reports(const std::vector<Json>& reports, const std::vector<std::string>& names,
                           std::vector<std::string>& missing) {
  if (reports.empty() || names.size() != reports.size())
    throw std::invalid_argument("no reports to merge");
  for (size_t i = 0; i < reports.size(); ++i) {
    try {
      check_regress_report(reports[i]);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("'" + names[i] + "' is not a regress report: " + e.what());
    }
  }
  const Json& ref = reports.front();
  std::set<std::string> shards;
  uint64_t n = 0;
  for (size_t i = 0; i < reports.size(); ++i) {
    const Json& r = reports[i];
    if (r["seed"] != ref["seed"] || r["random_commands"] != ref["random_commands"])
      throw std::invalid_argument("'" + names[i] + "' is another regression (seed " +
                                  r["seed"].dump() + ", " + r["random_commands"].dump() +
                                  " commands) than '" + names[0] + "'");
    for (const auto& s : r["shards"]) {
      const std::string shard = s.get<std::string>();
      if (!shards.insert(shard).second)
        throw std::invalid_argument("'" + names[i] + "': shard " + shard + " given twice");
      const uint64_t sn = shard_count(shard);
      if (n && sn != n)
        throw std::invalid_argument("'" + names[i] + "': shard " + shard + " is not of " +
                                    std::to_string(n));
      n = sn;
    }
  }
  // Every run once (regress_report orders them by their first case), its
  // cases in their run's order.
  std::vector<RegressRun> runs;
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
          throw std::invalid_argument("'" + names[i] + "': case '" + c["case"].get<std::string>() +
                                      "' of " + key + " is in two reports");
    }
  for (auto& r : runs)
    for (auto& [ordinal, c] : cases[r.core + " " + r.variant + " " + r.mode]) r.cases.push_back(c);
  // The shards not given, one by one up to a count no regression reaches.
  constexpr uint64_t kListed = 4096;
  missing.clear();
  for (uint64_t k = 1; k <= std::min(n, kListed); ++k)
    if (!shards.count(std::to_string(k) + "/" + std::to_string(n)))
      missing.push_back(std::to_string(k) + "/" + std::to_string(n));
  if (n > kListed)
    missing.push_back("and every other K/" + std::to_string(n) + " not given above " +
                      std::to_string(kListed));
  return regress_report(runs, ref["seed"].get<uint64_t>(), ref["random_commands"].get<uint64_t>(),
                        {shards.begin(), shards.end()});
}

}  // namespace hwinterp::tb
