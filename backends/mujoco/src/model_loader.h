// SPDX-License-Identifier: MIT
// MJCF text -> mjModel, through MuJoCo 2.2's virtual file system (2.2 has no load-from-string:
// the text becomes the in-memory file "model.xml"). Also owns MuJoCo's process-wide message
// handlers: warnings are not printed (the backend counts them from mjData::warning) and an error
// throws RunError instead of MuJoCo's default, which prints, waits for Enter and exits.
#pragma once

#include <memory>
#include <string>

#include <mujoco/mujoco.h>

namespace vroc::mujoco {

struct ModelDeleter {
    void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
    void operator()(mjData* d) const { mj_deleteData(d); }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;
using DataPtr = std::unique_ptr<mjData, DataDeleter>;

/// Installs the handlers described above and the passive callback (passive_callback.h); idempotent.
void installMessageHandlers();

/// Compiles `xml`. Throws InputError "mujoco: scene '<name>': MuJoCo refused the model: <MuJoCo's text>".
ModelPtr loadModel(const std::string& xml, const std::string& scene_name);

}  // namespace vroc::mujoco
