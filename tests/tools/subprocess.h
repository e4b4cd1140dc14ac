// SPDX-License-Identifier: MIT
// Runs the built `vroc` program as a subprocess and captures its exit code, stdout and stderr.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "csv_reader.h"
#include "vroc/core/subprocess.h"

namespace vroc::test {

struct ProcessResult {
    int exit_code = -1;   ///< 128 + the signal number if a signal ended it
    std::string out;
    std::string err;
};

inline std::string vrocBinary() { return std::string(VROC_BINARY_DIR) + "/bin/vroc"; }

/// `vroc args...` as an argument vector.
inline std::vector<std::string> vrocCommand(const std::vector<std::string>& args) {
    std::vector<std::string> argv{vrocBinary()};
    argv.insert(argv.end(), args.begin(), args.end());
    return argv;
}

/// Runs `vroc args...` with stdout and stderr redirected to files (so stderr is not a terminal),
/// in working directory `cwd`.
inline ProcessResult runVroc(const std::vector<std::string>& args, const std::filesystem::path& cwd) {
    SpawnOptions options;
    options.stdout_file = cwd / ".vroc-test-stdout";
    options.stderr_file = cwd / ".vroc-test-stderr";
    options.working_directory = cwd;
    ProcessResult result;
    result.exit_code = runProcess(vrocCommand(args), options);
    result.out = readText(options.stdout_file.string());
    result.err = readText(options.stderr_file.string());
    std::filesystem::remove(options.stdout_file);
    std::filesystem::remove(options.stderr_file);
    return result;
}

}  // namespace vroc::test
