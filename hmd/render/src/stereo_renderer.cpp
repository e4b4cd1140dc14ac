// SPDX-License-Identifier: MIT
#include "vroc/render/stereo_renderer.h"

#include <GL/osmesa.h>

#include "prewarp_map.h"
#include "shape_mesh.h"
#include "vroc/core/errors.h"

namespace vroc::render {

std::array<float, 3> virtualColor(int virtual_index) {
    static const std::array<float, 3> palette[] = {
        {0.90f, 0.25f, 0.20f}, {0.20f, 0.45f, 0.95f}, {0.95f, 0.80f, 0.15f},
        {0.75f, 0.30f, 0.85f}, {0.95f, 0.55f, 0.15f}, {0.25f, 0.85f, 0.85f}};
    return palette[virtual_index % 6];
}

struct StereoRenderer::Impl {
    OSMesaContext context = nullptr;
    std::vector<std::uint8_t> buffer;            // RGBA, bottom-up (OSMesa's default)
    std::vector<ShapeMesh> meshes;               // per scene body, body frame
    std::vector<bool> is_real;
    std::vector<std::array<float, 3>> colors;    // virtual bodies
    hmd::StereoRig rig;
    PrewarpMap prewarp;

    explicit Impl(const hmd::StereoRig& r) : rig(r) {}
    ~Impl() {   // here, so a constructor that throws half-way still frees the context
        if (context) OSMesaDestroyContext(context);
    }
    void makeCurrent(int width, int height) {
        if (OSMesaGetCurrentContext() == context) return;
        if (!OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, width, height))
            throw RunError("OSMesa: cannot make the context current");
    }
};

namespace {

void loadMatrix(GLenum mode, const Eigen::Matrix4d& m) {
    glMatrixMode(mode);
    glLoadMatrixd(m.data());   // Eigen is column-major, as OpenGL expects
}

Eigen::Matrix4d poseMatrix(const Pose& pose) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = pose.orientation.toRotationMatrix();
    m.topRightCorner<3, 1>() = pose.position;
    return m;
}

void drawTriangles(const ShapeMesh& mesh, bool with_normals) {
    if (mesh.triangle_positions.empty()) return;
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, mesh.triangle_positions.data());
    if (with_normals) {
        glEnableClientState(GL_NORMAL_ARRAY);
        glNormalPointer(GL_FLOAT, 0, mesh.triangle_normals.data());
    }
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(mesh.triangle_positions.size() / 3));
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
}

void drawEdges(const ShapeMesh& mesh) {
    if (mesh.edge_positions.empty()) return;
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, mesh.edge_positions.data());
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(mesh.edge_positions.size() / 3));
    glDisableClientState(GL_VERTEX_ARRAY);
}

}  // namespace

StereoRenderer::StereoRenderer(const Scene& scene, const hmd::StereoRig& rig, const RenderSettings& settings)
    : impl_(std::make_unique<Impl>(rig)), settings_(settings) {
    impl_->context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!impl_->context) throw RunError("OSMesa: cannot create a context");
    impl_->buffer.assign(static_cast<std::size_t>(width()) * height() * 4, 0);
    // Always bind here: a destroyed context's address may be reused by this new one.
    if (!OSMesaMakeCurrent(impl_->context, impl_->buffer.data(), GL_UNSIGNED_BYTE, width(), height()))
        throw RunError("OSMesa: cannot make the context current");
    if (!glGetString(GL_RENDERER))   // libGL linked before OSMesa makes every gl* a no-op
        throw RunError("OSMesa: no GL renderer (is libGL linked into this program?)");
    int virtual_index = 0;
    for (const Body& body : scene.bodies) {
        impl_->meshes.push_back(tessellate(body.shape, settings.sphere_slices, settings.sphere_stacks));
        impl_->is_real.push_back(!body.isDynamic());   // real objects, tracked ones too: depth + wireframe
        impl_->colors.push_back(!body.isDynamic() ? std::array<float, 3>{0, 0, 0} : virtualColor(virtual_index++));
    }
    const hmd::LensDistortion lens(rig.settings().k1, rig.settings().k2);
    if (!lens.isIdentity()) impl_->prewarp = PrewarpMap(lens, settings.eye_width, settings.eye_height);
}

