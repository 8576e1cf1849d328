// Runs a helper program with an argument vector: no shell, so no file name
// (quotes, semicolons, spaces, $(...), newlines) is ever read as a command.
#pragma once

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

extern char** environ;

namespace hwinterp {

// Runs argv[0] (looked up on PATH when it has no '/') with argv, standard
// output to /dev/null when quiet, standard error inherited; waits for it.
// Returns its exit status, or -1 when it could not be started or was ended
// by a signal (*why says which).
inline int spawn_and_wait(const std::vector<std::string>& argv, bool quiet, std::string* why) {
  if (argv.empty()) {
    if (why) *why = "no program";
    return -1;
  }
  std::vector<char*> cargv;
  cargv.reserve(argv.size() + 1);
  for (const std::string& a : argv) cargv.push_back(const_cast<char*>(a.c_str()));
  cargv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet) posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, cargv[0], &actions, nullptr, cargv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    if (why) *why = "cannot start " + argv[0] + ": " + std::strerror(rc);
    return -1;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      if (why) *why = std::string("waitpid: ") + std::strerror(errno);
      return -1;
    }
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (why) *why = argv[0] + " ended by signal " + std::to_string(WTERMSIG(status));
  return -1;
}

// argv quoted as a POSIX shell would read it back: for messages only, never
// executed.
inline std::string quoted_command(const std::vector<std::string>& argv) {
  std::string out;
  for (const std::string& a : argv) {
    if (!out.empty()) out += ' ';
    out += '\'';
    for (char c : a) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    out += '\'';
  }
  return out;
}

}  // namespace hwinterp
