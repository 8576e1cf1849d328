#include "tb/report/output_path.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace hwinterp {

namespace {

// The directory part of `path` ("." for a bare name) and the name.
std::pair<std::string, std::string> split_path(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return {".", path};
  return {slash == 0 ? "/" : path.substr(0, slash), path.substr(slash + 1)};
}

}  // namespace

void check_writable(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw std::runtime_error("'" + path + "' is a directory");
    if (access(path.c_str(), W_OK) != 0) throw std::runtime_error("cannot write '" + path + "'");
    return;
  }
  const std::string dir = split_path(path).first;
  if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw std::runtime_error("cannot write '" + path + "': no directory '" + dir + "'");
  if (access(dir.c_str(), W_OK) != 0)
    throw std::runtime_error("cannot write '" + path + "': directory '" + dir +
                             "' is not writable");
}

OutputFiles::OutputFiles() {
  umask_ = umask(0);
  umask(umask_);
}

OutputFiles::~OutputFiles() {
  for (const File& f : files_)
    if (!f.temporary.empty()) std::remove(f.temporary.c_str());
}

OutputFiles::Identity OutputFiles::identity(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) == 0) return {st.st_dev, st.st_ino, ""};
  const auto [dir, name] = split_path(path);
  if (stat(dir.c_str(), &st) == 0) return {st.st_dev, st.st_ino, name};
  return {0, 0, path};  // no directory: stage() refuses it
}

const OutputFiles::File* OutputFiles::same_as(const Identity& id) const {
  for (const File& f : files_)
    if (!f.scratch && f.id == id) return &f;
  return nullptr;
}

void OutputFiles::input(const std::string& what, const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return;
  const Identity id = identity(path);
  if (const File* f = same_as(id); f && f->output)
    throw std::runtime_error("'" + path + "' is both " + what + " and the output " + f->what +
                             ": the run would overwrite what it reads");
  files_.push_back({what, path, "", id, /*output=*/false});
}

std::string OutputFiles::make_temporary(const std::string& path) {
  check_writable(path);
  const auto [dir, name] = split_path(path);
  // Hidden, the file's name last: `.hwinterp-XXXXXX-name`.
  std::string tmpl = (dir == "/" ? "" : dir) + "/.hwinterp-XXXXXX-" + name;
  std::vector<char> buf(tmpl.begin(), tmpl.end());
  buf.push_back('\0');
  const int fd = mkstemps(buf.data(), static_cast<int>(name.size() + 1));
  if (fd < 0)
    throw std::runtime_error("cannot write '" + path + "': no file can be created in '" + dir +
                             "' (" + std::strerror(errno) + ")");
  close(fd);
  return std::string(buf.data());
}

std::string OutputFiles::stage(const std::string& what, const std::string& path) {
  const Identity id = identity(path);
  if (const File* f = same_as(id))
    throw std::runtime_error("'" + path + "' is also " + (f->output ? "the output " : "") +
                             f->what +
                             (f->output ? ": give each output its own file"
                                        : ": the run would overwrite what it reads"));
  File f{what, path, make_temporary(path), id};
  files_.push_back(f);
  return f.temporary;
}

std::string OutputFiles::temporary(const std::string& what) const {
  for (const File& f : files_)
    if (f.output && !f.scratch && f.what == what) return f.temporary;
  return "";
}

std::string OutputFiles::scratch(const std::string& path) {
  File f{"", path, make_temporary(path), identity(path), /*output=*/false, /*scratch=*/true};
  files_.push_back(f);
  return f.temporary;
}

void OutputFiles::discard(const std::string& what) {
  for (File& f : files_)
    if (f.output && !f.scratch && f.what == what && !f.temporary.empty()) {
      std::remove(f.temporary.c_str());
      f.temporary.clear();
    }
}

void OutputFiles::commit() {
  std::string first_error;
  for (File& f : files_) {
    if (!f.output || f.scratch || f.temporary.empty()) continue;
    struct stat st {};
    const mode_t mode = stat(f.path.c_str(), &st) == 0 ? (st.st_mode & 07777) : (0666 & ~umask_);
    chmod(f.temporary.c_str(), mode);
    if (std::rename(f.temporary.c_str(), f.path.c_str()) != 0) {
      if (first_error.empty())
        first_error = f.what + ": cannot write '" + f.path + "' (" + std::strerror(errno) +
                      "); the output is left in '" + f.temporary + "'";
    }
    f.temporary.clear();  // renamed, or kept where the message says: the result is not lost
  }
  if (!first_error.empty()) throw std::runtime_error(first_error);
}

}  // namespace hwinterp
