// run_process.h: run a program (the shadetool binary) from a test and capture what it did.
//
// Inputs:  argv          program and arguments (no shell: no quoting problems with odd names)
//          options       stdin file (default /dev/null), a uid/gid to run as (tests run as root,
//                        where permissions do not stop reading; dropping to `nobody` makes them)
// Output:  exit code (128 + signal number when killed by a signal, kExecFailed when the program
//          could not be started or the uid could not be dropped), stdout and stderr as bytes.
#pragma once

#include <cerrno>
#include <cstdio>
#include <cstddef>
#include <cstdlib>
#include <fcntl.h>
#include <grp.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace shadetool_test {

struct ProcessResult {
  int code = -1;
  std::string out, err;
};

struct ProcessOptions {
  std::string stdin_path = "/dev/null";
  int uid = -1;  // >= 0: setgid(gid) and setuid(uid) in the child before exec
  int gid = -1;
  // > 0: the child's address space is limited to this many MiB (RLIMIT_AS), so that a program
  // that trusts a lying count fails instead of allocating terabytes. Ignored in AddressSanitizer
  // builds, whose shadow memory alone reserves terabytes of address space.
  std::size_t memory_limit_mb = 0;
};

constexpr int kExecFailed = 255;

inline std::string read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

inline ProcessResult run_process(const std::vector<std::string>& argv, const ProcessOptions& options = {}) {
  char out_name[] = "/tmp/shadetool-test-out-XXXXXX";
  char err_name[] = "/tmp/shadetool-test-err-XXXXXX";
  const int out_fd = ::mkstemp(out_name);
  const int err_fd = ::mkstemp(err_name);
  ProcessResult r;
  if (out_fd < 0 || err_fd < 0) return r;
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int in_fd = ::open(options.stdin_path.c_str(), O_RDONLY);
    if (in_fd < 0 || ::dup2(in_fd, 0) < 0 || ::dup2(out_fd, 1) < 0 || ::dup2(err_fd, 2) < 0) ::_exit(kExecFailed);
#if !defined(__SANITIZE_ADDRESS__)
    if (options.memory_limit_mb > 0) {
      const rlim_t bytes = static_cast<rlim_t>(options.memory_limit_mb) << 20;
      const struct rlimit limit = {bytes, bytes};
      if (::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(kExecFailed);
    }
#endif
    if (options.uid >= 0) {
      const gid_t gid = static_cast<gid_t>(options.gid >= 0 ? options.gid : options.uid);
      if (::setgroups(0, nullptr) != 0 || ::setgid(gid) != 0 || ::setuid(static_cast<uid_t>(options.uid)) != 0)
        ::_exit(kExecFailed);
    }
    ::execv(args[0], args.data());
    ::_exit(kExecFailed);
  }
  int status = 0;
  if (pid > 0) ::waitpid(pid, &status, 0);
  ::close(out_fd);
  ::close(err_fd);
  r.code = pid < 0 ? -1 : WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_file(out_name);
  r.err = read_file(err_name);
  ::unlink(out_name);
  ::unlink(err_name);
  return r;
}

// Runs the shadetool binary through /bin/sh: `args` is a shell command-line tail, so it may quote,
// redirect (`< in.obj`, `> out.ply`) and use variables. stdout and stderr are captured as above.
#ifdef SHADETOOL_BIN
inline ProcessResult run_shadetool(const std::string& args, const ProcessOptions& options = {}) {
  return run_process({"/bin/sh", "-c", std::string("'") + SHADETOOL_BIN + "' " + args}, options);
}
#endif

}  // namespace shadetool_test
