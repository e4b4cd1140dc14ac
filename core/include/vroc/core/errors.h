// SPDX-License-Identifier: MIT
// Error types shared by every layer. The command line maps them to exit codes:
// InputError -> 2 (bad input or usage), RunError -> 3 (failure while running).
#pragma once

#include <stdexcept>
#include <string>

namespace vroc {

/// Bad user input: scene file, setting, option, plugin. The message is one line that names the
/// file (and JSON path or line where known) and says what was expected.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Failure while running (I/O after start, unrecoverable numerical state).
struct RunError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Degenerate geometry (e.g. a hull of coplanar points). Loaders rethrow it as InputError with context.
struct GeometryError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace vroc
