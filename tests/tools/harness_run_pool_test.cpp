// SPDX-License-Identifier: MIT
// RunPool: results in job order and bit-identical whether jobs ran here or in forked workers;
// failures named without losing the other runs; --resume reruns only what is missing and refuses
// another plan's runs.
#include <gtest/gtest.h>

#include <csignal>
#include <cmath>
#include <fstream>

#include "test_scenes.h"
#include "vroc/core/errors.h"
#include "vroc/harness/pool/run_pool.h"

namespace vroc::harness {
namespace {

namespace fs = std::filesystem;

// Results with awkward doubles (not exactly representable in decimal, subnormal, negative zero).
std::vector<PoolJob> arithmeticJobs(int n, const fs::path& marks = {}) {
    std::vector<PoolJob> jobs;
    for (int i = 0; i < n; ++i)
        jobs.push_back({"job-" + std::to_string(i), [i, marks] {
            if (!marks.empty()) std::ofstream(marks / ("ran-" + std::to_string(i))) << "x";   // forked runs leave a mark
            double s = 0;
            for (int k = 1; k <= 1000 + i; ++k) s += 1.0 / (k * 3.0 + i);
            return Json{{"i", i}, {"sum", s}, {"tiny", 4.9e-324 * (i + 1)}, {"negzero", -0.0}, {"third", (i + 1) / 3.0}};
        }});
    return jobs;
}

PoolOptions options(const fs::path& dir, int jobs, bool resume = false) {
    PoolOptions o;
    o.jobs = jobs;
    o.runs_dir = dir / "runs";
    o.resume = resume;
    o.plan = {{"test", "arithmetic"}};
    return o;
}

TEST(RunPool, ForkedWorkersGiveTheSameBitsInJobOrder) {
    const fs::path dir = test::freshTempDir("run-pool-order");
    RunPool here(options(dir / "a", 1));
    RunPool forked(options(dir / "b", 3));
    const std::vector<Json> a = here.run(arithmeticJobs(10));
    const std::vector<Json> b = forked.run(arithmeticJobs(10));
    ASSERT_EQ(a.size(), 10u);
    ASSERT_EQ(b.size(), 10u);
    for (int i = 0; i < 10; ++i) {
        EXPECT_EQ(a[i]["i"], i);
        EXPECT_EQ(a[i].dump(), b[i].dump());
        const double sa = a[i]["sum"], sb = b[i]["sum"];
        EXPECT_EQ(std::memcmp(&sa, &sb, sizeof sa), 0);
        EXPECT_TRUE(std::signbit(b[i]["negzero"].get<double>()));
        EXPECT_EQ(b[i]["tiny"].get<double>(), 4.9e-324 * (i + 1));
        EXPECT_TRUE(fs::exists(dir / "b" / "runs" / ("job-" + std::to_string(i) + ".json")));
    }
    EXPECT_EQ(forked.execution().runs, 10);
}

TEST(RunPool, WithoutARunsFolderForkedWorkersSendTheirResultsOverThePipes) {
    const fs::path dir = test::freshTempDir("run-pool-pipes");
    fs::create_directories(dir / "marks");
    PoolOptions o;
    o.jobs = 2;   // no runs_dir: nothing is written, yet the runs go to forked workers
    const std::vector<Json> piped = RunPool(o).run(arithmeticJobs(8, dir / "marks"));
    const std::vector<Json> here = RunPool::inProcess().run(arithmeticJobs(8));
    ASSERT_EQ(piped.size(), 8u);
    for (int i = 0; i < 8; ++i) {
        EXPECT_EQ(piped[i].dump(), here[i].dump());
        EXPECT_TRUE(std::signbit(piped[i]["negzero"].get<double>()));
        EXPECT_TRUE(fs::exists(dir / "marks" / ("ran-" + std::to_string(i))));
    }
    // Only the marks: no run files, no status file anywhere in the folder.
    int files = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 8);
}

TEST(RunPool, AFailedOrCrashedRunIsNamedAndTheOthersAreKept) {
    const fs::path dir = test::freshTempDir("run-pool-fail");
    for (int jobs : {1, 2}) {
        std::vector<PoolJob> work = arithmeticJobs(4);
        work[1].run = [] () -> Json { throw RunError("solver diverged"); };
        // A crash costs only its own run. (Default disposition first: a sanitizer build would
        // otherwise catch the signal and abort instead.)
        if (jobs > 1) work[2].run = [] () -> Json { std::signal(SIGSEGV, SIG_DFL); std::raise(SIGSEGV); return {}; };
        RunPool pool(options(dir / std::to_string(jobs), jobs));
        try {
            pool.run(work);
            FAIL() << "failed runs must be reported";
        } catch (const RunError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("job-1: solver diverged"), std::string::npos) << what;
            if (jobs > 1) {
                EXPECT_NE(what.find("job-2: worker killed by signal 11"), std::string::npos) << what;
            }
            EXPECT_NE(what.find("--resume"), std::string::npos) << what;
        }
        EXPECT_TRUE(fs::exists(dir / std::to_string(jobs) / "runs" / "job-0.json"));
        EXPECT_TRUE(fs::exists(dir / std::to_string(jobs) / "runs" / "job-3.json"));
        EXPECT_FALSE(fs::exists(dir / std::to_string(jobs) / "runs" / "job-1.json"));
    }
}

TEST(RunPool, ResumeRunsOnlyWhatIsMissing) {
    const fs::path dir = test::freshTempDir("run-pool-resume");
    const fs::path marks = dir / "marks";
    fs::create_directories(marks);
    std::vector<Json> first;
    {
        RunPool pool(options(dir, 2));
        first = pool.run(arithmeticJobs(6, marks));
    }
    fs::remove(dir / "runs" / "job-2.json");
    fs::remove(dir / "runs" / "job-5.json");
    fs::remove_all(marks);
    fs::create_directories(marks);
    RunPool again(options(dir, 2, true));
    const std::vector<Json> second = again.run(arithmeticJobs(6, marks));
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(first[i].dump(), second[i].dump());
        EXPECT_EQ(fs::exists(marks / ("ran-" + std::to_string(i))), i == 2 || i == 5) << i;
    }
    EXPECT_EQ(again.execution().resumed, 4);
    std::ifstream status(dir / "runs" / "status.json");
    const Json s = Json::parse(status);
    EXPECT_TRUE(s["complete"].get<bool>());
}

TEST(RunPool, ResumeRefusesAnotherPlansRuns) {
    const fs::path dir = test::freshTempDir("run-pool-plan");
    RunPool(options(dir, 1)).run(arithmeticJobs(2));
    PoolOptions other = options(dir, 1, true);
    other.plan = {{"test", "something else"}};
    RunPool pool(other);
    EXPECT_THROW(pool.run(arithmeticJobs(2)), InputError);
}

TEST(RunPool, WithoutResumeTheFolderStartsEmpty) {
    const fs::path dir = test::freshTempDir("run-pool-fresh");
    RunPool(options(dir, 1)).run(arithmeticJobs(3));
    RunPool(options(dir, 1)).run(arithmeticJobs(1));
    EXPECT_FALSE(fs::exists(dir / "runs" / "job-2.json"));
}

TEST(RunPool, JobIdsAreFileNameSafe) {
    EXPECT_EQ(poolJobId("step-bullet solver_iterations=50-dt1/240"), "step-bullet_solver_iterations=50-dt1_240");
}

}  // namespace
}  // namespace vroc::harness
