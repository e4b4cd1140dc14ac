// SPDX-License-Identifier: MIT
#include "vroc/harness/pool/mpi_world.h"

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#ifdef VROC_WITH_MPI
#define OMPI_SKIP_MPICXX 1   // the C API only: the deprecated C++ bindings need libmpi_cxx
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace vroc::harness::mpi {
namespace {

int g_rank = 0;
int g_size = 1;

#ifdef VROC_WITH_MPI
bool g_active = false;

bool launchedByMpirun() {
    for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
        if (std::getenv(v)) return true;
    return false;
}
#endif

// Polls sleep this long: short next to a run (milliseconds to minutes), long enough that an idle
// rank costs no CPU.
constexpr auto kPoll = std::chrono::microseconds(500);

}  // namespace

bool available() {
#ifdef VROC_WITH_MPI
    return true;
#else
    return false;
#endif
}

void initialize(int& argc, char**& argv) {
#ifdef VROC_WITH_MPI
    if (!launchedByMpirun()) return;
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &g_size);
    g_active = true;
#else
    (void)argc;
    (void)argv;
#endif
}

void finalize() {
#ifdef VROC_WITH_MPI
    if (g_active) MPI_Finalize();
    g_active = false;
#endif
}

void abortAll(int code) {
#ifdef VROC_WITH_MPI
    if (g_active) MPI_Abort(MPI_COMM_WORLD, code);
#endif
    std::exit(code);
}

int rank() { return g_rank; }
int size() { return g_size; }

std::string libraryVersion() {
#ifdef VROC_WITH_MPI
    char text[MPI_MAX_LIBRARY_VERSION_STRING];
    int n = 0;
    MPI_Get_library_version(text, &n);
    std::string s(text, static_cast<std::size_t>(n));
    if (const auto nl = s.find_first_of(std::string("\r\n\0", 3)); nl != std::string::npos) s.resize(nl);
    return s;
#else
    return "none";
#endif
}

#ifdef VROC_WITH_MPI
void sendText(int to, int tag, const std::string& text) {
    MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

bool receiveText(int tag, int& from, std::string& text) {
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &flag, &status);
    if (!flag) return false;
    int n = 0;
    MPI_Get_count(&status, MPI_CHAR, &n);
    text.assign(static_cast<std::size_t>(n), '\0');
    from = status.MPI_SOURCE;
    MPI_Recv(text.data(), n, MPI_CHAR, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return true;
}

std::string waitText(int from, int tag) {
    for (;;) {
        int flag = 0;
        MPI_Status status;
        MPI_Iprobe(from, tag, MPI_COMM_WORLD, &flag, &status);
        if (flag) {
            int n = 0;
            MPI_Get_count(&status, MPI_CHAR, &n);
            std::string text(static_cast<std::size_t>(n), '\0');
            MPI_Recv(text.data(), n, MPI_CHAR, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            return text;
        }
        std::this_thread::sleep_for(kPoll);
    }
}

void broadcastText(std::string& text) {
    if (!g_active) return;
    unsigned long long n = text.size();
    MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    text.resize(static_cast<std::size_t>(n));
    // MPI counts are int: send in chunks of 1 GiB.
    for (unsigned long long off = 0; off < n; off += (1ull << 30)) {
        const int chunk = static_cast<int>(std::min<unsigned long long>(n - off, 1ull << 30));
        MPI_Bcast(text.data() + off, chunk, MPI_CHAR, 0, MPI_COMM_WORLD);
    }
}
#else
void sendText(int, int, const std::string&) { throw std::logic_error("mpi::sendText without MPI"); }
bool receiveText(int, int&, std::string&) { return false; }
std::string waitText(int, int) { throw std::logic_error("mpi::waitText without MPI"); }
void broadcastText(std::string&) {}
#endif

}  // namespace vroc::harness::mpi
