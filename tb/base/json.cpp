#include "tb/base/json.h"

#include <fstream>
#include <stdexcept>

namespace hwinterp {

std::string dump_json(const Json& j) {
  return j.dump(2, ' ', false, Json::error_handler_t::replace);
}

void write_json_file(const std::string& path, const Json& j) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write '" + path + "'");
  out << dump_json(j) << '\n';
  out.close();
  if (!out) throw std::runtime_error("error writing '" + path + "'");
}

}  // namespace hwinterp
