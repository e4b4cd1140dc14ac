// SPDX-License-Identifier: MIT
#include "engine_tints.h"

#include <map>

namespace vroc::viewer {

std::string engineKey(const ViewerRun& run) { return run.member < 0 ? "run:" + run.label : "ensemble:" + run.backend; }

void assignEngineTints(std::vector<ViewerRun>& runs, std::vector<std::string>& notes) {
    std::map<std::string, std::size_t> order;  // engine key -> index of first appearance
    for (ViewerRun& run : runs) {
        const std::size_t engine = order.try_emplace(engineKey(run), order.size()).first->second;
        run.tint = kEngineTints[engine % kEngineTints.size()];
    }
    if (order.size() > kEngineTints.size())
        notes.push_back(std::to_string(order.size()) + " engines, " + std::to_string(kEngineTints.size()) +
                        " tints: from the " + std::to_string(kEngineTints.size() + 1) +
                        "th engine on the tints repeat (the views' labels tell them apart)");
}

}  // namespace vroc::viewer
