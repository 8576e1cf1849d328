#include "tb/report/output_path.h"

#include <sys/stat.h>
#include <unistd.h>

#include <stdexcept>

namespace hwinterp {

void check_writable(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw std::runtime_error("'" + path + "' is a directory");
    if (access(path.c_str(), W_OK) != 0) throw std::runtime_error("cannot write '" + path + "'");
    return;
  }
  const auto slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "."
                          : slash == 0               ? "/"
                                                     : path.substr(0, slash);
  if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw std::runtime_error("cannot write '" + path + "': no directory '" + dir + "'");
  if (access(dir.c_str(), W_OK) != 0)
    throw std::runtime_error("cannot write '" + path + "': directory '" + dir +
                             "' is not writable");
}

}  // namespace hwinterp
