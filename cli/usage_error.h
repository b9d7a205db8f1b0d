// usage_error.h: a command-line mistake found after parsing (conflicting options): exit code 2.
#pragma once

#include <stdexcept>
#include <string>

namespace shadetool_cli {

class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& m) : std::runtime_error(m) {}
};

}  // namespace shadetool_cli
