// command_registry.h: each subcommand registers itself from its own cli/cmd_*.cpp, so adding a
// subcommand touches no shared file.
//
//   RegisterCommand reg("render", HelpSection::Shade, [](CLI::App& app) -> std::function<int()> {
//     auto options = std::make_shared<CommandOptions<RenderCliOptions>>();
//     ... app.add_subcommand("render", ...), flags bound to options->io and options->opt ...
//     return [options] { ... run_command("render", options->io, step, OutputKind::Image); };
//   });
//
// Order in `shadetool --help`: by section (the order a mesh goes through the tool: inspect it, edit
// it, shade it), then by name; no numbers to keep apart. The name must be the subcommand's
// (main checks).
// Options: CLI11 writes a subcommand's flags into the variables they are bound to while parsing,
// and the run function reads them after, so they live in a CommandOptions that the run function
// holds (shared_ptr), not in function-local statics.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "driver.h"

namespace CLI { class App; }

namespace shadetool_cli {

enum class HelpSection { Inspect, Edit, Shade };

struct CommandRegistration {
  std::string name;     // the subcommand's name, as added to the app
  HelpSection section;  // with the name, its position in `shadetool --help`
  // Adds the subcommand to `app` and returns the function to run when it was chosen (exit code).
  std::function<std::function<int()>(CLI::App& app)> add;
};

std::vector<CommandRegistration>& command_registry();

struct RegisterCommand {
  RegisterCommand(std::string name, HelpSection section, std::function<std::function<int()>(CLI::App&)> add) {
    command_registry().push_back({std::move(name), section, std::move(add)});
  }
};

// The variables a subcommand's flags are bound to: the shared ones (driver.h) and its own.
template <class Options>
struct CommandOptions {
  IoOptions io;
  Options opt;
};

}  // namespace shadetool_cli
