// SPDX-License-Identifier: MIT
// `vroc sweep/compare/check/ensemble` over several worker processes and MPI ranks, end to end:
// results (everything but wall-clock timings) bit-identical to one process running them in turn;
// an interrupted command names what did not finish, and --resume finishes only that.
#include <gtest/gtest.h>

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <memory>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include "subprocess.h"
#include "test_scenes.h"

namespace vroc::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const std::string kSource = VROC_SOURCE_DIR;

// Wall-clock measurements differ between any two runs; everything else must not.
Json withoutTimings(const Json& x) {
    static const std::set<std::string> timing = {"timing", "cost_wall_per_sim_s", "step_p50_us", "wall_s", "wall_total_s",
                                                 "wall_time_s", "pareto_front", "seconds"};
    if (x.is_object()) {
        Json out = Json::object();
        for (const auto& [k, v] : x.items())
            if (!timing.count(k)) out[k] = withoutTimings(v);
        return out;
    }
    if (x.is_array()) {
        Json out = Json::array();
        for (const Json& v : x) out.push_back(withoutTimings(v));
        return out;
    }
    return x;
}

Json results(const fs::path& dir) {
    std::ifstream in(dir / "metrics.json");
    EXPECT_TRUE(in.good()) << dir;
    return withoutTimings(Json::parse(in)["results"]);
}

Json execution(const fs::path& dir) {
    std::ifstream in(dir / "metrics.json");
    return Json::parse(in)["execution"];
}

std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

TEST(ParallelCli, SweepEnsembleCompareAndCheckGiveTheSameResultsWithTwoWorkers) {
    const fs::path dir = freshTempDir("parallel-same");
    const std::string staircase = kSource + "/scenes/staircase.json";
    const std::vector<std::vector<std::string>> commands = {
        {"sweep", staircase, "--backends", "native,bullet", "--duration", "1", "--dt", "1/60,1/120", "--detail", "full,sphere"},
        {"ensemble", staircase, "--backends", "native,bullet", "--members", "6", "--duration", "1.5"},
        {"compare", staircase, "--backends", "native,bullet", "--duration", "1"},
        {"check", "--backends", "native,bullet", "--only", "bounce-e0.5", "--only", "tumble", "--only", "thin-wall"},
    };
    for (const auto& c : commands) {
        const fs::path one = dir / (c[0] + "-1"), two = dir / (c[0] + "-2");
        const auto r1 = runVroc(concat(c, {"--jobs", "1", "-o", one.string()}), dir);
        ASSERT_EQ(r1.exit_code, 0) << c[0] << ": " << r1.err;
        const auto r2 = runVroc(concat(c, {"--jobs", "2", "-o", two.string()}), dir);
        ASSERT_EQ(r2.exit_code, 0) << c[0] << ": " << r2.err;
        EXPECT_EQ(results(one).dump(), results(two).dump()) << c[0] << ": results differ between --jobs 1 and --jobs 2";
        EXPECT_EQ(execution(two)["jobs"], 2);
        EXPECT_TRUE(fs::exists(two / "runs" / "status.json"));
        EXPECT_TRUE(fs::exists(two / "report.html"));
    }
    // The ensemble names the observables that separate the backends.
    const auto r = runVroc({"report", (dir / "ensemble-2").string(), "-o", (dir / "ensemble-report").string()}, dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(ParallelCli, BadEnsembleAndPoolInputIsAOneLineErrorWithExit2) {
    const fs::path dir = freshTempDir("parallel-bad-input");
    const std::string staircase = kSource + "/scenes/staircase.json";
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"ensemble", staircase, "--backends", "native,bullet", "--perturb", "speed=1"}, "--perturb: unknown key 'speed'"},
        {{"ensemble", staircase, "--backends", "native,bullet", "--perturb", "positions=-1"}, "expected KEY=SIGMA with SIGMA >= 0"},
        {{"ensemble", staircase, "--backends", "native,bullet", "--members", "1"}, "--members: expected at least 2"},
        {{"ensemble", staircase, "--backends", "native"}, "at least two"},
        {{"ensemble", staircase, "--backends", "native,bullet", "--dt", "1/0"}, "--dt: '1/0'"},
        {{"sweep", staircase, "--backends", "bullet", "--resume"}, "--resume: give --out"},
        {{"sweep", staircase, "--backends", "bullet", "--resume", "-o", (dir / "none").string()}, "nothing to resume"},
        {{"check", "--backends", "bullet", "--jobs", "-2"}, "--jobs"},
    };
    for (const auto& [args, expected] : cases) {
        const auto r = runVroc(args, dir);
        EXPECT_EQ(r.exit_code, 2) << args[0] << " " << expected << ": " << r.err;
        EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_FALSE(fs::exists(dir / "none" / "metrics.json"));
}

