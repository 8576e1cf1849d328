// Opens a part-program file as a MoveSource that owns its stream, for the
// command line: `hwinterp gcode FILE.ngc` or `--canon FILE`.
//
// Contract: a file that cannot be opened is a cli::UsageError naming it;
// error messages from the reader name the file as given.
#pragma once

#include <memory>
#include <string>

#include "tb/gcode/move.h"

namespace hwinterp::gcode {

std::unique_ptr<MoveSource> open_ngc(const std::string& path);  // RS274/NGC (ngc_reader.h)
std::unique_ptr<MoveSource> open_canon(
    const std::string& path);  // rs274 -g output (canon_reader.h)

}  // namespace hwinterp::gcode
