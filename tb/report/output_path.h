// Output files are checked before a run, so that a long run never loses its
// result to a path that cannot be written at the end.
#pragma once

#include <string>

namespace hwinterp {

// Throws std::runtime_error naming `path` when it could not be written: it
// is a directory, it exists and is not writable, or its directory does not
// exist or is not writable. Creates nothing.
void check_writable(const std::string& path);

}  // namespace hwinterp
