// SPDX-License-Identifier: MIT
// ODE's process-wide state, used the same way by every ODE backend in the process:
//  - the library is initialised once (dInitODE2) and never closed (backends may live until exit);
//  - each thread that collides or steps needs ODE's thread-local data (dAllocateODEDataForThread);
//  - dWorldQuickStep reorders constraint rows with ODE's one process-wide random generator
//    (dRandInt). Each backend keeps its own generator state and swaps it in around its steps,
//    so a run gives the same bits whatever other ODE backends did before or beside it;
//  - ODE reports trouble it recovers from (the Dantzig LCP giving up on a near-singular system)
//    through one process-wide message handler, which prints by default. It is replaced by one
//    that counts the message for the backend working on the calling thread (MessageCapture).
#pragma once

#include <ode/ode.h>

#include <cstdint>

#include "ode_config.h"

static_assert(sizeof(dReal) == 8, "the ODE backend needs ODE in double precision (dDOUBLE)");

namespace vroc::ode {

/// Initialises ODE once per process and ODE's data for the calling thread. Cheap when done.
void ensureOdeReady();

/// ODE messages (dMessage) counted while a backend works.
struct OdeMessageCounts {
    std::uint64_t lcp = 0;     ///< d_ERR_LCP: the LCP solver stopped early and zeroed the rest
    std::uint64_t other = 0;   ///< any other message
};

/// While alive, ODE messages raised on this thread are counted in `counts`, not printed.
/// Messages with no capture alive are printed to stderr as ODE would.
class MessageCapture {
public:
    explicit MessageCapture(OdeMessageCounts& counts);
    ~MessageCapture();
    MessageCapture(const MessageCapture&) = delete;
    MessageCapture& operator=(const MessageCapture&) = delete;

private:
    OdeMessageCounts* previous_;
};

/// One world step of `h` [s] with `stepper`, with the caller's random-generator state `seed`
/// in ODE's place for its duration (updated on return). Serialised with every other ODE
/// backend's steps, since the generator is process-wide. Returns false if ODE could not
/// allocate its working memory (the world is then unchanged).
bool seededWorldStep(dWorldID world, Stepper stepper, double h, unsigned long& seed);

}  // namespace vroc::ode
