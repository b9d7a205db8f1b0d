// command_registry.h: each subcommand registers itself from its own cli/cmd_*.cpp, so adding a
// subcommand touches no shared file.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace CLI { class App; }

namespace shadetool_cli {

struct CommandRegistration {
  int order;  // position in `shadetool --help`
  // Adds the subcommand to `app` and returns the function to run when it was chosen (exit code).
  std::function<std::function<int()>(CLI::App& app)> add;
};

std::vector<CommandRegistration>& command_registry();

struct RegisterCommand {
  RegisterCommand(int order, std::function<std::function<int()>(CLI::App&)> add) {
    command_registry().push_back({order, std::move(add)});
  }
};

}  // namespace shadetool_cli
