// SPDX-License-Identifier: MIT
// vroc.compare, vroc.check, vroc.sweep, vroc.ensemble and vroc.write_report: the harness commands
// from Python. Each runs on the run pool (`jobs` worker processes; the same bits for any number) and
// returns its metrics document, the one the command's report is rendered from; the package's
// HarnessResult (vroc/harness_result.py) turns it into tables of arrays. With `out` it also writes
// metrics.json, report.html and the runs there, as the command does; without, nothing is written.
#include <algorithm>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include <pybind11/stl.h>

#include "bindings.h"
#include "py_convert.h"
#include "vroc/core/errors.h"
#include "vroc/core/recording/atomic_output.h"
#include "vroc/core/scene_loader.h"
#include "vroc/harness/commands/check.h"
#include "vroc/harness/commands/compare.h"
#include "vroc/harness/commands/ensemble.h"
#include "vroc/harness/commands/pooled_command.h"
#include "vroc/harness/commands/sweep.h"
#include "vroc/harness/documents/check_document.h"
#include "vroc/harness/documents/compare_document.h"
#include "vroc/harness/documents/ensemble_document.h"
#include "vroc/harness/documents/html_report.h"
#include "vroc/harness/documents/metrics_document.h"
#include "vroc/harness/documents/sweep_document.h"
#include "vroc/harness/runs/backend_selection.h"

namespace vroc::python {
namespace {

namespace fs = std::filesystem;
using harness::Json;

std::vector<std::string> assignments(const py::handle& settings) {
    std::vector<std::string> out;
    for (const auto& [key, value] : settingPairs(settings)) out.push_back(key + "=" + value);
    return out;
}

std::string backendList(const std::vector<std::string>& names) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ",") + n;
    return list;
}

/// Runs a pooled command, the GIL released: with `out`, writing into it as the command does;
/// without, writing nothing. Returns {"document": JSON text, "report": path or None}.
py::dict pooled(const std::optional<std::string>& out, int jobs, const Json& plan, const std::string& command,
                const std::function<Json(harness::RunPool&)>& body) {
    if (jobs < 1) throw InputError(command + ": jobs must be >= 1, got " + std::to_string(jobs));
    harness::PooledCommand c;
    if (out) {
        if (out->empty()) throw InputError(command + ": out must name a folder (or be None for no files)");
        c.out = *out;
        c.out_given = true;
    }
    c.jobs = jobs;
    c.plan = plan;
    c.command = command;
    harness::PooledOutput r;
    {
        py::gil_scoped_release release;
        r = harness::runPooledCommand(c, body);
    }
    py::dict d;
    d["document"] = r.doc.dump();
    d["report"] = r.report.empty() ? py::object(py::none()) : py::object(py::str(r.report.string()));
    return d;
}

/// The stress scenes: as given, else scenes/stress here, else the source tree's (a build-tree module).
fs::path stressScenesDir(const std::string& given) {
    if (!given.empty()) {
        if (!fs::is_directory(given)) throw InputError("scenes_dir: " + given + " is not a directory");
        return given;
    }
    if (fs::is_directory("scenes/stress")) return "scenes/stress";
#ifdef VROC_SOURCE_SCENES_DIR
    if (fs::is_directory(VROC_SOURCE_SCENES_DIR "/stress")) return VROC_SOURCE_SCENES_DIR "/stress";
#endif
    throw InputError("scenes_dir: the stress scenes were not found in ./scenes/stress; give scenes_dir");
}

}  // namespace

