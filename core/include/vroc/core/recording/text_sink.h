// SPDX-License-Identifier: MIT
// Where the recording writers put their text: a file being written atomically, or a string in tests.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace vroc::recording {

/// Buffered writers hand text to their sink in blocks of about this size.
inline constexpr std::size_t kFlushBytes = 1 << 16;

class TextSink {
public:
    virtual ~TextSink() = default;
    /// Appends bytes. Throws RunError on I/O failure.
    virtual void write(std::string_view bytes) = 0;
};

/// Collects everything in memory (tests, small outputs).
class StringSink final : public TextSink {
public:
    void write(std::string_view bytes) override { text.append(bytes); }
    std::string text;
};

}  // namespace vroc::recording
