// SPDX-License-Identifier: MIT
#include "pipe_frames.h"

#include <cerrno>
#include <cstdint>
#include <unistd.h>

namespace vroc::harness::pool_detail {
namespace {

bool writeAll(int fd, const char* data, std::size_t n) {
    while (n > 0) {
        const ssize_t k = write(fd, data, n);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return false;
        data += k;
        n -= static_cast<std::size_t>(k);
    }
    return true;
}

bool readAll(int fd, char* data, std::size_t n) {
    while (n > 0) {
        const ssize_t k = read(fd, data, n);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return false;
        data += k;
        n -= static_cast<std::size_t>(k);
    }
    return true;
}

}  // namespace

bool writeFrame(int fd, const std::string& text) {
    const std::uint64_t n = text.size();
    return writeAll(fd, reinterpret_cast<const char*>(&n), sizeof n) && writeAll(fd, text.data(), text.size());
}

bool readFrame(int fd, std::string& text) {
    std::uint64_t n = 0;
    if (!readAll(fd, reinterpret_cast<char*>(&n), sizeof n)) return false;
    text.assign(n, '\0');
    return readAll(fd, text.data(), n);
}

}  // namespace vroc::harness::pool_detail
