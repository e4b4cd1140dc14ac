// SPDX-License-Identifier: MIT
#include "mjcf_writer.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <vector>

#include "box_depth_bound.h"
#include "friction_damping.h"
#include "principal_frame.h"

namespace vroc::mujoco {
namespace {

std::string num(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}
std::string vec(const Vec3& v) { return num(v.x()) + " " + num(v.y()) + " " + num(v.z()); }
std::string quat(const Quat& q) { return num(q.w()) + " " + num(q.x()) + " " + num(q.y()) + " " + num(q.z()); }
std::string attr(const char* name, const std::string& value) { return std::string(" ") + name + "=\"" + value + "\""; }

// MuJoCo's defaults for the torsional and rolling coefficients (unused with condim 3).
constexpr const char* kSpinFriction = "0.005";
constexpr const char* kRollFriction = "0.0001";

// Contact attributes shared by geoms and pairs: solref and margin/gap.
std::string contactAttributes(const PairMaterial& m, double collision_distance) {
    std::string s;
    if (!m.default_solref) s += attr("solref", num(-m.spring.stiffness) + " " + num(-m.spring.damping));
    s += attr("margin", num(collision_distance)) + attr("gap", num(collision_distance));
    return s;
}

// Real geoms: contype 2, conaffinity 1; tracked: contype 4, conaffinity 0; virtual: contype 1,
// conaffinity 7. A pair collides when (contype_a & conaffinity_b) || (contype_b & conaffinity_a):
// every pair with a virtual body, no pair without one.
std::string collisionBits(BodyRole role) {
    switch (role) {
        case BodyRole::Real: return attr("contype", "2") + attr("conaffinity", "1");
        case BodyRole::Tracked: return attr("contype", "4") + attr("conaffinity", "0");
        case BodyRole::Virtual: break;
    }
    return attr("contype", "1") + attr("conaffinity", "7");
}

struct Part {
    const Shape* shape;
    Pose pose;   // part frame -> scene body frame
};

std::vector<Part> partsOf(const Shape& shape) {
    if (shape.kind != Shape::Kind::Compound) return {{&shape, Pose::identity()}};
    std::vector<Part> parts;
    for (const ShapePart& p : shape.parts) parts.push_back({&p.shape, p.pose});
    return parts;
}

// MuJoCo 2.2 allocates its contact list (nconmax) and constraint rows (njmax) once, and by
// default has room for 100 contacts, which a stack of boxes exceeds (the extra contacts are dropped,
// counted as mujoco.contact_full). Room grows with the virtual geoms: 8 contacts each (a box on a
// box has up to 8) and 4 rows per contact (pyramidal cone, condim 3). Rows are dear in 2.2
// (njmax x njmax and njmax x nv arrays), so njmax stops where those arrays reach 256 MB.
std::string sizeElement(const Scene& scene, bool count_corrections) {
    long geoms = 0, dofs = 0;
    for (const Body& b : scene.bodies) {
        if (b.isStatic()) continue;
        geoms += b.shape.kind == Shape::Kind::Compound ? static_cast<long>(b.shape.parts.size()) : 1;
        dofs += 6;
    }
    const long nconmax = std::max(100L, 8 * geoms);
    long njmax = std::max(500L, 4 * nconmax);
    const auto bytes = [&](long rows) { return 12.0 * rows * rows + 24.0 * rows * dofs; };
    while (njmax > 500 && bytes(njmax) > 256e6) njmax = njmax * 9 / 10;
    njmax = std::max(500L, njmax);
    // Scratch stack [mjtNums]: MuJoCo's own guess overflows for thousands of bodies ("engine error:
    // Stack overflow" at compile time); room for arrays linear in the dofs and rows.
    const long nstack = 1000000 + 2000 * (dofs + njmax);
    // One userdata slot: the passive callback's count of corrected contacts.
    return "  <size" + attr("nconmax", std::to_string(nconmax)) + attr("njmax", std::to_string(njmax)) +
           attr("nstack", std::to_string(nstack)) + (count_corrections ? attr("nuserdata", "1") : "") + "/>\n";
}

// With tracked bodies present, <statistic meaninertia>: the sum of the virtual bodies' diagonal
// joint-space inertia over all dofs. MuJoCo scales its solver's tolerance by 1 / (meaninertia nv);
// its own meaninertia (the mean diagonal of M at qpos0) would include the tracked bodies' huge
// masses and loosen the tolerance a millionfold. This keeps the scale the virtual bodies alone give.
std::string statisticElement(const Scene& scene) {
    double diagonal = 0.0;
    long dofs = 0, tracked = 0;
    for (const Body& b : scene.bodies) {
        if (b.isStatic()) continue;
        dofs += 6;
        if (b.isTracked()) {
            ++tracked;
            continue;
        }
        diagonal += 3.0 * b.mass_properties.mass + principalFrame(b.mass_properties).principal_inertia.sum();
    }
    if (tracked == 0) return "";   // MuJoCo's own statistic
    const double meaninertia = diagonal > 0.0 ? diagonal / static_cast<double>(dofs) : 1.0;
    return "  <statistic" + attr("meaninertia", num(meaninertia)) + "/>\n";
}

// What the passive callback does (passive_callback.h), as <numeric>s; none for MuJoCo's own model.
std::string customElement(const SolverOptions& o) {
    std::string numerics;
    if (o.box_depth_bound) numerics += "    <numeric" + attr("name", kBoxDepthBoundName) + attr("data", "1") + "/>\n";
    if (o.friction_damping > 0.0)
        numerics +=
            "    <numeric" + attr("name", kFrictionDampingName) + attr("data", num(o.friction_damping)) + "/>\n";
    return numerics.empty() ? "" : "  <custom>\n" + numerics + "  </custom>\n";
}

class Writer {
public:
    Writer(const Scene& scene, const ContactMaterials& materials) : scene_(scene), materials_(materials) {}

