// SPDX-License-Identifier: MIT
// Base64 (RFC 4648, with padding) and little-endian packing of the page's binary arrays.
#pragma once

#include <string>
#include <string_view>

namespace vroc::viewer {

std::string base64(std::string_view bytes);

/// Appends `value` as 4 bytes of an IEEE-754 single, little-endian whatever the host.
void appendFloat32(std::string& bytes, float value);

}  // namespace vroc::viewer
