// Output files are checked before a run and written safely: to a temporary
// file beside each, renamed into place only when the run completes, so that
// a refused or failed run leaves every existing file as it was and a long run
// never loses its result to a path that cannot be written at the end.
#pragma once

#include <sys/types.h>

#include <map>
#include <string>
#include <vector>

namespace hwinterp {

// Throws std::runtime_error naming `path` when it could not be written: it
// is a directory, it exists and is not writable, or its directory does not
// exist or is not writable. Creates nothing.
void check_writable(const std::string& path);

// A run's output files and the input files they must not overwrite.
// Contract: stage() every output before the run (the run writes the path it
// returns), commit() after the run completed; every temporary not committed
// is removed when the object goes (a refused run, an exception).
class OutputFiles {
 public:
  OutputFiles();
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  // `path`, named `what` in messages (an option, "the program"), is read by
  // the run. Throws std::runtime_error when it is the same file as a staged
  // output. A path that does not exist is not an input (its reader says so).
  void input(const std::string& what, const std::string& path);

  // Stages `path` as the output `what`: throws std::runtime_error naming
  // both when it is a directory, exists and is not writable, is the same
  // file as an input or another output (device and inode; a file not there
  // yet by its directory's device and inode and its name), or when no file
  // can be created in its directory. Creates the temporary file beside it
  // (hidden, its name ending in the file's name, so the extension stays) and
  // returns its path: the run writes there. A path that exists and is not a
  // regular file (/dev/stdout, a pipe, a device) is returned as it is: the
  // run writes to it directly, nothing is renamed onto it.
  std::string stage(const std::string& what, const std::string& path);

  // Registers `path` as the output `what` that the run writes in place while
  // others read it (board-sim's URI file and logs): throws as stage does when
  // it is the same file as an input or another output, or cannot be written.
  void live(const std::string& what, const std::string& path);

  // The temporary of the output `what` (as stage returned it); "" if none.
  std::string temporary(const std::string& what) const;

  // A temporary file beside `path` for the run's own use (a plot's data):
  // removed at the end, never committed. Throws as stage does.
  std::string scratch(const std::string& path);

  // The output `what` will not be committed (its writer failed): its
  // temporary is removed, its file left as it was.
  void discard(const std::string& what);

  // Renames every staged output into place, with the mode the file had (a
  // new file: 0666 less the umask). Throws std::runtime_error naming the
  // first that fails; the others are still renamed.
  void commit();

 private:
  struct Identity {
    dev_t dev = 0;
    ino_t ino = 0;
    std::string name;  // a file not there yet: its name in the directory (dev, ino)
    bool operator==(const Identity& o) const {
      return dev == o.dev && ino == o.ino && name == o.name;
    }
  };
  struct File {
    std::string what, path, temporary;
    Identity id;
    bool output = true;  // else an input
    bool scratch = false;
    bool in_place = false;  // not a regular file (a device, a pipe): written directly
  };
  static Identity identity(const std::string& path);
  // A path the run must write directly: a device, a pipe, a name under /dev
  // or /proc, or a symbolic link into them.
  static bool written_in_place(const std::string& path);
  std::string make_temporary(const std::string& path);
  const File* same_as(const Identity& id) const;
  // The identity of `path`, an output to be; throws naming the file it would be the same as.
  Identity distinct(const std::string& path) const;

  std::vector<File> files_;
  mode_t umask_ = 022;
};

}  // namespace hwinterp
