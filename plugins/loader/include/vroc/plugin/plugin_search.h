// SPDX-License-Identifier: MIT
// Where plugins are found. A plugin is named by a path (anything containing '/') or by a name,
// looked up as vroc-plugin-<name>.so in, in order: the directories of VROC_PLUGIN_PATH
// (colon-separated), <directory of the running program>/../lib/vroc-plugins (the build tree),
// <directory of the running program>/../<libdir>/vroc/plugins (an installed vroc), and, for
// programs inside the build tree only, the build's plugin directory
// (${CMAKE_BINARY_DIR}/lib/vroc-plugins).
#pragma once

#include <string>
#include <vector>

namespace vroc::plugins {

inline constexpr const char* kPluginPathVariable = "VROC_PLUGIN_PATH";

/// "vroc-plugin-<name>.so".
std::string pluginFileName(const std::string& name);
/// The directories above, in search order, without duplicates; `extra` first.
std::vector<std::string> pluginSearchDirs(const std::vector<std::string>& extra, bool use_environment,
                                          bool use_default_dirs);
/// Every vroc-plugin-*.so in `dirs`, sorted by directory order then name; a name found twice is
/// listed once (the first wins, as in resolution).
std::vector<std::string> findPluginFiles(const std::vector<std::string>& dirs);

/// "analytic:motion=circle,radius=0.3" -> {"analytic", "motion=circle,radius=0.3"}.
struct DeviceSpec {
    std::string plugin;   ///< name or path
    std::string options;  ///< key=value,... (may be empty)
};
DeviceSpec parseDeviceSpec(const std::string& text);

}  // namespace vroc::plugins
