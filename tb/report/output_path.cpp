#include "tb/report/output_path.h"

#include <fcntl.h>
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
    if (!f.temporary.empty() && !f.in_place) std::remove(f.temporary.c_str());
}

OutputFiles::Identity OutputFiles::identity(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) == 0) return {st.st_dev, st.st_ino, ""};
  const auto [dir, name] = split_path(path);
  if (stat(dir.c_str(), &st) == 0) return {st.st_dev, st.st_ino, name};
  return {0, 0, path};  // no directory: stage() refuses it
}

OutputFiles::Identity OutputFiles::distinct(const std::string& path) const {
  const Identity id = identity(path);
  if (const File* f = same_as(id))
    throw std::runtime_error("'" + path + "' is also " + (f->output ? "the output " : "") +
                             f->what +
                             (f->output ? ": give each output its own file"
                                        : ": the run would overwrite what it reads"));
  return id;
}

const OutputFiles::File* OutputFiles::same_as(const Identity& id) const {
  for (const File& f : files_)
    if (!f.scratch && f.id == id) return &f;
  return nullptr;
}

void OutputFiles::input(const std::string& what, const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return;  // only files are overwritten
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

bool OutputFiles::written_in_place(const std::string& path) {
  const auto special = [](const std::string& p) {
    return p.rfind("/dev/", 0) == 0 || p.rfind("/proc/", 0) == 0;
  };
  if (special(path)) return true;
  struct stat st {};
  if (lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
    std::vector<char> target(4096);
    const ssize_t n = readlink(path.c_str(), target.data(), target.size() - 1);
    if (n > 0 && special(std::string(target.data(), static_cast<size_t>(n)))) return true;
  }
  return stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

std::string OutputFiles::stage(const std::string& what, const std::string& path) {
  // A device, a pipe, or a name under /dev or /proc (/dev/stdout: renaming
  // onto it would replace the link, and a file behind a descriptor would be
  // left unchanged) is written in place, and is no file another output or an
  // input could be (two outputs to /dev/stdout interleave, as asked).
  struct stat st {};
  if (written_in_place(path)) {
    check_writable(path);
    // Opened for writing now (without truncating; a pipe without a reader is
    // not waited for): root's access() says yes to /proc, open() does not.
    const bool existed = stat(path.c_str(), &st) == 0;
    if (!existed || !S_ISFIFO(st.st_mode)) {
      const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_NONBLOCK, 0666);
      if (fd < 0)
        throw std::runtime_error("cannot write '" + path + "' (" + std::strerror(errno) + ")");
      close(fd);
      if (!existed) std::remove(path.c_str());
    }
    File f{what, path, path, Identity{0, 0, "\n" + path}};
    f.in_place = true;
    files_.push_back(f);
    return path;
  }
  const Identity id = distinct(path);
  // A symbolic link stays: the file it names is replaced.
  std::string target = path;
  if (lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
    if (char* real = realpath(path.c_str(), nullptr)) {
      target = real;
      std::free(real);
    }
  }
  File f{what, target, make_temporary(target), id};
  files_.push_back(f);
  return f.temporary;
}

void OutputFiles::live(const std::string& what, const std::string& path) {
  check_writable(path);
  const Identity id = distinct(path);
  File f{what, path, path, id};
  f.in_place = true;
  files_.push_back(f);
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
      if (!f.in_place) std::remove(f.temporary.c_str());
      f.temporary.clear();
    }
}

void OutputFiles::commit() {
  std::string first_error;
  for (File& f : files_) {
    if (!f.output || f.scratch || f.in_place || f.temporary.empty()) continue;
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
