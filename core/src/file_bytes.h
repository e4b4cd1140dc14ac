// SPDX-License-Identifier: MIT
// Whole files as bytes (internal; the scene loader and the mesh import read a file once).
#pragma once

#include <optional>
#include <string>

namespace vroc {

/// Every byte of `file`, or nothing if it cannot be opened or read to its end.
std::optional<std::string> fileBytes(const std::string& file);

}  // namespace vroc
