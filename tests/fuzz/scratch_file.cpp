// SPDX-License-Identifier: MIT
#include "scratch_file.h"

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <system_error>
#include <vector>

#include "fuzz_require.h"

namespace vroc::fuzz {

ScratchFile::ScratchFile(std::string_view name) {
    std::error_code ec;
    const std::string base = std::filesystem::is_directory("/dev/shm", ec)
                                 ? std::string("/dev/shm")
                                 : std::filesystem::temp_directory_path().string();
    std::vector<char> pattern(base.begin(), base.end());
    const std::string suffix = "/vroc-fuzz-XXXXXX";
    pattern.insert(pattern.end(), suffix.begin(), suffix.end());
    pattern.push_back('\0');
    VROC_FUZZ_REQUIRE(mkdtemp(pattern.data()) != nullptr);
    directory_ = pattern.data();
    path_ = directory_ + "/" + std::string(name);
}

ScratchFile::~ScratchFile() {
    std::error_code ec;
    std::filesystem::remove_all(directory_, ec);
}

void ScratchFile::write(const void* data, std::size_t size) const {
    const int fd = open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    VROC_FUZZ_REQUIRE(fd >= 0);
    const char* bytes = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t n = ::write(fd, bytes, size);
        VROC_FUZZ_REQUIRE(n > 0);
        bytes += n;
        size -= static_cast<std::size_t>(n);
    }
    VROC_FUZZ_REQUIRE(close(fd) == 0);
}

}  // namespace vroc::fuzz