void bindHarness(py::module_& m) {
    m.def(
        "_compare",
        [](const std::string& scene_file, const std::vector<std::string>& backends, const py::handle& settings,
           double duration, std::optional<double> dt, int windows, double window, const std::optional<std::string>& out,
           int jobs, const std::string& footing, int footing_substeps) {
            harness::CompareOptions o;
            o.duration = duration;
            o.frame_dt = dt;
            o.windows = windows;
            o.window = window;
            o.progress = false;
            o.write_csv = out.has_value();
            o.command_line = "vroc.compare";
            if (!(o.duration > 0)) throw InputError("compare: duration must be a positive number of seconds");
            if (dt && !(*dt > 0)) throw InputError("compare: dt must be a positive number of seconds");
            if (!(o.window > 0) || o.windows < 1) throw InputError("compare: window and windows must be positive");
            const auto selected =
                harness::selectBackendsOnFooting(backendList(backends), assignments(settings), footing, footing_substeps, true);
            const Scene scene = loadScene(scene_file);
            return pooled(out, jobs, harness::comparePlan(scene, selected, o), "vroc.compare", [&](harness::RunPool& pool) {
                return harness::compareDocument(harness::compareScene(scene, selected, o, out ? fs::path(*out) : fs::path(), pool),
                                                o.command_line);
            });
        },
        py::arg("scene"), py::arg("backends"), py::arg("settings"), py::arg("duration"), py::arg("dt"), py::arg("windows"),
        py::arg("window"), py::arg("out"), py::arg("jobs"), py::arg("footing"), py::arg("footing_substeps"));

    m.def(
        "_check",
        [](const std::vector<std::string>& backends, const py::handle& settings, const std::vector<std::string>& only,
           bool long_set, bool stress, const std::string& scenes_dir, const std::optional<std::string>& out, int jobs,
           const std::string& footing, int footing_substeps) {
            harness::CheckOptions o;
            o.long_set = long_set;
            o.progress = false;
            o.only = only;
            o.stress = stress;
            o.command_line = "vroc.check";
            const auto selected =
                harness::selectBackendsOnFooting(backendList(backends), assignments(settings), footing, footing_substeps, true);
            const bool any_stress =
                stress || std::any_of(only.begin(), only.end(), [](const std::string& id) { return harness::isStressScenarioId(id); });
            if (any_stress) o.scenes_dir = stressScenesDir(scenes_dir);
            harness::CheckSuiteResult result;
            py::dict d = pooled(out, jobs, harness::checkPlan(selected, o), "vroc.check", [&](harness::RunPool& pool) {
                result = harness::runCheckSuite(selected, o, pool);
                return harness::checkDocument(result, o.command_line);
            });
            d["exit_code"] = result.exitCode();
            d["required_failures_native"] = result.required_failures_native;
            d["text"] = harness::checkTableText(result);
            return d;
        },
        py::arg("backends"), py::arg("settings"), py::arg("only"), py::arg("long_set"), py::arg("stress"),
        py::arg("scenes_dir"), py::arg("out"), py::arg("jobs"), py::arg("footing"), py::arg("footing_substeps"));

    m.def(
        "_sweep",
        [](const std::string& scene_source, const std::vector<std::string>& backends, const py::handle& settings,
           const std::vector<double>& dts, double duration, int windows, double window, const std::vector<std::string>& vary,
           const std::optional<std::string>& out, int jobs, const std::string& footing, int footing_substeps) {
            harness::SweepOptions o;
            if (!dts.empty()) o.dts = dts;
            for (double dt : o.dts)
                if (!(dt > 0)) throw InputError("sweep: every dt must be a positive number of seconds");
            o.duration = duration;
            o.windows = windows;
            o.window = window;
            o.vary = vary;
            o.progress = false;
            o.command_line = "vroc.sweep";
            if (!(o.duration > 0)) throw InputError("sweep: duration must be a positive number of seconds");
            const auto selected =
                harness::selectBackendsOnFooting(backendList(backends), assignments(settings), footing, footing_substeps, false);
            harness::sweepCurves(selected, o.vary);   // a bad vary fails before anything runs
            const harness::SweepScene scene = harness::loadSweepScene(scene_source);
            harness::SweepResult result;
            py::dict d = pooled(out, jobs, harness::sweepPlan(scene, selected, o), "vroc.sweep", [&](harness::RunPool& pool) {
                result = harness::runSweep(scene, selected, o, pool);
                return harness::sweepDocument(result, o.command_line);
            });
            py::list front;
            for (const harness::SweepPoint& p : result.points) {
                if (!p.on_pareto_front) continue;
                const harness::SweepStep& s = result.stepOf(p);
                py::dict f;
                f["curve"] = result.curves[p.curve].curve.label;
                f["dt"] = s.dt;
                f["cost"] = s.cost;
                f["window_error"] = s.window_error;
                front.append(f);
            }
            d["pareto_front"] = front;
            return d;
        },
        py::arg("scene"), py::arg("backends"), py::arg("settings"), py::arg("dts"), py::arg("duration"), py::arg("windows"),
        py::arg("window"), py::arg("vary"), py::arg("out"), py::arg("jobs"), py::arg("footing"), py::arg("footing_substeps"));

    m.def(
        "_ensemble",
        [](const std::string& scene_file, const std::vector<std::string>& backends, const py::handle& settings, int members,
           const std::string& perturb, double duration, std::optional<double> dt, std::uint64_t seed,
           const std::optional<std::string>& out, int jobs, const std::string& footing, int footing_substeps) {
            harness::EnsembleOptions o;
            o.members = members;
            if (!perturb.empty()) o.perturb = harness::parsePerturbation(perturb);
            o.duration = duration;
            o.seed = seed;
            o.source = scene_file;
            o.command_line = "vroc.ensemble";
            if (o.members < 2) throw InputError("ensemble: members must be at least 2 per backend");
            if (!(o.duration > 0)) throw InputError("ensemble: duration must be a positive number of seconds");
            if (dt && !(*dt > 0)) throw InputError("ensemble: dt must be a positive number of seconds");
            const auto selected =
                harness::selectBackendsOnFooting(backendList(backends), assignments(settings), footing, footing_substeps, false);
            if (selected.size() < 2) throw InputError("ensemble compares backends: give at least two");
            const Scene scene = loadScene(scene_file);
            if (dt) o.frame_dt = *dt;
            harness::EnsembleResult result;
            py::dict d = pooled(out, jobs, harness::ensemblePlan(scene, selected, o), "vroc.ensemble",
                                [&](harness::RunPool& pool) {
                                    result = harness::runEnsemble(scene, selected, o, pool);
                                    return harness::ensembleDocument(result);
                                });
            d["verdict"] = harness::ensembleVerdictText(result);
            return d;
        },
        py::arg("scene"), py::arg("backends"), py::arg("settings"), py::arg("members"), py::arg("perturb"),
        py::arg("duration"), py::arg("dt"), py::arg("seed"), py::arg("out"), py::arg("jobs"), py::arg("footing"),
        py::arg("footing_substeps"));

    m.def(
        "_write_report",
        [](const std::string& document, const std::string& out) {
            const Json doc = Json::parse(document);
            py::gil_scoped_release release;
            recording::prepareOutputDirectory(out);
            harness::writeDocument(doc, fs::path(out) / "metrics.json");
            return fs::absolute(harness::writeReport({doc}, out)).lexically_normal().string();
        },
        py::arg("document"), py::arg("out"));
}

}  // namespace vroc::python
