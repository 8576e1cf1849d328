// "figure | paper | ours | match" rows for the `hwinterp reproduce` pages of
// papers 001, 003 and 004 (tb/reproduce_log.cpp, _chord.cpp, _ratio.cpp):
// one text table and one JSON array from the same rows.
#pragma once

#include <cmath>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "tb/base/json.h"
#include "tb/base/text_table.h"

namespace hwinterp::cli {

class FigureRows {
 public:
  void add(std::string figure, std::string paper, std::string ours, bool match) {
    rows_.push_back({std::move(figure), std::move(paper), std::move(ours), match});
  }
  bool ok() const {
    for (const auto& r : rows_)
      if (!r.match) return false;
    return true;
  }
  std::string text() const {
    TextTable t({"figure", "paper", "ours", "match"});
    for (const auto& r : rows_) t.add_row({r.figure, r.paper, r.ours, r.match ? "yes" : "NO"});
    return t.render();
  }
  Json json() const {
    Json a = Json::array();
    for (const auto& r : rows_) {
      Json o = Json::object();
      o["figure"] = r.figure;
      o["paper"] = r.paper;
      o["ours"] = r.ours;
      o["match"] = r.match;
      a.push_back(std::move(o));
    }
    return a;
  }

 private:
  struct Row {
    std::string figure, paper, ours;
    bool match;
  };
  std::vector<Row> rows_;
};

// A value printed with `decimals` decimals covers half a unit of its last
// place; values on that boundary must still match, so compare numerically.
inline bool matches_printed(double ours, double printed, int decimals) {
  return std::abs(ours - printed) <= 0.5 * std::pow(10.0, -decimals) + 1e-12;
}

// Printed in m.mmmm e-k form: half a unit of the 5th significant digit.
inline bool matches_sig5(double ours, double printed) {
  const double half = 0.5e-4 * std::pow(10.0, std::floor(std::log10(std::abs(printed))));
  return std::abs(ours - printed) <= half * (1 + 1e-9);
}

}  // namespace hwinterp::cli
