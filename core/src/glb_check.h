// SPDX-License-Identifier: MIT
// A check of a binary glTF (GLB) file's framing before assimp reads it (internal; mesh_import.cpp).
// assimp 5.2.5 (Debian 12) allocates what a GLB header declares before it looks at the file: a
// 164-byte file declaring 895 MB took over 2 GB (found by tests/fuzz/mesh_import_fuzz;
// docs/fuzzing.md). Such a file is refused here, naming the field, before assimp sees it.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace vroc {

/// True if a file's bytes start with the GLB magic "glTF" (assimp picks its binary glTF importers by
/// it, whatever the extension).
bool isGlbFile(std::string_view bytes);

/// The first problem of the GLB framing of a file's bytes, or nothing: a 12-byte header (magic, version 1
/// or 2, total length at most the file's size); version 2: chunks of 8-byte headers whose lengths
/// stay within the total, the first one JSON; version 1: the content length (and its format 0,
/// JSON) within the total.
std::optional<std::string> glbProblem(std::string_view bytes);

}  // namespace vroc