// A process still running when its test ends (an assertion failed) is killed with its process
// group rather than waited for.
struct KillIfRunning {
    void operator()(Subprocess* p) const {
        if (!p->poll()) ::kill(-p->pid(), SIGKILL);
        delete p;
    }
};
using Started = std::unique_ptr<Subprocess, KillIfRunning>;

// Starts `argv` in the background, in a process group of its own, with output to files.
Started start(const std::vector<std::string>& argv, const fs::path& out, const fs::path& err) {
    SpawnOptions options;
    options.stdout_file = out;
    options.stderr_file = err;
    options.new_process_group = true;
    return Started(new Subprocess(argv, options));
}

int countRuns(const fs::path& runs) {
    int n = 0;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(runs, ec))
        if (e.path().filename().string().rfind("member-", 0) == 0 && e.path().extension() == ".json") ++n;
    return n;
}

// Waits until `n` runs are on disk (or the process ended); returns false on timeout.
bool waitForRuns(Subprocess& process, const fs::path& runs, int n) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < deadline) {
        if (countRuns(runs) >= n) return true;
        if (process.poll()) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
}

std::vector<std::string> pileEnsemble(const fs::path& out) {
    return {"ensemble", kSource + "/scenes/stress/pyramid10.json", "--backends", "native,bullet", "--members", "40",
            "--duration", "0.5", "--permutations", "199", "-o", out.string()};
}

