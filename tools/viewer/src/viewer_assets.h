// SPDX-License-Identifier: MIT
// The files the page inlines, embedded at build time (tools/viewer/CMakeLists.txt generates
// viewer_assets.cpp from them): the page's own template, script and style (tools/viewer/page/) and
// three.js r111 with its orbit controls from Debian's libjs-three.
#pragma once

#include <string_view>

namespace vroc::viewer::assets {

extern const std::string_view kPageHtml;         ///< page/viewer.html: the template with {{...}} slots
extern const std::string_view kPageCss;          ///< page/viewer.css
extern const std::string_view kPageJs;           ///< page/viewer.js: the viewer itself
extern const std::string_view kThreeJs;          ///< /usr/share/javascript/three/three.min.js
extern const std::string_view kOrbitControlsJs;  ///< .../examples/js/controls/OrbitControls.js

}  // namespace vroc::viewer::assets
