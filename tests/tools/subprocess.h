// SPDX-License-Identifier: MIT
// Runs the built `vroc` program as a subprocess and captures its exit code, stdout and stderr.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "csv_reader.h"

namespace vroc::test {

struct ProcessResult {
    int exit_code = -1;   ///< -1 if it did not exit normally (signal)
    std::string out;
    std::string err;
};

inline std::string vrocBinary() { return std::string(VROC_BINARY_DIR) + "/bin/vroc"; }

inline std::string shellQuote(const std::string& word) {
    std::string out = "'";
    for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

/// Runs `vroc args...` with stdout and stderr redirected to files (so stderr is not a terminal),
/// in working directory `cwd`.
inline ProcessResult runVroc(const std::vector<std::string>& args, const std::filesystem::path& cwd) {
    const auto out_file = cwd / ".vroc-test-stdout";
    const auto err_file = cwd / ".vroc-test-stderr";
    std::string command = "cd " + shellQuote(cwd.string()) + " && " + shellQuote(vrocBinary());
    for (const auto& a : args) command += " " + shellQuote(a);
    command += " >" + shellQuote(out_file.string()) + " 2>" + shellQuote(err_file.string()) + " </dev/null";
    const int status = std::system(command.c_str());
    ProcessResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = readText(out_file.string());
    result.err = readText(err_file.string());
    std::filesystem::remove(out_file);
    std::filesystem::remove(err_file);
    return result;
}

}  // namespace vroc::test
