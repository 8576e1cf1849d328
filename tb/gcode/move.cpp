#include "tb/gcode/move.h"

namespace hwinterp::gcode {

const char* to_string(MoveKind k) {
  switch (k) {
    case MoveKind::kTraverse:
      return "traverse";
    case MoveKind::kFeed:
      return "feed";
    case MoveKind::kArc:
      return "arc";
  }
  return "?";
}

const char* to_string(Plane p) {
  switch (p) {
    case Plane::kXY:
      return "XY";
    case Plane::kYZ:
      return "YZ";
    case Plane::kXZ:
      return "XZ";
  }
  return "?";
}

void ReaderStats::count(const Move& m) {
  switch (m.kind) {
    case MoveKind::kTraverse:
      ++traverses;
      break;
    case MoveKind::kFeed:
      ++feeds;
      break;
    case MoveKind::kArc:
      ++arcs;
      break;
  }
}

}  // namespace hwinterp::gcode
