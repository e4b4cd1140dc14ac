// SPDX-License-Identifier: MIT
#pragma once

namespace vroc::cli {

/// Registers every backend this program was linked with (explicit calls, see tools/CMakeLists.txt).
void registerBackends();

}  // namespace vroc::cli
