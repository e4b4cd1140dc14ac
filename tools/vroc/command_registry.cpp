// SPDX-License-Identifier: MIT
#include "command.h"

// `vroc play` needs the renderer, which a build may leave out (CMake option VROC_BUILD_RENDERER).
#ifdef VROC_WITH_RENDERER
#define VROC_RENDERER_COMMANDS(X) X(Play)
#else
#define VROC_RENDERER_COMMANDS(X)
#endif

// To add a command: write command_<name>.cpp defining `vroc::cli::Command make<Name>Command()`
// and add one line X(<Name>) to this list.
#define VROC_COMMAND_LIST(X) \
    X(Backends)              \
    X(Run)                   \
    X(Compare) X(Check) X(Sweep) X(Ensemble) X(Report) X(View) \
    X(Plugins)               \
    VROC_RENDERER_COMMANDS(X)

namespace vroc::cli {

#define VROC_DECLARE_COMMAND(Name) Command make##Name##Command();
VROC_COMMAND_LIST(VROC_DECLARE_COMMAND)
#undef VROC_DECLARE_COMMAND

std::span<const Command> allCommands() {
#define VROC_LIST_COMMAND(Name) make##Name##Command(),
    static const Command commands[] = {VROC_COMMAND_LIST(VROC_LIST_COMMAND)};
#undef VROC_LIST_COMMAND
    return commands;
}

}  // namespace vroc::cli