// `launcher`: how the command starts, the vroc binary or mpirun with its options and the binary.
void expectInterruptedThenResumed(const fs::path& dir, const fs::path& out, int code, const std::string& err_text,
                                  const std::vector<std::string>& launcher) {
    EXPECT_NE(code, 0);
    EXPECT_NE(err_text.find("vroc: error: ensemble interrupted: "), std::string::npos) << err_text;
    EXPECT_NE(err_text.find("did not"), std::string::npos) << err_text;
    EXPECT_NE(err_text.find("--resume"), std::string::npos) << err_text;
    EXPECT_FALSE(fs::exists(out / "metrics.json")) << "an interrupted command must not look complete";
    std::ifstream st(out / "runs" / "status.json");
    ASSERT_TRUE(st.good());
    const Json status = Json::parse(st);
    EXPECT_FALSE(status["complete"].get<bool>());
    const int finished = countRuns(out / "runs");
    EXPECT_GT(finished, 0);
    EXPECT_LT(finished, 80);

    const fs::path o = dir / "resume.out", e = dir / "resume.err";
    const auto resumed = start(concat(launcher, concat(pileEnsemble(out), {"--resume", "--jobs", "2", "-q"})), o, e);
    ASSERT_EQ(resumed->wait(), 0) << readText(e.string());
    EXPECT_GE(execution(out)["resumed"].get<int>(), finished);

    const fs::path ref = dir / "reference";
    const auto r = runVroc(concat(pileEnsemble(ref), {"--jobs", "1"}), dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(results(out).dump(), results(ref).dump()) << "resumed results differ from one uninterrupted process";
}

TEST(ParallelCli, InterruptedEnsembleResumesToTheSameResults) {
    const fs::path dir = freshTempDir("parallel-interrupt");
    const fs::path out = dir / "ens";
    const fs::path o = dir / "run.out", e = dir / "run.err";
    const auto run = start(vrocCommand(concat(pileEnsemble(out), {"--jobs", "2", "-q"})), o, e);
    ASSERT_TRUE(waitForRuns(*run, out / "runs", 6)) << readText(e.string());
    kill(run->pid(), SIGINT);   // Ctrl-C
    const int code = run->wait();
    EXPECT_EQ(code, 3);   // docs/cli.md: interruption is a failure while running
    expectInterruptedThenResumed(dir, out, code, readText(e.string()), {vrocBinary()});
}

#ifdef VROC_TEST_MPIEXEC
std::vector<std::string> mpirun(int ranks) {
    // As root (CI, containers) Open MPI needs its documented consent.
    return {VROC_TEST_MPIEXEC, "--oversubscribe", "--allow-run-as-root", "-n", std::to_string(ranks), vrocBinary()};
}

TEST(ParallelCli, MpiRanksGiveTheSameResultsAsOneProcess) {
    const fs::path dir = freshTempDir("parallel-mpi");
    const std::string staircase = kSource + "/scenes/staircase.json";
    const std::vector<std::string> sweep = {"sweep", staircase, "--backends", "native,bullet", "--duration", "1", "--dt", "1/60,1/120", "-q"};
    const auto r1 = runVroc(concat(sweep, {"--jobs", "1", "-o", (dir / "one").string()}), dir);
    ASSERT_EQ(r1.exit_code, 0) << r1.err;
    for (int ranks : {2, 3}) {
        const fs::path out = dir / ("ranks" + std::to_string(ranks));
        const auto mpi = start(concat(mpirun(ranks), concat(sweep, {"-o", out.string()})), dir / "mpi.out", dir / "mpi.err");
        ASSERT_EQ(mpi->wait(), 0) << readText((dir / "mpi.err").string());
        EXPECT_EQ(results(dir / "one").dump(), results(out).dump()) << ranks << " ranks";
        EXPECT_EQ(execution(out)["ranks"], ranks);
    }
    // Commands that write one set of files refuse to run on many ranks.
    const auto run = start(concat(mpirun(2), {"run", staircase, "-o", (dir / "run").string()}), dir / "run.out", dir / "run.err");
    EXPECT_EQ(run->wait(), 2);
    EXPECT_NE(readText((dir / "run.err").string()).find("does not run under mpirun"), std::string::npos);
}

// The pid of the vroc process that is MPI rank `rank` of the job writing to `out`.
pid_t findRank(int rank, const fs::path& out) {
    for (const auto& e : fs::directory_iterator("/proc")) {
        const std::string name = e.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        std::ifstream cmd(e.path() / "cmdline"), env(e.path() / "environ");
        std::string c((std::istreambuf_iterator<char>(cmd)), {}), v((std::istreambuf_iterator<char>(env)), {});
        if (c.find(out.string()) == std::string::npos || c.find("mpirun") != std::string::npos) continue;
        if (v.find("OMPI_COMM_WORLD_RANK=" + std::to_string(rank) + '\0') != std::string::npos) return std::stoi(name);
    }
    return -1;
}

TEST(ParallelCli, AKilledRankEndsTheJobNamingTheMissingRunsAndResumeFinishesIt) {
    const fs::path dir = freshTempDir("parallel-mpi-kill");
    const fs::path out = dir / "ens";
    const fs::path o = dir / "run.out", e = dir / "run.err";
    const auto run = start(concat(mpirun(2), concat(pileEnsemble(out), {"-q"})), o, e);
    ASSERT_TRUE(waitForRuns(*run, out / "runs", 6)) << readText(e.string());
    const pid_t rank1 = findRank(1, out);
    ASSERT_GT(rank1, 0);
    kill(rank1, SIGKILL);   // a lost node
    const int code = run->wait();   // must end, not hang (the test's own timeout would catch a hang)
    expectInterruptedThenResumed(dir, out, code, readText(e.string()), {mpirun(2)});
}
#endif

}  // namespace
}  // namespace vroc::test
