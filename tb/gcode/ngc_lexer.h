// Splits one RS274/NGC line into words, as LinuxCNC reads a line.
//
// Contract: comments in parentheses and after ';' are removed (a '(' inside
// a comment or an unclosed one is refused, as LinuxCNC does); spaces and
// tabs outside comments are removed everywhere, also inside numbers
// ("X 1 . 5" is X1.5, "X1 2" is X12); letters are upper-cased. A word is a
// letter and a number: an optional sign, digits with at most one '.', at
// least one digit. A line that is exactly '%' (surrounding spaces allowed) is
// a percent line.
//
// Refused with the --canon hint (cli::UsageError, "FILE:LINE: word 'W'
// changes the path and is not in the supported subset; ..."): parameters
// '#', expressions '[', polar coordinates '@' '^', O-words, block delete '/'.
// Every other letter makes a word (the reader decides which it takes).
// Refused as unreadable: a letter without a number, a malformed number
// ("X1..2", "X--1"), any other character, control and non-ASCII bytes
// outside comments, a value beyond +-1e9.
#pragma once

#include <string>
#include <vector>

#include "tb/gcode/line_source.h"

namespace hwinterp::gcode {

struct Word {
  char letter;       // 'A'..'Z', upper case
  std::string text;  // as written, spaces removed, upper case: "G1", "X-1.5"
  double value;
};

struct LexedLine {
  bool percent = false;
  std::vector<Word> words;
  int comments = 0;  // parenthesised and ';' comments
};

// Lexes `line` (the line `src` read last; errors name it).
LexedLine lex_ngc_line(const std::string& line, const LineSource& src);

// The message every word outside the subset gets (without "FILE:LINE: ").
std::string unsupported_word_message(const std::string& word, const std::string& file);

}  // namespace hwinterp::gcode
