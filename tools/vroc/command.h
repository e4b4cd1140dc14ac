// SPDX-License-Identifier: MIT
// A `vroc` command: one file per command (command_<name>.cpp) defines `Command make<Name>Command()`;
// command_registry.cpp lists them. main() adds each as a CLI11 subcommand and runs the chosen one.
#pragma once

#include <functional>
#include <span>
#include <string>

namespace CLI {
class App;
}

namespace vroc::cli {

/// Facts about this invocation that commands may record.
struct Context {
    std::string command_line;   ///< argv joined with spaces (shell-quoted where needed)
    bool stderr_is_terminal = false;
};

/// Runs the command after parsing; returns the exit code (0 on success). Errors are thrown:
/// InputError -> exit 2 (bad input), RunError or anything else -> exit 3 (failure while running).
using Action = std::function<int()>;

struct Command {
    const char* name;      ///< the subcommand word, e.g. "run"
    const char* summary;   ///< one line for `vroc --help`
    /// Declares the subcommand's options on `sub` (bound to state the action owns) and returns
    /// the action. Called once, before parsing.
    Action (*setup)(CLI::App& sub, const Context& context);
};

/// Every command, in the order `vroc --help` lists them.
std::span<const Command> allCommands();

}  // namespace vroc::cli
