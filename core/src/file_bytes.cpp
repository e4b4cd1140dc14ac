// SPDX-License-Identifier: MIT
#include "file_bytes.h"

#include <fstream>
#include <iterator>

namespace vroc {

std::optional<std::string> fileBytes(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in.good() && !in.eof()) return std::nullopt;
    return bytes;
}

}  // namespace vroc
