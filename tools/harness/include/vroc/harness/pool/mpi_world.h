// SPDX-License-Identifier: MIT
// The MPI world the `vroc` process runs in: one rank (size 1) unless it was started by `mpirun` and
// the build has MPI (VROC_WITH_MPI, on by default when Open MPI is installed). Only the run pool
// (src/pool/) talks MPI; every other part of the harness sees rank and size.
#pragma once

#include <string>
#include <vector>

namespace vroc::harness::mpi {

/// Starts MPI if this process was launched by mpirun (OMPI_COMM_WORLD_SIZE / PMI_SIZE in the
/// environment) and the build has MPI; otherwise a world of one. Call once, first thing in main().
void initialize(int& argc, char**& argv);
/// Ends MPI (no-op for a world of one). Call once before returning from main().
void finalize();
/// Ends every rank of the job at once with `code` (MPI_Abort; std::exit for a world of one).
[[noreturn]] void abortAll(int code);

int rank();                        ///< 0 .. size()-1
int size();                        ///< 1 without MPI
inline bool isRoot() { return rank() == 0; }   ///< the rank that writes every file and report
bool available();                  ///< built with MPI
std::string libraryVersion();      ///< "Open MPI v4.1.4, ..." or "none"

// Point-to-point messages of text; the receivers poll (receive*) so that waiting ranks sleep
// instead of spinning on a core another rank's run needs.
void sendText(int to, int tag, const std::string& text);
/// A message with `tag` from any rank if one has arrived: true and fills (from, text).
bool receiveText(int tag, int& from, std::string& text);
/// Blocks (sleeping between polls) until a message with `tag` arrives from `from`.
std::string waitText(int from, int tag);
/// Rank 0's text to every rank (collective).
void broadcastText(std::string& text);

}  // namespace vroc::harness::mpi
