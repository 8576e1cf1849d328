#include "tb/gcode/ngc_reader.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include "tb/gcode/arc_rules.h"
#include "tb/gcode/ngc_lexer.h"

namespace hwinterp::gcode {

namespace {

// One word of a modal group on a line (LinuxCNC refuses two).
struct Slot {
  int code = -1;  // G code x 10, or the M number
  std::string word;
  bool given() const { return code != -1; }
};

std::string fmt(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

bool has_sign(const Word& w) { return w.text.size() > 1 && (w.text[1] == '+' || w.text[1] == '-'); }

}  // namespace

// The words of one line, sorted by what they do.
struct NgcReader::Block {
  std::string shown;  // the line, for messages
  std::array<std::optional<double>, 6> axis;
  std::optional<double> i, j, k, r, p, q, f, s, t;
  std::array<std::string, 26> text;  // each letter's word as written
  Slot motion, nonmodal, plane, units, distance, arc_distance, feed_mode, cutter_comp, tool_length,
      coord_system, path_control;
  Slot m_stop, m_tool, m_spindle, m_coolant;
  bool n = false;
};

NgcReader::NgcReader(std::istream& in, std::string name)
    : src_(in, std::move(name), kMaxLineChars) {}

bool NgcReader::next(Move& m) {
  std::string line;
  while (!ended_) {
    if (!src_.next(line)) {
      if (percent_)
        src_.fail(
            "the program opened with '%' and ended without the closing '%' "
            "(LinuxCNC refuses it)");
      src_.fail("the program ended without M2, M30 or a closing '%' (LinuxCNC refuses it)");
    }
    ++stats_.lines;
    if (run_line(line, m)) {
      stats_.count(m);
      return true;
    }
  }
  skip_rest();
  return false;
}

void NgcReader::skip_rest() {
  while (src_.skip()) {
    ++stats_.lines;
    ++stats_.lines_after_end;
  }
}

bool NgcReader::run_line(const std::string& line, Move& m) {
  const LexedLine lx = lex_ngc_line(line, src_);
  if (lx.percent) {
    ++stats_.words["%"];
    if (!started_) {
      started_ = percent_ = true;
      return false;
    }
    if (percent_) {
      ended_ = true;
      return false;
    }
    src_.fail("'%' stands only on the program's first line and on the line that closes it");
  }
  if (lx.comments > 0) stats_.words["comment"] += lx.comments;
  if (lx.words.empty() && lx.comments == 0) return false;  // blank
  started_ = true;
  if (lx.words.empty()) return false;

  Block b;
  b.shown = "'" + excerpt(line) + "'";
  const auto fail_word = [&](const Word& w, const std::string& why) {
    src_.fail("'" + w.text + "' " + why + " in " + b.shown);
  };
  const auto refuse = [&](const Word& w) {
    src_.fail(unsupported_word_message(w.text, src_.name()));
  };
  const auto put = [&](Slot& slot, int code, const Word& w) {
    if (slot.given())
      src_.fail("'" + slot.word + "' and '" + w.text +
                "' are of one modal group, on one line, in " + b.shown);
    slot.code = code;
    slot.word = w.text;
  };

  for (size_t idx = 0; idx < lx.words.size(); ++idx) {
    const Word& w = lx.words[idx];
    const int letter = w.letter - 'A';
    if (w.letter != 'G' && w.letter != 'M') {
      if (!b.text[letter].empty())
        src_.fail("two " + std::string(1, w.letter) + " words ('" + b.text[letter] + "' and '" +
                  w.text + "') in " + b.shown);
      b.text[letter] = w.text;
    }
    switch (w.letter) {
      case 'N':
        if (idx != 0)
          fail_word(w, "must be the first word of its line (LinuxCNC refuses it later)");
        if (has_sign(w)) fail_word(w, "is not a line number");
        b.n = true;
        break;
      case 'G': {
        const double tenths = w.value * 10;
        const long code = std::lround(tenths);
        if (has_sign(w) || std::fabs(tenths - static_cast<double>(code)) > 0.001)
          fail_word(w, "is not a G code");
        switch (code) {
          case 0:
          case 10:
          case 20:
          case 30:
          case 800:
            // LinuxCNC ignores a G80 beside another motion word.
            if (code == 800) ++stats_.words["G80"];
            if (code == 800 && b.motion.given()) break;
            if (b.motion.code == 800) b.motion = Slot{};
            put(b.motion, static_cast<int>(code), w);
            break;
          case 40:
            put(b.nonmodal, 40, w);
            break;
          case 170:
          case 180:
          case 190:
            put(b.plane, static_cast<int>(code), w);
            break;
          case 200:
          case 210:
            put(b.units, static_cast<int>(code), w);
            break;
          case 400:
            put(b.cutter_comp, 400, w);
            break;
          case 490:
            put(b.tool_length, 490, w);
            break;
          case 540:
          case 550:
          case 560:
          case 570:
          case 580:
          case 590:
            put(b.coord_system, static_cast<int>(code), w);
            break;
          case 610:
          case 611:
          case 640:
            put(b.path_control, static_cast<int>(code), w);
            break;
          case 900:
          case 910:
            put(b.distance, static_cast<int>(code), w);
            break;
          case 901:
          case 911:
            put(b.arc_distance, static_cast<int>(code), w);
            break;
          case 940:
            put(b.feed_mode, 940, w);
            break;
          default:
            refuse(w);
        }
        break;
      }
      case 'M': {
        const long code = std::lround(w.value);
        if (has_sign(w) || std::fabs(w.value - static_cast<double>(code)) > 0.0001)
          fail_word(w, "is not an M code");
        switch (code) {
          case 0:
          case 1:
          case 2:
          case 30:
            put(b.m_stop, static_cast<int>(code), w);
            break;
          case 6:
            put(b.m_tool, 6, w);
            break;
          case 3:
          case 4:
          case 5:
            put(b.m_spindle, static_cast<int>(code), w);
            break;
          case 7:
          case 8:
          case 9:
            put(b.m_coolant, static_cast<int>(code), w);
            break;
          default:
            refuse(w);
        }
        break;
      }
      case 'X':
      case 'Y':
      case 'Z':
      case 'A':
      case 'B':
      case 'C': {
        static const std::string kOrder = kAxisNames;
        b.axis[kOrder.find(w.letter)] = w.value;
        break;
      }
      case 'I':
        b.i = w.value;
        break;
      case 'J':
        b.j = w.value;
        break;
      case 'K':
        b.k = w.value;
        break;
      case 'R':
        b.r = w.value;
        break;
      case 'P':
        b.p = w.value;
        break;
      case 'Q':
        b.q = w.value;
        break;
      case 'F':
        if (w.value < 0) fail_word(w, "is a negative feed");
        b.f = w.value;
        break;
      case 'S':
        if (w.value < 0) fail_word(w, "is a negative spindle speed");
        b.s = w.value;
        break;
      case 'T':
        if (w.value < 0 || std::fabs(w.value - std::round(w.value)) > 0.0001)
          fail_word(w, "is not a tool number (an integer >= 0)");
        b.t = w.value;
        break;
      default:  // the lexer refuses every other letter
        refuse(w);
    }
  }
  return execute(b, m);
}

bool NgcReader::execute(const Block& b, Move& m) {
  const auto word_of = [&](char letter) { return "'" + b.text[letter - 'A'] + "'"; };
  const auto fail = [&](const std::string& what) { src_.fail(what + " in " + b.shown); };

  // What moves on this line (LinuxCNC's enhance_block).
  bool any_axis = false;
  for (const auto& a : b.axis) any_axis = any_axis || a.has_value();
  const bool any_ijk = b.i || b.j || b.k;
  int motion = -1;
  if (b.motion.given()) {
    if (b.motion.code == 800 && any_axis) fail("axis words with G80");
    motion = b.motion.code;
  } else if (any_axis) {
    if (motion_ == -1)
      fail("axis words without a motion mode (G0, G1, G2 or G3 first; G80 ends the mode)");
    motion = motion_;
  } else if (any_ijk && (motion_ == 20 || motion_ == 30)) {
    motion = motion_;
  }
  const bool is_arc = motion == 20 || motion == 30;
  // Every word must have a use on its line (LinuxCNC's check_items).
  for (const char c : {'I', 'J', 'K', 'R'})
    if (!b.text[c - 'A'].empty() && !is_arc) fail(word_of(c) + " without G2 or G3 to use it");
  if (b.p && !is_arc && b.nonmodal.code != 40 && b.path_control.code != 640)
    fail(word_of('P') + " without G2, G3, G4 or G64 to use it");
  if (b.q && b.path_control.code != 640) fail(word_of('Q') + " without G64 to use it");
  if (b.nonmodal.code == 40 && !b.p) fail("G4 without P (the dwell time)");
  if (b.nonmodal.code == 40 && (b.motion.code == 20 || b.motion.code == 30))
    fail("G4 beside '" + b.motion.word + "' (both would use P)");

  // LinuxCNC's order of execution.
  if (b.n) ++stats_.words["N"];
  if (b.feed_mode.given()) {
    feed_mm_ = 0;  // as LinuxCNC: G94 sets the feed rate to zero
    ++stats_.words["G94"];
  }
  if (b.f) {
    feed_mm_ = *b.f * (inch_ ? kMmPerInch : 1.0);
    ++stats_.words["F"];
  }
  if (b.s) ++stats_.words["S"];
  if (b.t) ++stats_.words["T"];
  for (const Slot* s : {&b.m_tool, &b.m_spindle, &b.m_coolant})
    if (s->given()) ++stats_.words["M" + std::to_string(s->code)];
  if (b.nonmodal.given()) {
    ++stats_.words["G4"];
    ++stats_.words["P"];
  }
  if (b.plane.given())
    plane_ = b.plane.code == 170 ? Plane::kXY : b.plane.code == 190 ? Plane::kYZ : Plane::kXZ;
  if (b.units.given()) {
    const bool inch = b.units.code == 200;
    if (inch != inch_) {
      // As LinuxCNC: the position is converted, the feed stays what it is.
      const double k = inch ? 1.0 / kMmPerInch : kMmPerInch;
      for (int a = kX; a <= kZ; ++a) pos_[a] *= k;
      inch_ = inch;
    }
  }
  if (b.cutter_comp.given()) ++stats_.words["G40"];
  if (b.tool_length.given()) ++stats_.words["G49"];
  if (b.coord_system.given()) ++stats_.words["G" + std::to_string(b.coord_system.code / 10)];
  if (b.path_control.given()) {
    const int c = b.path_control.code;
    ++stats_.words[c == 611 ? "G61.1" : "G" + std::to_string(c / 10)];
    if (c == 640 && b.p && !is_arc) ++stats_.words["P"];
    if (b.q) ++stats_.words["Q"];
  }
  if (b.distance.given()) absolute_ = b.distance.code == 900;
  if (b.arc_distance.given()) arc_absolute_ = b.arc_distance.code == 901;

  bool moved = false;
  if (motion == 800) {
    motion_ = -1;
  } else if (motion != -1) {
    motion_ = motion;
    std::array<double, 6> end = pos_;
    for (int a = 0; a < kAxes; ++a)
      if (b.axis[a]) end[a] = absolute_ ? *b.axis[a] : pos_[a] + *b.axis[a];
    m = Move{};
    if (motion == 0) {
      m.kind = MoveKind::kTraverse;
    } else if (motion == 10) {
      if (feed_mm_ == 0) fail("G1 with a zero feed rate (no F word yet)");
      m.kind = MoveKind::kFeed;
    } else {
      if (feed_mm_ == 0) fail("an arc with a zero feed rate (no F word yet)");
      arc(b, motion == 20, end, m);
    }
    m.end = end;
    m.stop_before = stop_pending_;
    stop_pending_ = false;
    pos_ = end;
    finish(m);
    moved = true;
  }

  if (b.m_stop.given()) {
    ++stats_.words["M" + std::to_string(b.m_stop.code)];
    if (b.m_stop.code == 2 || b.m_stop.code == 30) ended_ = true;
    if (b.m_stop.code == 0 || b.m_stop.code == 1) stop_pending_ = true;  // after this line's move
  }
  return moved;
}

void NgcReader::arc(const Block& b, bool clockwise, const std::array<double, 6>& end, Move& m) {
  const auto fail = [&](const std::string& what) { src_.fail(what + " in " + b.shown); };
  const PlaneAxes pa = plane_axes(plane_);
  // The plane's centre words in canon order, and the one it has no use for.
  const char kLetters[3] = {'I', 'J', 'K'};  // offsets along X, Y, Z
  const char l1 = kLetters[pa.first], l2 = kLetters[pa.second], other = kLetters[pa.third];
  const std::array<const std::optional<double>*, 3> ijk = {&b.i, &b.j, &b.k};
  const std::optional<double>& o1 = *ijk[pa.first];
  const std::optional<double>& o2 = *ijk[pa.second];
  const std::string unit = inch_ ? " in" : " mm";
  if (ijk[pa.third]->has_value())
    fail("'" + b.text[other - 'A'] + "' for an arc in the " + to_string(plane_) + " plane");
  if (b.r && (o1 || o2)) fail("R together with " + std::string(1, l1) + "/" + l2 + " on one arc");
  if (!b.r && !o1 && !o2)
    fail(std::string("an arc without its centre: R or ") + l1 + "/" + l2 + " needed");

  int turns = 1;
  if (b.p) {
    turns = static_cast<int>(std::floor(*b.p + 0.5));
    if (std::fabs(*b.p - turns) > 0.001)
      fail("'" + b.text['P' - 'A'] + "' is not a whole number of turns");
    if (turns < 1) fail("'" + b.text['P' - 'A'] + "': an arc needs P >= 1");
  }

  const ArcTolerance tol = linuxcnc_arc_tolerance(inch_);
  const double s1 = pos_[pa.first], s2 = pos_[pa.second];
  const double e1 = end[pa.first], e2 = end[pa.second];
  double c1 = 0, c2 = 0;
  if (b.r) {
    if (*b.r == 0) fail("a zero-radius arc ('" + b.text['R' - 'A'] + "')");
    const RadiusCenter rc = center_from_radius(s1, s2, e1, e2, *b.r, clockwise, tol);
    if (rc.verdict == RadiusCenter::kSamePoint)
      fail("an R arc that ends where it starts (a full circle needs " + std::string(1, l1) + "/" +
           l2 + ")");
    if (rc.verdict == RadiusCenter::kTooSmall)
      fail("radius '" + b.text['R' - 'A'] + "' too small to reach the end (half the chord is " +
           fmt(rc.half_chord) + unit + ")");
    c1 = rc.c1;
    c2 = rc.c2;
  } else {
    if (arc_absolute_) {
      if (!o1 || !o2)
        fail(std::string("an absolute centre (G90.1) without both ") + l1 + " and " + l2);
      c1 = *o1;
      c2 = *o2;
    } else {
      c1 = s1 + o1.value_or(0.0);
      c2 = s2 + o2.value_or(0.0);
    }
    const CenterCheck cc = check_center_arc(s1, s2, e1, e2, c1, c2, tol);
    if (cc.verdict == CenterCheck::kZeroRadius)
      fail("a zero-radius arc (radius " + fmt(cc.r_start) + unit + " to the start, " +
           fmt(cc.r_end) + unit + " to the end; LinuxCNC's minimum is " + fmt(tol.radius) + unit +
           ")");
    if (cc.verdict == CenterCheck::kOffCircle) {
      char buf[320];
      std::snprintf(buf, sizeof buf,
                    "the arc's end is off its circle (radius %.4f%s to the start, %.4f%s to "
                    "the end: %.4g%s, %.4f %%; LinuxCNC allows %.4f%s, or %.4f%s within %.1f %%)",
                    cc.r_start, unit.c_str(), cc.r_end, unit.c_str(), cc.abs_err, unit.c_str(),
                    100 * cc.rel_err, tol.spiral_abs, unit.c_str(), 100 * tol.spiral_abs,
                    unit.c_str(), 100 * tol.spiral_rel);
      fail(buf);
    }
  }
  m.kind = MoveKind::kArc;
  m.center = {c1, c2};
  m.rotation = clockwise ? -turns : turns;
}

void NgcReader::finish(Move& m) const {
  const double k = inch_ ? kMmPerInch : 1.0;
  for (int a = kX; a <= kZ; ++a) m.end[a] *= k;
  if (m.kind == MoveKind::kArc) {
    m.center[0] *= k;
    m.center[1] *= k;
  }
  m.plane = plane_;
  m.feed = feed_mm_;
  m.line = src_.line_number();
}

}  // namespace hwinterp::gcode
