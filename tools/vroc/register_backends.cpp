// SPDX-License-Identifier: MIT
#include "register_backends.h"

#include "vroc/bullet/bullet_backend.h"
#include "vroc/native/native_backend.h"

namespace vroc::cli {

// The one place that names the backends: tools may know them, core never does.
void registerBackends() {
    vroc::bullet::registerBackend();
    vroc::native::registerBackend();
}

}  // namespace vroc::cli
