// main.cpp: `shadetool SUBCOMMAND ...`. Parses, dispatches, maps errors onto exit codes:
// 0 success, 1 bad input or processing error, 2 usage error (CLI11's own codes are mapped to 2).
#include <algorithm>
#include <cctype>
#include <string>
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
    // Within a subcommand: an unknown flag is named first (CLI11 would report a missing input
    // before it), and the usage shown is the subcommand's, not the top level's.
    CLI::App* sub = nullptr;
    for (auto& entry : runners)
      if (entry.first->parsed()) sub = entry.first;
    std::string message = e.what();
    if (sub) {
      for (int i = 2; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--") break;
        const bool number = arg.size() > 1 && (std::isdigit(static_cast<unsigned char>(arg[1])) || arg[1] == '.');
        if (arg.size() < 2 || arg[0] != '-' || number) continue;
        const std::string name = arg.substr(0, arg.find('='));
        if (name.rfind("--", 0) == 0 ? sub->get_option_no_throw(name) == nullptr
                                     : sub->get_option_no_throw(name.substr(0, 2)) == nullptr) {
          message = "unknown option '" + name + "' for '" + sub->get_name() + "'";
          break;
        }
      }
    }
    fmt::print(stderr, "shadetool: {}\n", message);
    if (sub) {
      const std::string help = sub->help();
      const std::size_t at = help.find("Usage:");
      if (at != std::string::npos) {
        std::string usage = help.substr(at, help.find('\n', at) - at);  // "Usage: NAME [OPTIONS] ..."
        if (usage.rfind("Usage: shadetool ", 0) != 0) usage.insert(7, "shadetool ");
        fmt::print(stderr, "{}\n", usage);
      }
      fmt::print(stderr, "Run 'shadetool {} --help' for its options.\n", sub->get_name());
    } else {
      fmt::print(stderr, "Run 'shadetool --help' for usage.\n");
    }
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
