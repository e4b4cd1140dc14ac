// SPDX-License-Identifier: MIT
// Whole files as bytes, and their magic numbers (internal; the scene loader and the mesh checks).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace vroc {

/// Every byte of `file`, or nothing if it cannot be opened or read to its end.
std::optional<std::string> fileBytes(const std::string& file);

/// True if `file` can be opened and its first bytes are `magic`.
bool fileStartsWith(const std::string& file, std::string_view magic);

}  // namespace vroc
