// SPDX-License-Identifier: MIT
// The restitution mapping and the MJCF writer, against independent answers.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "contact_materials.h"
#include "mjcf_writer.h"
#include "model_loader.h"
#include "restitution_mapping.h"
#include "test_scenes.h"

namespace vroc::test {
namespace {

// Closed form of the underdamped contact released at zero force (unit entry speed, w = 1):
// x = e^(-zeta t) sin(s t) / s, s = sqrt(1 - zeta^2); the force x + 2 zeta x' vanishes at
// s t = theta = atan2(2 zeta s, 2 zeta^2 - 1), and e = e^(-zeta theta / s) |cos theta - zeta/s sin theta|.
double closedForm(double zeta) {
    const double s = std::sqrt(1 - zeta * zeta);
    const double theta = std::atan2(2 * zeta * s, 2 * zeta * zeta - 1);
    return std::exp(-zeta * theta / s) * std::abs(std::cos(theta) - zeta / s * std::sin(theta));
}

TEST(MujocoMapping, ReleaseRestitutionMatchesTheClosedForm) {
    EXPECT_NEAR(mujoco::releaseRestitution(0.0), 1.0, 1e-9);
    for (double zeta : {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9})
        EXPECT_NEAR(mujoco::releaseRestitution(zeta), closedForm(zeta), 1e-8) << zeta;
    // Critical damping: x = t e^-t, force zero at t = 2, e = e^-2.
    EXPECT_NEAR(mujoco::releaseRestitution(1.0), std::exp(-2.0), 1e-8);
    // Released at zero force, the contact gives back more than exp(-zeta pi / s) (release at x = 0).
    EXPECT_GT(mujoco::releaseRestitution(0.3), std::exp(-0.3 * M_PI / std::sqrt(1 - 0.09)));
    for (double e : {0.2, 0.5, 0.8, 0.99}) EXPECT_NEAR(mujoco::releaseRestitution(mujoco::dampingRatioFor(e, 2.0)), e, 1e-8);
    EXPECT_EQ(mujoco::dampingRatioFor(1.0, 2.0), 0.0);
    EXPECT_EQ(mujoco::dampingRatioFor(0.0, 2.0), 2.0);   // floored at the damping cap
    const mujoco::ContactSpring s = mujoco::contactSpring(0.5, 0.008, 0.002);
    EXPECT_DOUBLE_EQ(s.stiffness, 1.0 / (0.008 * 0.008));
    EXPECT_NEAR(s.damping, 2 * mujoco::dampingRatioFor(0.5, 2.0) / 0.008, 1e-9);
    std::printf("damping ratio for e = 0.5: %.6f, e = 0: %.3f (cap; releaseRestitution %.4f)\n",
                mujoco::dampingRatioFor(0.5, 2.0), mujoco::dampingRatioFor(0.0, 2.0), mujoco::releaseRestitution(2.0));
}

// Two materials (two groups), a real floor, a ball, a hull with an off-origin COM and a
// non-diagonal inertia, a compound: the compiled model carries the scene's masses and inertias.
Scene smallScene() {
    Scene scene = emptyScene(0.5, 0.4);
    const int rubber = addMaterial(scene, "rubber", 0.8, 0.9);
    addFloor(scene);
    addBall(scene, "ball", 0.1, 2.0, Vec3(0, 0, 1), rubber);
    Pose pose;
    pose.position = Vec3(1, 0, 1);
    pose.orientation = Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ()));
    addHullCuboid(scene, "hull", Vec3(0.2, 0.1, 0.05), 3.0, pose, Quat(Eigen::AngleAxisd(0.5, Vec3(1, 1, 0).normalized())),
                  Vec3(0.01, 0.02, 0.03));
    Body dumbbell;
    dumbbell.name = "dumbbell";
    dumbbell.material = rubber;
    ShapePart left{Shape::sphere(0.05), Pose{Vec3(-0.15, 0, 0), Quat::Identity()}};
    ShapePart right{Shape::sphere(0.05), Pose{Vec3(0.15, 0, 0), Quat::Identity()}};
    ShapePart bar{Shape::box(Vec3(0.1, 0.01, 0.01)), Pose::identity()};
    dumbbell.shape = Shape::compound({left, right, bar});
    dumbbell.pose.position = Vec3(-1, 0, 0.5);
    dumbbell.mass_properties.mass = 2.0;
    dumbbell.mass_properties.inertia = Vec3(0.001, 0.02, 0.02).asDiagonal();
    scene.bodies.push_back(dumbbell);
    return scene;
}

