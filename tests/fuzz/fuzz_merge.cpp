// Fuzz target: `hwinterp merge`'s reports. The input is one or more JSON
// reports separated by a line holding only "---"; each is parsed, then
// tb::merge_regress_reports checks every field and merges them, and the
// merged report goes through junit_xml and runs_table as the command does.
// Bad input must come back as std::invalid_argument or a JSON parse error:
// never a crash, never another exception.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "tb/report/regress_report.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<hwinterp::Json> reports;
  std::vector<std::string> names;
  size_t at = 0;
  while (at <= text.size()) {
    size_t end = text.find("\n---\n", at);
    if (end == std::string::npos) end = text.size();
    try {
      reports.push_back(hwinterp::Json::parse(text.substr(at, end - at)));
    } catch (const hwinterp::Json::exception&) {
      return 0;
    }
    names.push_back("report " + std::to_string(names.size() + 1));
    at = end + 5;
  }
  try {
    std::vector<std::string> missing;
    const hwinterp::Json merged = hwinterp::tb::merge_regress_reports(reports, names, missing);
    (void)hwinterp::tb::junit_xml(merged);
    (void)hwinterp::tb::runs_table(merged);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
