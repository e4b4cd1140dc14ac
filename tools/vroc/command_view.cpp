// SPDX-License-Identifier: MIT
// `vroc view DIR... -o view.html`: the self-contained 3D replay page of earlier runs (docs/viewer.md).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "command.h"
#include "vroc/viewer/viewer_inputs.h"
#include "vroc/viewer/viewer_page.h"

namespace vroc::cli {
namespace {

struct ViewArgs {
    std::vector<std::string> dirs;
    std::string out = "view.html";
    viewer::ViewerOptions options;
    bool no_penetration = false;
};

int view(ViewArgs& a) {
    const auto start = std::chrono::steady_clock::now();
    a.options.penetration = !a.no_penetration;
    const viewer::ViewerData data = viewer::loadViewerData({a.dirs.begin(), a.dirs.end()}, a.options);
    const std::size_t bytes = viewer::writeViewerPage(data, a.out);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("vroc view: %s (%zu bodies, %zu frames, %zu runs, %.1f MB, %.1f s)\n",
                std::filesystem::absolute(a.out).lexically_normal().string().c_str(), data.bodies.size(),
                data.times.size(), data.runs.size(), double(bytes) / 1e6, seconds);
    for (const std::string& note : data.notes) std::printf("  note: %s\n", note.c_str());
    return 0;
}

Action setupView(CLI::App& sub, const Context&) {
    auto a = std::make_shared<ViewArgs>();
    sub.add_option("dirs", a->dirs, "Output directories of vroc run, compare or ensemble (one scene)")->required();
    sub.add_option("--out,-o", a->out, "The page to write (default view.html)");
    sub.add_option("--scene", a->options.scene_file, "Scene file to use instead of the one the runs recorded");
    sub.add_option("--max-frames", a->options.max_frames,
                   "Frames kept at most; longer runs are subsampled (default 2000)");
    sub.add_option("--members", a->options.max_members, "Ensemble members replayed per backend (default 8)");
    sub.add_flag("--no-penetration", a->no_penetration,
                 "Do not compute the penetration highlight (faster for large scenes)");
    sub.footer(
        "Writes one HTML file that needs no network: three.js (Debian's libjs-three) and the data are inside.\n"
        "Ensembles keep no trajectories: their members are replayed (deterministically) here.");
    return [a] { return view(*a); };
}

}  // namespace

Command makeViewCommand() {
    return {"view", "Write a self-contained 3D replay page (view.html) of run, compare or ensemble outputs",
            &setupView};
}

}  // namespace vroc::cli
