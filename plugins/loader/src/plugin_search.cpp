// SPDX-License-Identifier: MIT
#include "vroc/plugin/plugin_search.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <set>

namespace vroc::plugins {
namespace {

std::string programDir() {
    char buffer[4096];
    const ssize_t n = readlink("/proc/self/exe", buffer, sizeof buffer - 1);
    if (n <= 0) return {};
    buffer[n] = '\0';
    return std::filesystem::path(buffer).parent_path().string();
}

#ifdef VROC_BUILD_TREE_DIR
// True if `dir` is `root` or below it (both resolved).
bool isWithin(const std::string& dir, const std::string& root) {
    std::error_code ec;
    const std::filesystem::path d = std::filesystem::weakly_canonical(dir, ec);
    if (ec) return false;
    const std::filesystem::path r = std::filesystem::weakly_canonical(root, ec);
    if (ec) return false;
    return std::mismatch(r.begin(), r.end(), d.begin(), d.end()).first == r.end();
}
#endif

}  // namespace

std::string pluginFileName(const std::string& name) { return "vroc-plugin-" + name + ".so"; }

std::vector<std::string> pluginSearchDirs(const std::vector<std::string>& extra, bool use_environment,
                                          bool use_default_dirs) {
    std::vector<std::string> dirs = extra;
    if (const char* env = use_environment ? std::getenv(kPluginPathVariable) : nullptr) {
        std::string all = env;
        size_t begin = 0;
        while (begin <= all.size()) {
            size_t end = all.find(':', begin);
            if (end == std::string::npos) end = all.size();
            if (end > begin) dirs.push_back(all.substr(begin, end - begin));
            begin = end + 1;
        }
    }
    if (use_default_dirs) {
        const std::string exe = programDir();
        if (!exe.empty()) {
            dirs.push_back(exe + "/../lib/vroc-plugins");   // the build tree's layout
#ifdef VROC_PLUGIN_INSTALL_RELDIR
            dirs.push_back(exe + "/" + VROC_PLUGIN_INSTALL_RELDIR);   // installed: <libdir>/vroc/plugins
#endif
        }
#if defined(VROC_PLUGIN_BUILD_DIR) && defined(VROC_BUILD_TREE_DIR)
        // Only for programs that run from the build tree: an installed program (or one linking
        // the installed library) never looks into the build it came from.
        if (!exe.empty() && isWithin(exe, VROC_BUILD_TREE_DIR)) dirs.push_back(VROC_PLUGIN_BUILD_DIR);
#endif
    }
    // Drop repeats (the program-relative and build directories usually coincide).
    std::vector<std::string> unique;
    std::set<std::string> seen;
    for (const std::string& dir : dirs) {
        std::error_code ec;
        auto canonical = std::filesystem::weakly_canonical(dir, ec);
        const std::string key = ec ? dir : canonical.string();
        if (seen.insert(key).second) unique.push_back(ec ? dir : key);
    }
    return unique;
}

std::vector<std::string> findPluginFiles(const std::vector<std::string>& dirs) {
    std::vector<std::string> files;
    std::set<std::string> names;
    for (const std::string& dir : dirs) {
        std::error_code ec;
        std::vector<std::string> here;
        for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
            const std::string file = entry.path().filename().string();
            if (file.rfind("vroc-plugin-", 0) == 0 && file.size() > 3 && file.compare(file.size() - 3, 3, ".so") == 0)
                here.push_back(file);
        }
        std::sort(here.begin(), here.end());
        for (const std::string& file : here)
            if (names.insert(file).second) files.push_back(dir + "/" + file);
    }
    return files;
}

DeviceSpec parseDeviceSpec(const std::string& text) {
    const size_t colon = text.find(':');
    if (colon == std::string::npos) return {text, ""};
    return {text.substr(0, colon), text.substr(colon + 1)};
}

}  // namespace vroc::plugins
