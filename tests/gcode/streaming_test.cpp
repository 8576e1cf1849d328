// Both readers stream: a 100 000-move program goes through while the stream
// is generated a line at a time, and a reader never reads more than the line
// of the move it returns (so memory does not grow with the program).
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <istream>
#include <streambuf>

#include "gcode_test_util.h"

namespace hwinterp::gcode {
namespace {

// A stream whose lines are made on demand by `make(n)` (n from 0; an empty
// optional ends it), counting how many were asked for.
class LineGenerator : public std::streambuf {
 public:
  explicit LineGenerator(std::function<bool(uint64_t, std::string&)> make)
      : make_(std::move(make)) {}
  uint64_t lines_made() const { return made_; }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (!make_(made_, line_)) return traits_type::eof();
    ++made_;
    setg(line_.data(), line_.data(), line_.data() + line_.size());
    return traits_type::to_int_type(*gptr());
  }

 private:
  std::function<bool(uint64_t, std::string&)> make_;
  std::string line_;
  uint64_t made_ = 0;
};

constexpr uint64_t kMoves = 100000;

TEST(Streaming, NgcReaderTakes100000MovesALineAtATime) {
  // Line 0 sets the feed; then feeds and arcs alternate; the last line ends.
  LineGenerator gen([](uint64_t n, std::string& line) {
    if (n == 0) {
      line = "G21 G90 G17 F1000\n";
    } else if (n <= kMoves) {
      // Out along X, and back on a half circle.
      line = n % 2 ? "N" + std::to_string(n) + " G1 X1 Y0\n" : "G3 X0 Y0 I-0.5 J0\n";
    } else if (n == kMoves + 1) {
      line = "M2\n";
    } else {
      return false;
    }
    return true;
  });
  std::istream in(&gen);
  NgcReader r(in, "big.ngc");
  Move m;
  uint64_t count = 0;
  while (r.next(m)) {
    ++count;
    // The move of line k (1-based file line k + 1) was read with nothing after it.
    ASSERT_EQ(m.line, count + 1);
    ASSERT_LE(gen.lines_made(), count + 1);
  }
  EXPECT_EQ(count, kMoves);
  EXPECT_EQ(r.stats().feeds, kMoves / 2);
  EXPECT_EQ(r.stats().arcs, kMoves / 2);
  EXPECT_EQ(m.end[kX], 0);
  EXPECT_EQ(m.center[0], 0.5);
}

TEST(Streaming, CanonReaderTakes100000MovesALineAtATime) {
  LineGenerator gen([](uint64_t n, std::string& line) {
    if (n >= kMoves) return false;
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "%5llu N..... STRAIGHT_FEED(%llu.0000, 1.0000, 2.0000, 0.0000, 0.0000, "
                  "0.0000)\n",
                  static_cast<unsigned long long>(n + 1), static_cast<unsigned long long>(n % 97));
    line = buf;
    return true;
  });
  std::istream in(&gen);
  CanonReader r(in, "big.canon");
  Move m;
  uint64_t count = 0;
  while (r.next(m)) {
    ++count;
    ASSERT_EQ(m.line, count);
    ASSERT_LE(gen.lines_made(), count);
  }
  EXPECT_EQ(count, kMoves);
  EXPECT_EQ(m.end[kX], (kMoves - 1) % 97);
}

}  // namespace
}  // namespace hwinterp::gcode
