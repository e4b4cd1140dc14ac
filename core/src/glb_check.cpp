// SPDX-License-Identifier: MIT
#include "glb_check.h"

#include <cstdint>

#include <fmt/format.h>

namespace vroc {

namespace {

constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON", little-endian

std::uint32_t littleEndian32(std::string_view bytes, std::size_t at) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + at);
    return static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
           static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24;
}

}  // namespace

bool isGlbFile(std::string_view bytes) { return bytes.starts_with("glTF"); }

std::optional<std::string> glbProblem(std::string_view bytes) {
    if (bytes.size() < 12) return fmt::format("the file has {} bytes, fewer than a GLB header's 12", bytes.size());
    const std::uint32_t version = littleEndian32(bytes, 4);
    const std::uint32_t length = littleEndian32(bytes, 8);
    if (version != 1 && version != 2) return fmt::format("header version {} (expected 1 or 2)", version);
    if (length > bytes.size())
        return fmt::format("header length {} is more than the file's {} bytes", length, bytes.size());
    if (version == 1) {
        if (length < 20) return fmt::format("header length {} is less than a version 1 header's 20 bytes", length);
        const std::uint32_t content = littleEndian32(bytes, 12);
        if (content > length - 20)
            return fmt::format("content length {} runs past the header length {}", content, length);
        if (littleEndian32(bytes, 16) != 0) return std::string("content format is not 0 (JSON)");
        return std::nullopt;
    }
    std::size_t at = 12;
    for (int chunk = 0; at < length; ++chunk) {
        if (length - at < 8)
            return fmt::format("chunk {}: its 8-byte header runs past the header length {}", chunk, length);
        const std::uint32_t size = littleEndian32(bytes, at);
        if (size > length - at - 8)
            return fmt::format("chunk {}: its length {} runs past the header length {}", chunk, size, length);
        if (chunk == 0 && littleEndian32(bytes, at + 4) != kChunkJson)
            return std::string("chunk 0 is not the JSON chunk");
        at += 8 + static_cast<std::size_t>(size);
    }
    if (at == 12) return std::string("no JSON chunk");
    return std::nullopt;
}

}  // namespace vroc
