// SPDX-License-Identifier: MIT
// Length-prefixed messages over a pipe between the run pool's dispatcher and its local workers
// (an 8-byte length, then the text), read and written whole across partial reads and EINTR.
#pragma once

#include <string>

namespace vroc::harness::pool_detail {

/// False when the other end is gone (a worker that died shows as a failed write).
bool writeFrame(int fd, const std::string& text);
/// False at the end of the stream or on an error.
bool readFrame(int fd, std::string& text);

}  // namespace vroc::harness::pool_detail
