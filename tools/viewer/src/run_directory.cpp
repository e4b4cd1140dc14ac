// SPDX-License-Identifier: MIT
#include "run_directory.h"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "vroc/core/errors.h"

namespace vroc::viewer {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

Json readJsonFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(file.string() + ": cannot read");
    std::stringstream text;
    text << in.rdbuf();
    Json doc = Json::parse(text.str(), nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) throw InputError(file.string() + ": expected a JSON object");
    return doc;
}

template <typename T>
T field(const Json& doc, const Json::json_pointer& at, const fs::path& file) {
    if (!doc.contains(at)) throw InputError(file.string() + ": " + at.to_string() + ": missing");
    try {
        return doc.at(at).get<T>();
    } catch (const Json::exception&) {
        throw InputError(file.string() + ": " + at.to_string() + ": has the wrong type");
    }
}

RunDirectory fromRunJson(const fs::path& dir, const fs::path& file) {
    const Json doc = readJsonFile(file);
    if (doc.value("format", "") != "vroc-run/1") throw InputError(file.string() + ": expected format \"vroc-run/1\"");
    RunDirectory out{dir, "run", "", "", "", {}, {}};
    out.scene_file = field<std::string>(doc, "/scene/file"_json_pointer, file);
    out.scene_sha256 = field<std::string>(doc, "/scene/sha256"_json_pointer, file);
    const auto backend = field<std::string>(doc, "/backend/name"_json_pointer, file);
    const auto steps = field<std::int64_t>(doc, "/steps"_json_pointer, file);
    out.title = "run of '" + field<std::string>(doc, "/scene/name"_json_pointer, file) + "' on " + backend;
    out.runs.push_back(
        {backend, backend, dir / "trajectory.csv", dir / "events.csv", static_cast<std::size_t>(steps) + 1});
    return out;
}

RunDirectory fromCompare(const fs::path& dir, const fs::path& file, const Json& doc) {
    RunDirectory out{dir, "compare", doc.value("title", "compare"), "", "", {}, {}};
    out.scene_file = field<std::string>(doc, "/scene/file"_json_pointer, file);
    out.scene_sha256 = field<std::string>(doc, "/scene/sha256"_json_pointer, file);
    const auto frames = field<std::int64_t>(doc, "/parameters/frames"_json_pointer, file);
    for (const Json& b : field<Json>(doc, "/backends"_json_pointer, file)) {
        const std::string name = b.value("name", "");
        if (name.empty()) throw InputError(file.string() + ": /backends: a backend without a name");
        // With both footings (--footing both) a backend runs twice: its key names the run's folder
        // ("bullet-equal") and its label tells the two apart on the page ("bullet (equal footing)").
        const std::string key = b.value("key", name);
        const std::string label = b.value("label", name);
        out.runs.push_back({name, label, dir / key / "trajectory.csv", dir / key / "events.csv",
                            static_cast<std::size_t>(frames) + 1});
    }
    return out;
}

RunDirectory fromEnsemble(const fs::path& dir, const fs::path& file, const Json& doc) {
    RunDirectory out{dir, "ensemble", doc.value("title", "ensemble"), "", "", {}, {}};
    out.scene_file = field<std::string>(doc, "/scene/source"_json_pointer, file);
    out.scene_sha256 = field<std::string>(doc, "/scene/sha256"_json_pointer, file);
    EnsembleReplayPlan& p = out.ensemble;
    p.members = field<int>(doc, "/parameters/members"_json_pointer, file);
    p.duration = field<double>(doc, "/parameters/duration_s"_json_pointer, file);
    p.frame_dt = field<double>(doc, "/parameters/frame_dt_s"_json_pointer, file);
    p.seed = field<std::uint64_t>(doc, "/parameters/seed"_json_pointer, file);
    p.perturb.position = field<double>(doc, "/parameters/perturb/positions_m"_json_pointer, file);
    p.perturb.velocity = field<double>(doc, "/parameters/perturb/velocities_m_per_s"_json_pointer, file);
    p.perturb.orientation = field<double>(doc, "/parameters/perturb/orientations_rad"_json_pointer, file);
    p.perturb.angular_velocity = field<double>(doc, "/parameters/perturb/angular_rad_per_s"_json_pointer, file);
    for (const Json& b : field<Json>(doc, "/backends"_json_pointer, file)) {
        p.backends.push_back({b.value("name", ""), b.value("settings", std::map<std::string, std::string>{})});
        for (int m = 0; m < p.members; ++m) {
            const fs::path run =
                dir / "runs" / ("member-" + p.backends.back().name + "-" + std::to_string(m) + ".json");
            if (!fs::exists(run)) continue;
            const Json member = readJsonFile(run);
            p.recorded_hashes[{p.backends.back().name, m}] = member.value("/result/state_hash"_json_pointer, "");
        }
    }
    return out;
}

}  // namespace

RunDirectory readRunDirectory(const fs::path& dir) {
    if (!fs::is_directory(dir))
        throw InputError(dir.string() + ": not a directory (expected the output of vroc run, compare or ensemble)");
    if (fs::exists(dir / "run.json")) return fromRunJson(dir, dir / "run.json");
    const fs::path metrics = dir / "metrics.json";
    if (!fs::exists(metrics)) {
        if (fs::exists(dir / "trajectory.csv"))
            throw InputError((dir / "run.json").string() +
                             ": missing, so the run did not finish (run.json is written last)");
        throw InputError(dir.string() +
                         ": holds neither run.json (vroc run) nor metrics.json (vroc compare, ensemble)");
    }
    const Json doc = readJsonFile(metrics);
    const std::string command = doc.value("command", "");
    if (command == "compare") return fromCompare(dir, metrics, doc);
    if (command == "ensemble") return fromEnsemble(dir, metrics, doc);
    throw InputError(metrics.string() + ": a '" + command +
                     "' report keeps no trajectories to replay (expected compare or ensemble)");
}

}  // namespace vroc::viewer
