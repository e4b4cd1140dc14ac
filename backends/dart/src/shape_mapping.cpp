// SPDX-License-Identifier: MIT
#include "shape_mapping.h"

#include <cmath>
#include <dart/dynamics/BoxShape.hpp>
#include <dart/dynamics/MeshShape.hpp>
#include <dart/dynamics/SphereShape.hpp>

#include <assimp/scene.h>

namespace vroc::dart {
namespace {

std::string hullProblem(const ConvexPolyhedron& hull) {
    if (hull.vertices.size() < 4) return "hull with fewer than 4 vertices";
    if (hull.faces.size() < 4) return "hull with fewer than 4 faces";
    for (const Vec3& v : hull.vertices)
        if (!v.allFinite()) return "hull with a non-finite vertex";
    for (std::size_t f = 0; f < hull.faces.size(); ++f) {
        if (hull.faces[f].size() < 3) return "hull face " + std::to_string(f) + " has fewer than 3 vertices";
        for (int i : hull.faces[f])
            if (i < 0 || static_cast<std::size_t>(i) >= hull.vertices.size())
                return "hull face " + std::to_string(f) + " names vertex " + std::to_string(i) + ", which is not there";
    }
    return "";
}

std::string convexProblem(const Shape& shape) {
    switch (shape.kind) {
        case Shape::Kind::Sphere:
            return shape.radius > 0.0 && std::isfinite(shape.radius) ? "" : "sphere radius must be a positive number";
        case Shape::Kind::Box:
            return (shape.half_extents.array() > 0.0).all() && shape.half_extents.allFinite()
                       ? ""
                       : "box half extents must be positive numbers";
        case Shape::Kind::Hull:
            return shape.hull ? hullProblem(*shape.hull) : "hull shape without a polyhedron";
        case Shape::Kind::Compound:
            return "a compound part is itself a compound (compounds are flattened on load)";
    }
    return "unknown shape kind";
}

// An assimp scene holding the hull's faces as triangle fans (faces are convex polygons, wound
// counter-clockwise from outside; a fan from the first vertex keeps that). MeshShape takes it and
// releases it with aiReleaseImport, which deletes a scene no importer made.
const aiScene* hullScene(const ConvexPolyhedron& hull) {
    auto* mesh = new aiMesh();
    mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh->mNumVertices = static_cast<unsigned>(hull.vertices.size());
    mesh->mVertices = new aiVector3D[mesh->mNumVertices];
    for (std::size_t i = 0; i < hull.vertices.size(); ++i) {
        const Vec3& v = hull.vertices[i];
        mesh->mVertices[i] =
            aiVector3D(static_cast<ai_real>(v.x()), static_cast<ai_real>(v.y()), static_cast<ai_real>(v.z()));
    }
    unsigned triangles = 0;
    for (const std::vector<int>& face : hull.faces) triangles += static_cast<unsigned>(face.size() - 2);
    mesh->mNumFaces = triangles;
    mesh->mFaces = new aiFace[triangles];
    unsigned t = 0;
    for (const std::vector<int>& face : hull.faces)
        for (std::size_t k = 1; k + 1 < face.size(); ++k, ++t) {
            mesh->mFaces[t].mNumIndices = 3;
            mesh->mFaces[t].mIndices = new unsigned[3]{static_cast<unsigned>(face[0]), static_cast<unsigned>(face[k]),
                                                       static_cast<unsigned>(face[k + 1])};
        }
    auto* scene = new aiScene();
    scene->mNumMeshes = 1;
    scene->mMeshes = new aiMesh* [1] { mesh };
    scene->mNumMaterials = 1;
    scene->mMaterials = new aiMaterial* [1] { new aiMaterial() };
    scene->mRootNode = new aiNode();
    scene->mRootNode->mNumMeshes = 1;
    scene->mRootNode->mMeshes = new unsigned[1]{0};
    return scene;
}

std::shared_ptr<::dart::dynamics::Shape> convexShape(const Shape& part) {
    switch (part.kind) {
        case Shape::Kind::Sphere:
            return std::make_shared<::dart::dynamics::SphereShape>(part.radius);
        case Shape::Kind::Box:
            return std::make_shared<::dart::dynamics::BoxShape>(2.0 * part.half_extents);
        case Shape::Kind::Hull:
            return std::make_shared<::dart::dynamics::MeshShape>(Eigen::Vector3d::Ones(), hullScene(*part.hull));
        case Shape::Kind::Compound:
            break;  // refused by unsupportedReason()
    }
    return nullptr;
}

}  // namespace

std::string unsupportedReason(const Shape& shape) {
    if (shape.kind != Shape::Kind::Compound) return convexProblem(shape);
    if (shape.parts.empty()) return "compound without parts";
    for (std::size_t i = 0; i < shape.parts.size(); ++i) {
        const std::string why = convexProblem(shape.parts[i].shape);
        if (!why.empty()) return "compound part " + std::to_string(i) + ": " + why;
        const Pose& p = shape.parts[i].pose;
        if (!p.position.allFinite() || !p.orientation.coeffs().allFinite() || !(p.orientation.norm() > 0.0))
            return "compound part " + std::to_string(i) + ": non-finite pose";
    }
    return "";
}

std::vector<PlacedShape> dartShapes(const Shape& shape) {
    std::vector<PlacedShape> out;
    if (shape.kind != Shape::Kind::Compound) {
        out.push_back({convexShape(shape), Pose::identity()});
        return out;
    }
    for (const ShapePart& part : shape.parts)
        out.push_back({convexShape(part.shape), Pose{part.pose.position, part.pose.orientation.normalized()}});
    return out;
}

}  // namespace vroc::dart
