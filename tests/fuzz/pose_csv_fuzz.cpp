// SPDX-License-Identifier: MIT
// Fuzz target: the recorded-pose CSV (plugins/support/pose_csv.h) and the `replay` plugin that
// plays it back, linked in and driven through its C ABI as the host drives it (docs/fuzzing.md).
// Input: one line of extra options for the replay device (e.g. "loop=1,offset=0.5"), then the
// recording file.
// Contract, per line: parsePoseCsvRow either fails with a message naming a column (or the column
// count), or returns a row whose fields are the cells' values (read back independently with
// strtoll/strtoull/strtod; no integer truncated, no negative bitmask), finite, with |q| within
// 0.01 of 1, and which formatPoseCsvRow writes so that it parses back to the same bits.
// Per file: create either fails with a message, or every pose the device returns, at the samples'
// times, next to them, between them and at host times 0 and 2^62 ns, passes the host's own check
// (plugins/loader/src/plugin_validation.h: finite, unit quaternion), carries the asked time, and
// at an interior sample's own time (no offset, no loop) is exactly that sample.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "fuzz_require.h"
#include "plugin_validation.h"
#include "pose_csv.h"
#include "scratch_file.h"

extern "C" int32_t vroc_plugin_negotiate(const VrocHostInfo* host, VrocPluginInfo* out);   // replay_plugin.cpp

namespace {

using vroc::plugin_sdk::PoseCsvRow;

constexpr uint32_t kReplaySensors = 16;   // replay_plugin.cpp describe()
// Host times are CLOCK_MONOTONIC readings: never negative; 2^62 ns is 146 years of uptime.
constexpr int64_t kLatestHostTime = int64_t{1} << 62;

// strtoX must consume the whole cell (they skip leading spaces and take a sign, as the C
// functions do; a stricter parser accepts less, which is fine).
bool wholeCell(const std::string& cell, const char* end) { return !cell.empty() && *end == '\0'; }

void checkRowAgainstCells(const std::vector<std::string>& cells, const PoseCsvRow& row) {
    char* end = nullptr;
    errno = 0;
    const long long time = std::strtoll(cells[0].c_str(), &end, 10);
    VROC_FUZZ_REQUIRE(wholeCell(cells[0], end) && errno == 0 && time == row.time_ns);
    errno = 0;
    const unsigned long long sensor = std::strtoull(cells[1].c_str(), &end, 10);
    VROC_FUZZ_REQUIRE(wholeCell(cells[1], end) && errno == 0 && sensor == row.sensor);   // no truncation
    VROC_FUZZ_REQUIRE(cells[1].find('-') == std::string::npos);
    for (int c = 2; c < 9; ++c) {
        const double v = std::strtod(cells[c].c_str(), &end);
        const double got = c < 5 ? row.position[c - 2] : row.orientation[c - 5];
        VROC_FUZZ_REQUIRE(wholeCell(cells[c], end) && std::isfinite(v));
        VROC_FUZZ_REQUIRE(std::memcmp(&v, &got, sizeof v) == 0);
    }
    errno = 0;
    const unsigned long long buttons = std::strtoull(cells[9].c_str(), &end, 10);
    VROC_FUZZ_REQUIRE(wholeCell(cells[9], end) && errno == 0 && buttons == row.buttons);
    VROC_FUZZ_REQUIRE(cells[9].find('-') == std::string::npos);   // strtoull would negate "-1"
}

bool sameBits(const PoseCsvRow& a, const PoseCsvRow& b) {
    return a.time_ns == b.time_ns && a.sensor == b.sensor && a.buttons == b.buttons &&
           std::memcmp(a.position.data(), b.position.data(), sizeof a.position) == 0 &&
           std::memcmp(a.orientation.data(), b.orientation.data(), sizeof a.orientation) == 0;
}

// One data line; returns whether it was accepted.
bool checkLine(const std::string& line, PoseCsvRow& row) {
    std::string error;
    if (!vroc::plugin_sdk::parsePoseCsvRow(line, row, error)) {
        VROC_FUZZ_REQUIRE(error.rfind("column", 0) == 0 || error.rfind("expected 10 columns", 0) == 0);
        return false;
    }
    std::string text = line;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    std::vector<std::string> cells;
    for (std::size_t begin = 0;;) {
        const std::size_t comma = text.find(',', begin);
        cells.push_back(text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin));
        if (comma == std::string::npos) break;
        begin = comma + 1;
    }
    VROC_FUZZ_REQUIRE(cells.size() == 10);
    checkRowAgainstCells(cells, row);
    const double norm = std::sqrt(row.orientation[0] * row.orientation[0] + row.orientation[1] * row.orientation[1] +
                                  row.orientation[2] * row.orientation[2] + row.orientation[3] * row.orientation[3]);
    VROC_FUZZ_REQUIRE(std::abs(norm - 1.0) <= 0.01);
    PoseCsvRow again;
    VROC_FUZZ_REQUIRE(vroc::plugin_sdk::parsePoseCsvRow(vroc::plugin_sdk::formatPoseCsvRow(row), again, error));
    VROC_FUZZ_REQUIRE(sameBits(row, again));
    return true;
}

