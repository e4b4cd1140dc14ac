# Unity ("jumbo") builds for the libraries and the `vroc` program (issue 26): CMake compiles each
# target's sources in batches of 8, one translation unit per batch, so the heavy third-party
# headers they share (nlohmann/json, CLI11, fmt, Eigen) are parsed and their templates instantiated
# once per batch instead of once per file.
# Not for the native backend (its files are few and heavy with Eigen's solvers: batching them made
# one 182 s translation unit, the whole build's critical path, and touching one of them would
# recompile its batch) nor for the tests (tests/CMakeLists.txt turns it off again: a failing test
# file is easier to read alone, and their helpers share names across files).
# Off with -DVROC_UNITY_BUILD=OFF (every file its own translation unit, as before).
option(VROC_UNITY_BUILD "Compile the libraries' and tools' sources in batches (unity build)" ON)
set(CMAKE_UNITY_BUILD ${VROC_UNITY_BUILD})
set(CMAKE_UNITY_BUILD_BATCH_SIZE 8)
