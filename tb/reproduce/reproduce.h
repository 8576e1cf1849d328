// `hwinterp reproduce`: each paper's tables, the paper's figure beside ours.
// Each paper's reproduction lives in its own tb/reproduce_<paper>.cpp and
// registers itself with HWINTERP_PAPER(...); cmd_reproduce.cpp runs them.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tb/base/concat.h"
#include "tb/base/json.h"

namespace hwinterp::cli {

struct PaperReproduction {
  bool ok = true;    // every row matched within its tolerance
  std::string text;  // human tables: paper figure | ours | match
  Json json = Json::object();
};

struct Paper {
  std::string key;    // --paper value: oli, log, chord, ratio
  std::string title;  // one line: paper file and topic
  int order;
  std::function<PaperReproduction()> run;
};

std::vector<Paper>& papers();

struct PaperRegistration {
  PaperRegistration(Paper p) { papers().push_back(std::move(p)); }
};

}  // namespace hwinterp::cli

#define HWINTERP_PAPER(...)                                        \
  static const ::hwinterp::cli::PaperRegistration HWINTERP_CONCAT( \
      hwinterp_paper_, __LINE__)(::hwinterp::cli::Paper{__VA_ARGS__})
