// SPDX-License-Identifier: MIT
// Writes the self-contained replay page (docs/viewer.md): three.js r111 from Debian's libjs-three
// and the page's own script inlined, the data embedded as base64 Float32 little-endian, and a
// Content-Security-Policy that forbids every network request.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "vroc/viewer/viewer_data.h"

namespace vroc::viewer {

/// The whole page as text.
std::string viewerPageHtml(const ViewerData& data);

/// Writes viewerPageHtml(data) to `file` atomically (core/recording: nothing half-written is left).
/// Returns the number of bytes written.
std::size_t writeViewerPage(const ViewerData& data, const std::filesystem::path& file);

}  // namespace vroc::viewer
