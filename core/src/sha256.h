// SPDX-License-Identifier: MIT
// SHA-256 through OpenSSL's libcrypto (internal): identifies the exact scene file a run used.
#pragma once

#include <string>
#include <string_view>

namespace vroc {

/// Lower-case hex SHA-256 (64 characters) of the bytes. Throws RunError if libcrypto fails.
std::string sha256Hex(std::string_view bytes);

}  // namespace vroc