    std::string write(const SolverOptions& o) {
        for (std::size_t i = 0; i < scene_.bodies.size(); ++i) body(static_cast<int>(i));
        pairs();
        std::ostringstream out;
        out << "<mujoco model=\"vroc\">\n"
            << "  <compiler angle=\"radian\" inertiafromgeom=\"false\"/>\n"
            << "  <option" << attr("timestep", num(o.timestep)) << attr("gravity", vec(scene_.gravity))
            << attr("cone", o.cone) << attr("impratio", num(o.impratio))
            << attr("noslip_iterations", std::to_string(o.noslip_iterations)) << attr("integrator", o.integrator)
            << "/>\n"
            << customElement(o)
            << sizeElement(scene_, o.box_depth_bound)
            << statisticElement(scene_)
            << "  <asset>\n" << assets_.str() << "  </asset>\n"
            << "  <worldbody>\n" << world_.str() << "  </worldbody>\n"
            << "  <contact>\n" << contact_.str() << "  </contact>\n"
            << "</mujoco>\n";
        return out.str();
    }

private:
    void body(int i) {
        const Body& b = scene_.bodies[static_cast<std::size_t>(i)];
        Pose frame;   // MuJoCo body frame -> scene body frame
        if (b.isDynamic()) frame = principalFrame(b.mass_properties).com_in_body;
        const Pose placed = b.pose * frame;
        world_ << "    <body" << attr("name", bodyName(i)) << attr("pos", vec(placed.position))
               << attr("quat", quat(placed.orientation)) << ">\n";
        if (b.isTracked()) {
            const TrackedInertia t = trackedInertia(scene_, b);
            world_ << "      <joint" << attr("name", "j" + std::to_string(i)) << attr("type", "free") << "/>\n"
                   << "      <inertial" << attr("pos", "0 0 0") << attr("mass", num(t.mass))
                   << attr("diaginertia", vec(Vec3::Constant(t.inertia))) << "/>\n";
        } else if (b.isDynamic()) {
            const PrincipalFrame pf = principalFrame(b.mass_properties);
            world_ << "      <joint" << attr("name", "j" + std::to_string(i)) << attr("type", "free") << "/>\n"
                   << "      <inertial" << attr("pos", "0 0 0") << attr("mass", num(b.mass_properties.mass))
                   << attr("diaginertia", vec(pf.principal_inertia)) << "/>\n";
        }
        const PairMaterial own = materials_.ofBody(i);
        const std::vector<Part> parts = partsOf(b.shape);
        for (std::size_t k = 0; k < parts.size(); ++k)
            geom(i, static_cast<int>(k), *parts[k].shape, frame.inverse() * parts[k].pose, own, b.role);
        world_ << "    </body>\n";
    }

