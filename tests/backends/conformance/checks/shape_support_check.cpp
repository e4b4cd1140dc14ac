// SPDX-License-Identifier: MIT
#include "checks/shape_support_check.h"

#include <exception>
#include <string>
#include <vector>

#include "checks/check_support.h"
#include "conformance_scenes.h"
#include "vroc/core/errors.h"

namespace vroc::conformance {
namespace {

struct DeclaredFeature {
    std::string name;
    Support support = Support::Unsupported;
    Scene scene;  ///< lonelyBody of a shape that needs it
};

std::vector<DeclaredFeature> declaredFeatures(const BackendCapabilities& c) {
    const Shape pair =
        Shape::compound({{Shape::sphere(0.1), at(Vec3(0.2, 0, 0))}, {Shape::sphere(0.1), at(Vec3(-0.2, 0, 0))}});
    return {{"sphere", c.sphere, lonelyBody(Shape::sphere(0.2))},
            {"box", c.box, lonelyBody(Shape::box(Vec3(0.2, 0.2, 0.2)))},
            {"hull", c.hull, lonelyBody(irregularHull())},
            {"compound", c.compound, lonelyBody(pair)},
            {"tracked", c.tracked, lonelyTrackedBody(Shape::sphere(0.2))}};
}

void checkRefused(const BackendInfo& backend, const DeclaredFeature& f, CheckResult& r) {
    try {
        createBackend(backend, f.scene);
        r.fail(f.name, " is declared unsupported, yet a scene with one was created (InputError expected)");
    } catch (const InputError& e) {
        if (std::string(e.what()).find("body") == std::string::npos)
            r.fail(f.name, " refused without naming the body: ", e.what());
    }
}

void checkAccepted(const BackendInfo& backend, const DeclaredFeature& f, CheckResult& r) {
    try {
        auto b = createBackend(backend, f.scene);
        for (int frame = 0; frame < 10; ++frame) b->stepFrame(f.scene.frame_dt);
        for (int i = 0; i < b->bodyCount(); ++i)
            if (!finite(b->bodyState(i)))
                r.fail(f.name, " (", supportName(f.support), "): body ", i, " not finite after 10 frames");
    } catch (const std::exception& e) {
        r.fail(f.name, " is declared ", supportName(f.support), ", yet the scene threw: ", e.what());
    }
}

}  // namespace

CheckResult checkShapeSupport(const BackendInfo& backend) {
    CheckResult r{backend.name, {}};
    for (const DeclaredFeature& f : declaredFeatures(backend.capabilities)) {
        if (f.support == Support::Unsupported)
            checkRefused(backend, f, r);
        else
            checkAccepted(backend, f, r);
    }
    return r;
}

}  // namespace vroc::conformance