const VrocDeviceApi* replayApi() {
    static const VrocDeviceApi* api = [] {
        static VrocHostServices services{};
        services.struct_type = VROC_STRUCT_HOST_SERVICES;
        services.struct_version = 1;
        services.struct_size = sizeof services;
        services.log = [](void*, int32_t, const char*, const char*) {};
        services.now_ns = [](void*) -> int64_t { return 0; };
        VrocHostInfo host{};
        host.struct_type = VROC_STRUCT_HOST_INFO;
        host.struct_version = 1;
        host.struct_size = sizeof host;
        host.abi_min = 1;
        host.abi_max = VROC_PLUGIN_ABI_VERSION;
        host.host_version = "vroc fuzz";
        host.services = &services;
        VrocPluginInfo info{};
        info.struct_type = VROC_STRUCT_PLUGIN_INFO;
        info.struct_version = 1;
        info.struct_size = sizeof info;
        VROC_FUZZ_REQUIRE(vroc_plugin_negotiate(&host, &info) == VROC_OK);
        vroc::plugins::LoadedPlugin loaded;
        VROC_FUZZ_REQUIRE(vroc::plugins::validatePluginInfo(info, 1, VROC_PLUGIN_ABI_VERSION, loaded).empty());
        return info.api;
    }();
    return api;
}

int64_t saturatingAdd(int64_t a, int64_t b) {
    int64_t r;
    if (__builtin_add_overflow(a, b, &r)) return b > 0 ? std::numeric_limits<int64_t>::max() : std::numeric_limits<int64_t>::min();
    return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const vroc::fuzz::ScratchFile file("recording.csv");
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::size_t newline = input.find('\n');
    if (newline == std::string::npos) return 0;
    const std::string extra_options = input.substr(0, newline);
    const std::string csv = input.substr(newline + 1);
    if (extra_options.find('\0') != std::string::npos) return 0;   // a C string cannot carry it

    // Lines as std::getline splits them (the replay reader's way); the first is the header.
    std::map<uint32_t, std::vector<PoseCsvRow>> rows;   // accepted rows per sensor, file order
    std::size_t begin = csv.find('\n');
    while (begin != std::string::npos && begin < csv.size()) {
        const std::size_t end = csv.find('\n', begin + 1);
        const std::string line = csv.substr(begin + 1, end == std::string::npos ? std::string::npos : end - begin - 1);
        PoseCsvRow row;
        if (!line.empty() && checkLine(line, row)) rows[row.sensor].push_back(row);
        begin = end;
    }

    file.write(csv.data(), csv.size());
    const VrocDeviceApi* api = replayApi();
    const std::string options = "file=" + file.path() + (extra_options.empty() ? "" : "," + extra_options);
    VrocDeviceHandle handle = nullptr;
    if (api->create(0, options.c_str(), &handle) != VROC_OK) {
        VROC_FUZZ_REQUIRE(handle == nullptr);
        char message[512];
        VROC_FUZZ_REQUIRE(api->last_error(nullptr, message, sizeof message) > 0);
        return 0;
    }
    VROC_FUZZ_REQUIRE(handle != nullptr);
    const bool plain = extra_options.empty();   // no offset, no loop: times are recording times
    for (const auto& [sensor, list] : rows) {
        if (sensor >= kReplaySensors) continue;
        std::vector<int64_t> times = {0, kLatestHostTime};
        for (std::size_t i = 0; i < list.size() && i < 16; ++i) {
            const int64_t t = list[i].time_ns;
            times.insert(times.end(), {t, saturatingAdd(t, -1), saturatingAdd(t, 1)});
            if (i > 0) times.push_back(list[i - 1].time_ns / 2 + t / 2);
        }
        for (int64_t t : times) {
            t = std::clamp<int64_t>(t, 0, kLatestHostTime);
            VrocPoseSample sample{};
            sample.struct_type = VROC_STRUCT_POSE_SAMPLE;
            sample.struct_version = 1;
            sample.struct_size = sizeof sample;
            const int32_t rc = api->get_pose(handle, sensor, t, &sample);
            if (rc < 0) {
                char message[512];
                VROC_FUZZ_REQUIRE(api->last_error(handle, message, sizeof message) > 0);
                continue;
            }
            VROC_FUZZ_REQUIRE(sample.time_ns == t);
            const std::string why = vroc::plugins::validatePoseSample(sample, sensor, kReplaySensors);
            if (!why.empty()) std::fprintf(stderr, "vroc fuzz: the host rejects a replayed pose: %s\n", why.c_str());
            VROC_FUZZ_REQUIRE(why.empty());
        }
        // At an interior sample's own time, with only that sample there: exactly that sample.
        if (!plain) continue;
        for (std::size_t i = 1; i + 1 < list.size() && i < 16; ++i) {
            if (list[i - 1].time_ns >= list[i].time_ns || list[i].time_ns >= list[i + 1].time_ns) continue;
            if (list[i].time_ns < 0 || list[i].time_ns > kLatestHostTime) continue;
            VrocPoseSample sample{};
            sample.struct_type = VROC_STRUCT_POSE_SAMPLE;
            sample.struct_version = 1;
            sample.struct_size = sizeof sample;
            if (api->get_pose(handle, sensor, list[i].time_ns, &sample) < 0) continue;
            for (int k = 0; k < 3; ++k) VROC_FUZZ_REQUIRE(sample.position[k] == list[i].position[k]);
        }
    }
    api->destroy(handle);
    return 0;
}