    void geom(int i, int k, const Shape& shape, const Pose& pose, const PairMaterial& m, BodyRole role) {
        world_ << "      <geom" << attr("name", geomName(i, k));
        switch (shape.kind) {
            case Shape::Kind::Sphere: world_ << attr("type", "sphere") << attr("size", num(shape.radius)); break;
            case Shape::Kind::Box: world_ << attr("type", "box") << attr("size", vec(shape.half_extents)); break;
            case Shape::Kind::Hull: {
                const std::string mesh = "m" + std::to_string(i) + "_" + std::to_string(k);
                assets_ << "    <mesh" << attr("name", mesh) << " vertex=\"";
                for (std::size_t v = 0; v < shape.hull->vertices.size(); ++v)
                    assets_ << (v ? " " : "") << vec(shape.hull->vertices[v]);
                assets_ << "\"/>\n";
                world_ << attr("type", "mesh") << attr("mesh", mesh);
                break;
            }
            case Shape::Kind::Compound: break;   // flattened by the scene loader; never nested
        }
        world_ << attr("pos", vec(pose.position)) << attr("quat", quat(pose.orientation)) << collisionBits(role)
               << attr("condim", "3")
               << attr("friction", num(m.friction) + " " + kSpinFriction + " " + kRollFriction)
               << contactAttributes(m, scene_.collision_distance) << "/>\n";
        part_counts_.resize(static_cast<std::size_t>(i) + 1, 0);
        part_counts_[static_cast<std::size_t>(i)] = k + 1;
    }

    // Pairs of bodies in different material groups: excluded from MuJoCo's broad phase (which
    // would mix the geoms' values its own way) and listed geom by geom with the combined values.
    void pairs() {
        const int n = static_cast<int>(scene_.bodies.size());
        for (int a = 0; a < n; ++a) {
            for (int b = a + 1; b < n; ++b) {
                // No pair without a virtual body (infinite mass on both sides: no response).
                if (!scene_.bodies[static_cast<std::size_t>(a)].isDynamic() &&
                    !scene_.bodies[static_cast<std::size_t>(b)].isDynamic())
                    continue;
                if (materials_.group(a) == materials_.group(b)) continue;
                contact_ << "    <exclude" << attr("body1", bodyName(a)) << attr("body2", bodyName(b)) << "/>\n";
                const PairMaterial m = materials_.ofPair(a, b);
                const std::string friction = num(m.friction) + " " + num(m.friction) + " " + kSpinFriction + " " +
                                             kRollFriction + " " + kRollFriction;
                for (int ka = 0; ka < part_counts_[static_cast<std::size_t>(a)]; ++ka)
                    for (int kb = 0; kb < part_counts_[static_cast<std::size_t>(b)]; ++kb)
                        contact_ << "    <pair" << attr("geom1", geomName(a, ka)) << attr("geom2", geomName(b, kb))
                                 << attr("condim", "3") << attr("friction", friction)
                                 << contactAttributes(m, scene_.collision_distance) << "/>\n";
            }
        }
    }

    const Scene& scene_;
    const ContactMaterials& materials_;
    std::ostringstream assets_, world_, contact_;
    std::vector<int> part_counts_;
};

}  // namespace

TrackedInertia trackedInertia(const Scene& scene, const Body& body) {
    double heaviest = 0.0;
    for (const Body& b : scene.bodies)
        if (b.isDynamic()) heaviest = std::max(heaviest, b.mass_properties.mass);
    TrackedInertia t;
    t.mass = kTrackedMassRatio * (heaviest > 0.0 ? heaviest : 1.0);
    const double r = std::max(body.shape.boundingRadius(), 1e-3);
    t.inertia = t.mass * r * r;
    return t;
}

std::string bodyName(int body) { return "b" + std::to_string(body); }
std::string geomName(int body, int part) { return "g" + std::to_string(body) + "_" + std::to_string(part); }

std::string writeMjcf(const Scene& scene, const ContactMaterials& materials, const SolverOptions& options) {
    return Writer(scene, materials).write(options);
}

}  // namespace vroc::mujoco