StereoRenderer::~StereoRenderer() = default;

std::string StereoRenderer::glRenderer() const {
    impl_->makeCurrent(width(), height());
    const GLubyte* name = glGetString(GL_RENDERER);
    return name ? reinterpret_cast<const char*>(name) : "";
}

void StereoRenderer::render(const std::array<Pose, 2>& eye_poses, const std::vector<Pose>& body_poses) {
    if (body_poses.size() != impl_->meshes.size()) throw RunError("renderer: one pose per scene body expected");
    impl_->makeCurrent(width(), height());
    glClearColor(0.f, 0.f, 0.f, 1.f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glShadeModel(GL_SMOOTH);
    glLineWidth(settings_.line_width);
    const GLfloat ambient[] = {0.25f, 0.25f, 0.25f, 1.f};
    const GLfloat diffuse[] = {0.85f, 0.85f, 0.85f, 1.f};
    const GLfloat headlight[] = {0.3f, 0.5f, 1.0f, 0.f};   // eye space: from above-right, behind
    for (int e = 0; e < 2; ++e) {
        glViewport(e * settings_.eye_width, 0, settings_.eye_width, settings_.eye_height);
        loadMatrix(GL_PROJECTION, impl_->rig.projectionMatrix());
        loadMatrix(GL_MODELVIEW, Eigen::Matrix4d::Identity());
        glLightfv(GL_LIGHT0, GL_POSITION, headlight);   // fixed to the eye
        glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
        glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
        const Eigen::Matrix4d view = hmd::StereoRig::viewMatrix(eye_poses[e]);
        // 1. Real model into depth only, pushed back a little so its own edges pass later.
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0f, 1.0f);
        for (std::size_t b = 0; b < impl_->meshes.size(); ++b) {
            if (!impl_->is_real[b]) continue;
            loadMatrix(GL_MODELVIEW, view * poseMatrix(body_poses[b]));
            drawTriangles(impl_->meshes[b], false);
        }
        glDisable(GL_POLYGON_OFFSET_FILL);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        // 2. Virtual objects, shaded.
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_COLOR_MATERIAL);
        glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
        for (std::size_t b = 0; b < impl_->meshes.size(); ++b) {
            if (impl_->is_real[b]) continue;
            loadMatrix(GL_MODELVIEW, view * poseMatrix(body_poses[b]));
            glColor3fv(impl_->colors[b].data());
            drawTriangles(impl_->meshes[b], true);
        }
        glDisable(GL_LIGHTING);
        // 3. Real model as wireframe on top (hidden edges stay hidden by the depth of step 1).
        glColor3fv(settings_.wireframe_color.data());
        for (std::size_t b = 0; b < impl_->meshes.size(); ++b) {
            if (!impl_->is_real[b]) continue;
            loadMatrix(GL_MODELVIEW, view * poseMatrix(body_poses[b]));
            drawEdges(impl_->meshes[b]);
        }
    }
    glFinish();
}

Image StereoRenderer::image() const {
    Image out;
    out.width = width();
    out.height = height();
    out.rgb.resize(static_cast<std::size_t>(out.width) * out.height * 3);
    const std::uint8_t* src = impl_->buffer.data();
    for (int y = 0; y < out.height; ++y) {
        const std::uint8_t* row = src + static_cast<std::size_t>(out.height - 1 - y) * out.width * 4;   // bottom-up
        std::uint8_t* dst = out.rgb.data() + static_cast<std::size_t>(y) * out.width * 3;
        for (int x = 0; x < out.width; ++x) {
            dst[3 * x] = row[4 * x];
            dst[3 * x + 1] = row[4 * x + 1];
            dst[3 * x + 2] = row[4 * x + 2];
        }
    }
    if (!impl_->prewarp.empty()) return impl_->prewarp.apply(out, settings_.eye_width);
    return out;
}

}  // namespace vroc::render
