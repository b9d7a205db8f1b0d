// error.h: the one exception type the library throws for bad input or failed processing.
//
// The message is already in the user-facing form `FILE:LINE: what is wrong` (or `FILE: what`
// when there is no line), so the CLI prints `shadetool: ` + what() and exits 1.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// Builds `file:line: what` (line 0 means "no line": `file: what`).
inline std::string located(const std::string& file, std::size_t line, const std::string& what) {
  std::string s = file.empty() ? std::string("<input>") : file;
  if (line > 0) s += ":" + std::to_string(line);
  s += ": ";
  s += what;
  return s;
}

[[noreturn]] inline void fail(const std::string& file, std::size_t line, const std::string& what) {
  throw Error(located(file, line, what));
}

}  // namespace shadetool
#pragma GCC visibility pop
