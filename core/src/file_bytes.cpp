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

bool fileStartsWith(const std::string& file, std::string_view magic) {
    std::ifstream in(file, std::ios::binary);
    std::string head(magic.size(), '\0');
    return in.read(head.data(), static_cast<std::streamsize>(head.size())) && head == magic;
}

}  // namespace vroc
