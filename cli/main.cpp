// main.cpp: `shadetool SUBCOMMAND ...`. Parses, dispatches, maps errors onto exit codes:
// 0 success, 1 bad input or processing error, 2 usage error (CLI11's own codes are mapped to 2).
#include <algorithm>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <tuple>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "command_registry.h"
#include "driver.h"
#include "usage_error.h"

namespace shadetool_cli {
std::vector<CommandRegistration>& command_registry() {
  static std::vector<CommandRegistration> registry;
  return registry;
}
}  // namespace shadetool_cli

int main(int argc, char** argv) {
  using namespace shadetool_cli;
  CLI::App app{"shadetool: mesh normals, repair, transforms and baked lighting"};
  app.name("shadetool");
  app.set_version_flag("--version", "shadetool 0.1.0");
  app.require_subcommand(1);
  app.failure_message(CLI::FailureMessage::simple);

  auto& registry = command_registry();
  std::sort(registry.begin(), registry.end(),
            [](auto& a, auto& b) { return std::tie(a.section, a.name) < std::tie(b.section, b.name); });
  std::vector<std::pair<CLI::App*, std::function<int()>>> runners;
  for (auto& reg : registry) {
    const std::size_t before = app.get_subcommands({}).size();
    auto run = reg.add(app);
    auto subs = app.get_subcommands({});
    if (subs.size() != before + 1 || subs.back()->get_name() != reg.name)
      throw std::logic_error("command registration \"" + reg.name + "\" did not add that one subcommand");
    runners.emplace_back(subs.back(), std::move(run));
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {  // --help: the help on stdout, exit 0
    app.exit(e);
    return kExitOk;
  } catch (const CLI::CallForAllHelp& e) {
    app.exit(e);
    return kExitOk;
  } catch (const CLI::CallForVersion& e) {
    app.exit(e);
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "shadetool: {}\n", e.what());
    fmt::print(stderr, "Run 'shadetool --help' for usage.\n");
    return kExitUsage;
  }

  try {
    for (auto& [sub, run] : runners)
      if (sub->parsed()) return run();
  } catch (const UsageError& e) {
    fmt::print(stderr, "shadetool: {}\n", e.what());
    return kExitUsage;
  } catch (const std::exception& e) {
    fmt::print(stderr, "shadetool: {}\n", e.what());
    return kExitFailure;
  }
  return kExitUsage;
}
