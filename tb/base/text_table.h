// Column-aligned text tables for the human summaries hwinterp prints.
#pragma once

#include <string>
#include <vector>

namespace hwinterp {

class TextTable {
 public:
  explicit TextTable(std::vector<std::string> header) : header_(std::move(header)) {}
  void add_row(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  // Numbers (cells starting with a digit, sign or '.') are right-aligned.
  std::string render() const;

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

// printf-style formatting of one double: fmt("%.4f", x).
std::string fmt(const char* format, double value);

}  // namespace hwinterp
