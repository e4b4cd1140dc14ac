// SPDX-License-Identifier: MIT
// Each engine's tint in the page (docs/viewer.md): the one colour its ghosts (the runs overlaid in
// one view), its legend entry and its view's label share. The tints are the Okabe-Ito palette
// (Okabe & Ito 2008, "Color Universal Design", https://jfly.uni-koeln.de/color/), chosen to stay
// apart under the common colour-vision deficiencies; its black is left out (ghosts are lit solids).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "vroc/viewer/viewer_data.h"

namespace vroc::viewer {

/// In the order they are given: blue and orange first (the pair that stays farthest apart under
/// every deficiency), yellow last (faint on the page's light background and near the contact
/// markers' yellow).
inline constexpr std::array<const char*, 7> kEngineTints = {"#0072b2", "#e69f00", "#009e73", "#cc79a7",
                                                            "#56b4e9", "#d55e00", "#f0e442"};

/// What the page shows as one engine (one view): a plain run, by its label ("native", "native (2)"
/// from a second directory), or an ensemble's members on one backend. page/viewer.js groups its
/// views by the same key (buildViews).
std::string engineKey(const ViewerRun& run);

/// Sets every run's tint: engines take kEngineTints in the order they first appear in `runs` (the
/// recording's order), so the same inputs always get the same tints. Past 7 engines the tints
/// repeat, and `notes` says so.
void assignEngineTints(std::vector<ViewerRun>& runs, std::vector<std::string>& notes);

}  // namespace vroc::viewer
