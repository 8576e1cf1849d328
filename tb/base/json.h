// JSON for the reports `hwinterp --json` writes: nlohmann-json (Debian
// nlohmann-json3-dev) with insertion-ordered objects, so reports diff
// cleanly and read in the order they were built.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace hwinterp {

using Json = nlohmann::ordered_json;

// Two-space indented text; bytes that are not UTF-8 (a case name from a job
// file, say) become U+FFFD instead of making the document invalid.
std::string dump_json(const Json& j);

// Writes `j` to `path` with a trailing newline. Throws std::runtime_error
// naming the path when it cannot be written, including a failed flush.
void write_json_file(const std::string& path, const Json& j);

}  // namespace hwinterp
