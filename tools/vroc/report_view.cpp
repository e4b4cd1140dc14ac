// SPDX-License-Identifier: MIT
#include "report_view.h"

#include <cstdio>
#include <exception>

#include "vroc/viewer/viewer_inputs.h"
#include "vroc/viewer/viewer_page.h"

namespace vroc::cli {

void writeReportView(const std::filesystem::path& out, const std::string& command, bool quiet, bool penetration) {
    try {
        viewer::ViewerOptions options;
        options.max_members = 4;  // an ensemble's replay costs a share of its run time: `vroc view` shows more
        options.penetration = penetration;
        options.penetration_max_bodies = 100;  // the highlight's cost grows as N^2: `vroc view` does up to 500
        viewer::ViewerData data = viewer::loadViewerData({out}, options);
        if (!penetration)
            data.notes.push_back("penetration not highlighted (vroc " + command +
                                 " skips it: --view-penetration, or vroc view of this directory, computes it)");
        const std::size_t bytes = viewer::writeViewerPage(data, out / "view.html");
        if (!quiet)
            std::printf("vroc %s: 3D view %s (%.1f MB)\n", command.c_str(), (out / "view.html").string().c_str(),
                        double(bytes) / 1e6);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vroc %s: no 3D view: %s\n", command.c_str(), e.what());
    }
}

}  // namespace vroc::cli
