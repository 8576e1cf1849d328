#include "tb/gcode/ngc_lexer.h"

#include <cmath>
#include <cstdlib>

namespace hwinterp::gcode {

namespace {

constexpr double kMaxValue = 1e9;  // no machine is a million metres long
constexpr size_t kTokenMax = 24;

bool is_letter(char c) { return c >= 'A' && c <= 'Z'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const size_t e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

// The text of the word starting at `i`: its first character and what follows
// up to the next letter outside brackets ("#<depth>", "[sin[1]]", "o<sub>"),
// at most kTokenMax characters.
std::string token_at(const std::string& code, size_t i) {
  size_t e = i + 1;
  int depth = 0;
  for (; e < code.size() && e - i < kTokenMax; ++e) {
    const char c = code[e];
    if (depth == 0 && is_letter(c)) break;
    if (c == '[' || c == '<') ++depth;
    if ((c == ']' || c == '>') && depth > 0) --depth;
  }
  return code.substr(i, e - i);
}

[[noreturn]] void refuse(const LineSource& src, const std::string& word) {
  src.fail(unsupported_word_message(word, src.name()));
}

}  // namespace

std::string unsupported_word_message(const std::string& word, const std::string& file) {
  return "word '" + word +
         "' changes the path and is not in the supported subset; run it through LinuxCNC's "
         "interpreter and use --canon (rs274 -g " +
         file + " out.canon)";
}

LexedLine lex_ngc_line(const std::string& line, const LineSource& src) {
  LexedLine out;
  if (trim(line) == "%") {
    out.percent = true;
    return out;
  }
  const std::string shown = "'" + excerpt(trim(line)) + "'";

  // Comments and blanks out, letters up.
  std::string code;
  bool in_comment = false;
  for (const char c : line) {
    if (in_comment) {
      if (c == ')') in_comment = false;
      if (c == '(') src.fail("'(' inside a comment (LinuxCNC refuses nested comments) in " + shown);
      continue;
    }
    if (c == '(') {
      in_comment = true;
      ++out.comments;
      continue;
    }
    if (c == ';') {
      ++out.comments;
      break;
    }
    if (c == ' ' || c == '\t') continue;
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u >= 0x7f) {
      static const char* kHex = "0123456789abcdef";
      src.fail(std::string("unreadable byte \\x") + kHex[u >> 4] + kHex[u & 15] + " in " + shown);
    }
    code.push_back(c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c);
  }
  if (in_comment) src.fail("comment '(' without ')' in " + shown);

  // Parameters, expressions and polar coordinates anywhere on the line,
  // named with the word they sit in ("X#1", "#1=5", "Z[1+2]", "@1^90").
  if (const size_t p = code.find_first_of("#[@^"); p != std::string::npos) {
    if (p > 0 && is_letter(code[p - 1])) refuse(src, code.substr(p - 1, 1) + token_at(code, p));
    refuse(src, token_at(code, p));
  }

  size_t i = 0;
  while (i < code.size()) {
    const char c = code[i];
    if (c == '/' && i == 0) refuse(src, "/" + (code.size() > 1 ? token_at(code, 1) : ""));
    if (c == 'O') refuse(src, token_at(code, i));
    if (!is_letter(c))
      src.fail("cannot read '" + token_at(code, i) + "' in " + shown +
               " (a word is a letter and a number)");
    size_t k = i + 1;
    if (k < code.size() && (code[k] == '+' || code[k] == '-')) ++k;
    size_t digits = 0, dots = 0;
    for (; k < code.size() && (is_digit(code[k]) || code[k] == '.'); ++k) {
      if (code[k] == '.') {
        ++dots;
      } else {
        ++digits;
      }
    }
    if (digits == 0 || dots > 1 || (k < code.size() && !is_letter(code[k]))) {
      if (k == i + 1 && (k >= code.size() || is_letter(code[k])))
        src.fail("letter '" + std::string(1, c) + "' without a number in " + shown);
      src.fail("cannot read '" + token_at(code, i) + "' in " + shown +
               " (a word is a letter and a number)");
    }
    Word w;
    w.letter = c;
    w.text = code.substr(i, k - i);
    w.value = std::strtod(w.text.c_str() + 1, nullptr);
    if (!(std::fabs(w.value) <= kMaxValue))
      src.fail("value of '" + excerpt(w.text, kTokenMax) + "' is beyond +-1e9");
    out.words.push_back(std::move(w));
    i = k;
  }
  return out;
}

}  // namespace hwinterp::gcode
