// SPDX-License-Identifier: MIT
#include "model_loader.h"

#include <cstring>

#include "passive_callback.h"
#include "vroc/core/errors.h"

namespace vroc::mujoco {
namespace {

void throwError(const char* message) { throw RunError(std::string("mujoco: ") + message); }
void ignoreWarning(const char*) {}

}  // namespace

void installMessageHandlers() {
    mju_user_error = &throwError;
    mju_user_warning = &ignoreWarning;
    installPassiveCallback();
}

ModelPtr loadModel(const std::string& xml, const std::string& scene_name) {
    installMessageHandlers();
    const std::string context = "mujoco: scene '" + scene_name + "': ";
    // mjVFS holds 2000 file names of 1000 bytes: about 2 MB, so never on the stack.
    auto vfs = std::make_unique<mjVFS>();
    mj_defaultVFS(vfs.get());
    const int size = static_cast<int>(xml.size()) + 1;   // with the terminating NUL
    if (mj_makeEmptyFileVFS(vfs.get(), "model.xml", size) != 0)
        throw InputError(context + "cannot create the in-memory model file");
    const int index = mj_findFileVFS(vfs.get(), "model.xml");
    std::memcpy(vfs->filedata[index], xml.c_str(), static_cast<std::size_t>(size));
    char error[1024] = "";
    mjModel* model = nullptr;
    try {
        model = mj_loadXML("model.xml", vfs.get(), error, sizeof error);
    } catch (const RunError& e) {
        mj_deleteVFS(vfs.get());
        throw InputError(context + "MuJoCo refused the model: " + e.what());
    }
    mj_deleteVFS(vfs.get());
    if (!model) throw InputError(context + "MuJoCo refused the model: " + error);
    return ModelPtr(model);
}

}  // namespace vroc::mujoco
