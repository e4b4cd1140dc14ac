// SPDX-License-Identifier: MIT
#include "vroc/viewer/viewer_page.h"

#include <string_view>

#include "page_payload.h"
#include "viewer_assets.h"
#include "vroc/core/recording/atomic_output.h"

namespace vroc::viewer {
namespace {

std::string htmlText(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else
            out += c;
    }
    return out;
}

}  // namespace

std::string viewerPageHtml(const ViewerData& data) {
    // The template's slots, each filled once, in any order; contents are never searched again.
    const std::pair<std::string_view, std::string> slots[] = {
        {"{{TITLE}}", htmlText("VROC view: " + data.title)},
        {"{{STYLE}}", std::string(assets::kPageCss)},
        {"{{THREE_JS}}", std::string(assets::kThreeJs)},
        {"{{ORBIT_CONTROLS_JS}}", std::string(assets::kOrbitControlsJs)},
        {"{{DATA_JSON}}", pageDataJson(data)},
        {"{{VIEWER_JS}}", std::string(assets::kPageJs)},
    };
    std::string out;
    std::string_view rest = assets::kPageHtml;
    while (true) {
        std::size_t best = std::string_view::npos;
        const std::pair<std::string_view, std::string>* slot = nullptr;
        for (const auto& s : slots) {
            const std::size_t at = rest.find(s.first);
            if (at < best) best = at, slot = &s;
        }
        if (!slot) break;
        out.append(rest.substr(0, best));
        out.append(slot->second);
        rest.remove_prefix(best + slot->first.size());
    }
    out.append(rest);
    return out;
}

std::size_t writeViewerPage(const ViewerData& data, const std::filesystem::path& file) {
    const std::string html = viewerPageHtml(data);
    recording::AtomicFile out(file);
    out.write(html);
    out.commit();
    return html.size();
}

}  // namespace vroc::viewer
