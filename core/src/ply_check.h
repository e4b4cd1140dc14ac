// SPDX-License-Identifier: MIT
// A strict check of a PLY file before assimp reads it (internal; mesh_import.cpp).
// assimp 5.2.5 (Debian 12) trusts the file: on a header without end_header it loops without end;
// on a malformed header (a line that is not a PLY keyword, a second `ply` line) it frees memory it
// does not own; on a binary body shorter than its header declares, or a face index beyond the
// vertices, it reads past its buffers (all found by tests/fuzz/mesh_import_fuzz; docs/fuzzing.md).
// Such a file is refused here, with where and what was expected, before assimp sees it.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace vroc {

/// True if the file named `file`, whose bytes are `bytes`, is to be read as PLY: its extension is
/// .ply (any case) or it starts with "ply" (assimp recognises the magic too).
bool isPlyFile(const std::string& file, std::string_view bytes);

/// The first problem of the PLY file whose bytes are `bytes` ("line 3: expected ...",
/// "element `face` #2: ..."), or nothing if it follows the format:
/// - header: `ply`; `format ascii|binary_little_endian|binary_big_endian 1.0`; `comment` and
///   `obj_info` lines; `element NAME COUNT`; `property TYPE NAME` and
///   `property list COUNT_TYPE TYPE NAME` after an element, names unique within it; `end_header`.
///   Printable ASCII (and tabs) only. An element `vertex` with properties x, y and z (the only data
///   a mesh gives the scene).
/// - body: every declared instance present (binary: within the file's bytes; ASCII: one number
///   token per scalar, a list count followed by that many numbers, integers where the type is an
///   integer); list counts not negative; a face's `vertex_indices` (or `vertex_index`) at least 3
///   indices, each naming a declared vertex.
std::optional<std::string> plyProblem(std::string_view bytes);

}  // namespace vroc
