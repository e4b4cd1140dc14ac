// SPDX-License-Identifier: MIT
// A file in a private temporary directory that a fuzz target rewrites with each input, for code
// whose only entry is a path (mesh import through assimp's ReadFile, the replay plugin's `file=`).
// The directory is on /dev/shm when it exists (no disk I/O per input) and is removed at exit.
#pragma once

#include <string>
#include <string_view>

namespace vroc::fuzz {

class ScratchFile {
public:
    /// Creates the directory; the file inside it is `name` (e.g. "input.obj").
    explicit ScratchFile(std::string_view name);
    ~ScratchFile();
    ScratchFile(const ScratchFile&) = delete;
    ScratchFile& operator=(const ScratchFile&) = delete;

    /// Replaces the file's content; traps if it cannot (a broken harness, not a finding).
    void write(const void* data, std::size_t size) const;
    const std::string& path() const { return path_; }
    const std::string& directory() const { return directory_; }

private:
    std::string directory_;
    std::string path_;
};

}  // namespace vroc::fuzz
