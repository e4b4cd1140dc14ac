// SPDX-License-Identifier: MIT
// A RunTrace as JSON and back, exactly: every double is written in its shortest round-trip form, so
// a trace read back is bit-identical to the one written (non-finite numbers are written as null and
// read back as NaN). This is how a run made in another process or on another MPI rank reaches the
// process that writes the report (run_pool.h).
#pragma once

#include "vroc/harness/documents/metrics_document.h"
#include "vroc/harness/runs/run_trace.h"

namespace vroc::harness {

Json stateJson(const BodyState& state);   ///< [px,py,pz, qx,qy,qz,qw, vx,vy,vz, wx,wy,wz]
BodyState stateFromJson(const Json& j);    ///< throws InputError on a malformed array

Json statesJson(const std::vector<BodyState>& states);
std::vector<BodyState> statesFromJson(const Json& j);

Json runTraceJson(const RunTrace& trace);
RunTrace runTraceFromJson(const Json& j);   ///< throws InputError on a malformed document

}  // namespace vroc::harness
