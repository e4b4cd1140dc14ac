// SPDX-License-Identifier: MIT
// Fast, exact CSV formatting shared by the recording writers (internal to core).
#pragma once

#include <charconv>
#include <string>
#include <string_view>

namespace vroc::recording::detail {

/// Appends `value` as printf("%.17g") would (round-trip exact), without locale or iostreams.
inline void appendNumber(std::string& out, double value) {
    char buf[32];
    auto result = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::general, 17);
    out.append(buf, result.ptr);
}

/// A CSV field: as is, or quoted (RFC 4180) when it holds a comma, quote or line break.
inline std::string csvField(std::string_view text) {
    if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
    std::string out = "\"";
    for (char c : text) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + '"';
}

/// Buffered writers hand text to their sink in blocks of about this size.
inline constexpr std::size_t kFlushBytes = 1 << 16;

}  // namespace vroc::recording::detail