TEST(MujocoMjcf, MassesInertiasAndMaterialsSurviveCompilation) {
    const Scene scene = smallScene();
    const mujoco::ContactMaterials materials(scene, 0.008, 0.002, true);
    mujoco::SolverOptions options;   // MuJoCo's defaults
    options.timestep = scene.frame_dt / 9;
    const std::string xml = mujoco::writeMjcf(scene, materials, options);
    std::printf("%s", xml.c_str());
    const mujoco::ModelPtr model = mujoco::loadModel(xml, scene.name);
    const mjModel& m = *model;
    EXPECT_EQ(m.opt.timestep, scene.frame_dt / 9);
    EXPECT_EQ(m.opt.gravity[2], -9.81);
    EXPECT_EQ(m.nbody, 5);      // world + 4 scene bodies
    EXPECT_EQ(m.ngeom, 6);      // floor, ball, hull, 3 dumbbell parts
    EXPECT_EQ(m.nmesh, 1);
    for (std::size_t i = 1; i < scene.bodies.size(); ++i) {
        const Body& b = scene.bodies[i];
        const int id = mj_name2id(&m, mjOBJ_BODY, mujoco::bodyName(static_cast<int>(i)).c_str());
        ASSERT_GT(id, 0);
        EXPECT_EQ(m.body_mass[id], b.mass_properties.mass) << b.name;
        // The MuJoCo body frame is the principal frame: inertial frame = body frame, and
        // R diag(body_inertia) R^T in scene body axes is the scene's inertia about the COM.
        EXPECT_EQ(m.body_ipos[3 * id] * m.body_ipos[3 * id] + m.body_ipos[3 * id + 1] * m.body_ipos[3 * id + 1] +
                      m.body_ipos[3 * id + 2] * m.body_ipos[3 * id + 2], 0.0) << b.name;
        const Vec3 diag(m.body_inertia[3 * id], m.body_inertia[3 * id + 1], m.body_inertia[3 * id + 2]);
        const Quat body_q(m.body_quat[4 * id], m.body_quat[4 * id + 1], m.body_quat[4 * id + 2], m.body_quat[4 * id + 3]);
        const Quat iq(m.body_iquat[4 * id], m.body_iquat[4 * id + 1], m.body_iquat[4 * id + 2], m.body_iquat[4 * id + 3]);
        const Mat3 R = (b.pose.orientation.conjugate() * body_q * iq).toRotationMatrix();   // principal -> scene body axes
        const Mat3 I = R * diag.asDiagonal() * R.transpose();
        EXPECT_LT((I - b.mass_properties.inertia).norm(), 1e-12 * b.mass_properties.inertia.norm()) << b.name << "\n" << I;
        // The body sits at the COM.
        const Vec3 com(m.body_pos[3 * id], m.body_pos[3 * id + 1], m.body_pos[3 * id + 2]);
        EXPECT_LT((com - b.pose.apply(b.mass_properties.center_of_mass)).norm(), 1e-12) << b.name;
    }
    // Materials: the floor (e 0.5, mu 0.4) and the hull share a group (geom values); the rubber
    // bodies (e 0.8, mu 0.9) form the other, so rubber-floor and rubber-hull pairs are explicit.
    const int floor_geom = mj_name2id(&m, mjOBJ_GEOM, "g0_0");
    EXPECT_EQ(m.geom_friction[3 * floor_geom], 0.4);
    EXPECT_EQ(m.geom_margin[floor_geom], 1e-3);
    EXPECT_EQ(m.geom_gap[floor_geom], 1e-3);
    // ball x (floor, hull) + dumbbell (3 parts) x (floor, hull): 2 + 6 pairs; ball-dumbbell share a group.
    EXPECT_EQ(m.npair, 8);
    EXPECT_EQ(m.nexclude, 4);
    for (int p = 0; p < m.npair; ++p) {
        EXPECT_DOUBLE_EQ(m.pair_friction[5 * p], std::sqrt(0.4 * 0.9));
        EXPECT_DOUBLE_EQ(m.pair_friction[5 * p + 1], std::sqrt(0.4 * 0.9));
        const mujoco::ContactSpring s = mujoco::contactSpring(0.5, 0.008, 0.002);   // min(0.5, 0.8)
        EXPECT_DOUBLE_EQ(m.pair_solref[2 * p], -s.stiffness);
        EXPECT_DOUBLE_EQ(m.pair_solref[2 * p + 1], -s.damping);
    }
    // The hull mesh: MuJoCo keeps the 8 vertices (as floats).
    EXPECT_EQ(m.mesh_vertnum[0], 8);
}

TEST(MujocoMjcf, RealRealPairsNeverCollide) {
    Scene scene = emptyScene();
    addFloor(scene);
    Body block;
    block.name = "block";
    block.role = BodyRole::Real;
    block.shape = Shape::box(Vec3(0.5, 0.5, 0.5));
    block.pose.position = Vec3(0, 0, 0.25);   // overlapping the floor
    scene.bodies.push_back(block);
    addBall(scene, "ball", 0.1, 1.0, Vec3(3, 0, 0.5));
    auto backend = makeMujoco(scene);
    run(*backend, scene, 10);
    EXPECT_EQ(backend->statistics().at("contact_points"), 0);
}

}  // namespace
}  // namespace vroc::test
