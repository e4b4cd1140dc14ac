// SPDX-License-Identifier: MIT
// Debian's Chromium, headless, for the viewer tests: WebGL by SwiftShader (software), the DOM
// after a virtual-time budget (the page writes its self-test into <pre id="vroc-selftest">), and
// screenshots read back with libpng.
#pragma once

#include <cmath>
#include <filesystem>
#include <optional>
#include <png.h>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "csv_reader.h"
#include "vroc/core/errors.h"
#include "vroc/core/subprocess.h"

namespace vroc::test {

inline constexpr int kShotWidth = 800, kShotHeight = 600;  // [px] small: SwiftShader is slow

inline bool haveChromium(const std::filesystem::path& dir) {
    SpawnOptions quiet;
    quiet.stdout_file = quiet.stderr_file = dir / "chromium-version.log";
    try {
        return runProcess({"chromium", "--version"}, quiet) == 0;
    } catch (const RunError&) {
        return false;
    }
}

/// Runs headless Chromium on `page` + `hash` with `mode` ("--dump-dom" or "--screenshot=<png>");
/// stdout goes to `out`. Returns the exit status.
inline int runChromium(const std::filesystem::path& page, const std::string& hash, const std::string& mode,
                       const std::filesystem::path& out, const std::filesystem::path& dir) {
    SpawnOptions options;
    options.stdout_file = out;
    options.stderr_file = dir / "chromium.log";
    return runProcess({"timeout", "60", "chromium", "--headless", "--no-sandbox", "--use-angle=swiftshader",
                       "--enable-unsafe-swiftshader", "--disable-background-networking", "--disable-component-update",
                       "--disable-sync", "--no-first-run", "--hide-scrollbars", "--force-device-scale-factor=1",
                       "--user-data-dir=" + (dir / "profile").string(),
                       "--window-size=" + std::to_string(kShotWidth) + "," + std::to_string(kShotHeight),
                       "--virtual-time-budget=2000", mode, "file://" + std::filesystem::absolute(page).string() + hash},
                      options);
}

/// The page's self-test (window.vrocViewer.selfTest() as written into the DOM), or nothing.
inline std::optional<nlohmann::json> pageSelfTest(const std::filesystem::path& page, const std::string& hash,
                                                  const std::filesystem::path& dir) {
    const auto dom = dir / "dom.html";
    if (runChromium(page, hash, "--dump-dom", dom, dir) != 0) return std::nullopt;
    const std::string text = readText(dom.string());
    const std::size_t id = text.find("id=\"vroc-selftest\"");
    if (id == std::string::npos) return std::nullopt;
    const std::size_t at = text.find('>', id) + 1, end = text.find("</pre>", at);
    if (end == std::string::npos) return std::nullopt;
    std::string json = text.substr(at, end - at);
    for (const auto& [entity, c] : {std::pair{"&quot;", "\""}, {"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}})
        for (std::size_t p = json.find(entity); p != std::string::npos; p = json.find(entity, p + 1))
            json.replace(p, std::string(entity).size(), c);
    const auto doc = nlohmann::json::parse(json, nullptr, false);
    if (doc.is_discarded()) return std::nullopt;
    return doc;
}

struct Rgb {
    int r = 0, g = 0, b = 0;
};

/// An RGB screenshot read with libpng.
struct Screenshot {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
    Rgb at(int x, int y) const {
        const std::size_t i =
            3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
};

inline std::optional<Screenshot> screenshot(const std::filesystem::path& page, const std::string& hash,
                                            const std::filesystem::path& png, const std::filesystem::path& dir) {
    if (runChromium(page, hash, "--screenshot=" + png.string(), dir / "chromium-stdout.log", dir) != 0)
        return std::nullopt;
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, png.c_str())) return std::nullopt;
    image.format = PNG_FORMAT_RGB;
    Screenshot s;
    s.rgb.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, s.rgb.data(), 0, nullptr)) return std::nullopt;
    s.width = static_cast<int>(image.width);
    s.height = static_cast<int>(image.height);
    return s;
}

/// Hue [deg] and saturation [0, 1] of a colour (HSL).
inline void hueSaturation(Rgb c, double& hue, double& saturation) {
    const double r = c.r / 255.0, g = c.g / 255.0, b = c.b / 255.0;
    const double mx = std::max({r, g, b}), mn = std::min({r, g, b}), d = mx - mn, l = (mx + mn) / 2;
    saturation = d == 0 ? 0 : d / (1 - std::abs(2 * l - 1));
    if (d == 0)
        hue = 0;
    else if (mx == r)
        hue = 60 * std::fmod((g - b) / d + 6, 6);
    else if (mx == g)
        hue = 60 * ((b - r) / d + 2);
    else
        hue = 60 * ((r - g) / d + 4);
}

inline Rgb parseHex(const std::string& hex) {  // "#rrggbb"
    return {std::stoi(hex.substr(1, 2), nullptr, 16), std::stoi(hex.substr(3, 2), nullptr, 16),
            std::stoi(hex.substr(5, 2), nullptr, 16)};
}

}  // namespace vroc::test
