// SPDX-License-Identifier: MIT
// `vroc`: the command-line program. Parses with CLI11, runs the chosen command and maps errors to
// exit codes: 0 success, 2 bad input or usage, 3 failure while running (docs/cli.md).
#include <malloc.h>
#include <unistd.h>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "command.h"
#include "vroc/core/build_info.h"
#include "vroc/core/errors.h"
#include "vroc/harness/pool/mpi_world.h"
#include "vroc/registration/register_backends.h"

namespace {

constexpr int kExitInput = 2;
constexpr int kExitRun = 3;

// Every error is one line: multi-line messages (e.g. the list of valid --set keys) are joined.
std::string oneLine(const std::string& message) {
    std::string out;
    bool at_line_start = false;
    for (char c : message) {
        if (c == '\n' || c == '\r') {
            if (!out.empty() && out.back() != ' ') out += out.back() == ':' ? " " : "; ";
            at_line_start = true;
            continue;
        }
        if (at_line_start && (c == ' ' || c == '\t')) continue;
        at_line_start = false;
        out += c;
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
    return out;
}

// Under mpirun every rank meets the same bad input: only rank 0 says so. A failure while running
// may be one rank's own, so every rank reports it, named.
int fail(int code, const std::string& message) {
    const int rank = vroc::harness::mpi::rank();
    if (code == kExitInput && rank != 0) return code;
    const std::string who = vroc::harness::mpi::size() > 1 ? "vroc (rank " + std::to_string(rank) + ")" : "vroc";
    std::fprintf(stderr, "%s: error: %s\n", who.c_str(), oneLine(message).c_str());
    return code;
}

// The commands whose runs RunPool spreads over ranks; rank 0 alone writes their files.
bool runsUnderMpi(const std::string& command) {
    return command == "sweep" || command == "check" || command == "compare" || command == "ensemble";
}

std::string shellQuoted(const std::string& word) {
    if (!word.empty() && word.find_first_of(" \t\n'\"\\$`*?[]{}()<>|&;#~") == std::string::npos) return word;
    std::string out = "'";
    for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string joinCommandLine(int argc, char** argv) {
    std::string out;
    for (int i = 0; i < argc; ++i) out += (i ? " " : "") + shellQuoted(argv[i]);
    return out;
}

std::string versionText() {
    const auto& b = vroc::buildInfo();
    return "vroc " + b.version + " (commit " + b.commit + ", " + b.compiler + ", " + b.flags + ")";
}

}  // namespace

static int runCommand(int argc, char** argv) {
    vroc::registration::registerBackends();
    vroc::cli::Context context{joinCommandLine(argc, argv), ::isatty(STDERR_FILENO) == 1};

    CLI::App app{"VROC: collision detection and response between virtual objects and a static model "
                 "of the real world, with physics backends chosen at run time and compared.",
                 "vroc"};
    app.set_version_flag("--version", versionText());
    app.require_subcommand(1);
    app.footer("Run `vroc <command> --help` for a command's options.\n"
               "Exit codes: 0 success, 2 bad input or usage, 3 failure while running.");

    struct Entry {
        CLI::App* sub;
        vroc::cli::Action action;
    };
    std::vector<Entry> entries;
    for (const auto& command : vroc::cli::allCommands()) {
        CLI::App* sub = app.add_subcommand(command.name, command.summary);
        entries.push_back({sub, command.setup(*sub, context)});
    }

    // CLI11 reports an unknown command word as "a subcommand is required"; say what was wrong.
    if (argc > 1 && argv[1][0] != '-') {
        std::string known;
        bool found = false;
        for (const auto& command : vroc::cli::allCommands()) {
            known += (known.empty() ? "" : ", ") + std::string(command.name);
            found = found || argv[1] == std::string(command.name);
        }
        if (!found) return fail(kExitInput, "unknown command '" + std::string(argv[1]) + "' (known: " + known + ")");
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::string help = "vroc --help";
        for (const auto& entry : entries)
            if (entry.sub->parsed()) help = "vroc " + entry.sub->get_name() + " --help";
        return fail(kExitInput, std::string(e.what()) + " (see `" + help + "`)");
    }

    try {
        for (const auto& entry : entries)
            if (entry.sub->parsed()) {
                if (vroc::harness::mpi::size() > 1 && !runsUnderMpi(entry.sub->get_name()))
                    return fail(kExitInput, "`vroc " + entry.sub->get_name() +
                                                "` does not run under mpirun (one process would write the same files as every other); "
                                                "mpirun runs vroc sweep, check, compare and ensemble");
                return entry.action();
            }
        return fail(kExitInput, "no command given (see `vroc --help`)");
    } catch (const vroc::InputError& e) {
        return fail(kExitInput, e.what());
    } catch (const vroc::RunError& e) {
        return fail(kExitRun, e.what());
    } catch (const std::exception& e) {
        return fail(kExitRun, std::string("unexpected failure: ") + e.what());
    }
}

int main(int argc, char** argv) {
    // A backend step allocates and frees its working sets every frame. glibc's defaults hand a freed
    // heap top (and every block above 128 KiB, mmapped) back to the kernel and fault it in again at
    // the next step: 15 % of a dense-contact run went to page faults. Keeping up to 256 MiB lets
    // every backend reuse its memory; it changes no result.
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
    mallopt(M_MMAP_THRESHOLD, 64 << 20);
    vroc::harness::mpi::initialize(argc, argv);
    const int code = runCommand(argc, argv);
    // A rank that fails may leave others waiting for it: end them all (mpirun reports the code).
    if (code >= 2 && vroc::harness::mpi::size() > 1) {
        std::fflush(nullptr);
        vroc::harness::mpi::abortAll(code);
    }
    vroc::harness::mpi::finalize();
    return code;
}
