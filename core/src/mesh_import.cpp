// SPDX-License-Identifier: MIT
#include "mesh_import.h"

#include <filesystem>
#include <optional>
#include <system_error>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>

#include "file_bytes.h"
#include "glb_check.h"
#include "ply_check.h"
#include "vroc/core/errors.h"

namespace vroc {

namespace {

// Depth-first walk; each node's meshes are emitted with the node's accumulated transform.
void collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, const Vec3& scale,
             std::vector<MeshPoints>& out) {
    const aiMatrix4x4 transform = parent * node.mTransformation;
    for (unsigned int i = 0; i < node.mNumMeshes; ++i) {
        const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
        MeshPoints part;
        part.name = mesh.mName.C_Str();
        part.vertices.reserve(mesh.mNumVertices);
        for (unsigned int v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D p = transform * mesh.mVertices[v];
            part.vertices.emplace_back(scale.x() * p.x, scale.y() * p.y, scale.z() * p.z);
        }
        out.push_back(std::move(part));
    }
    for (unsigned int c = 0; c < node.mNumChildren; ++c) collect(scene, *node.mChildren[c], transform, scale, out);
}

}  // namespace

std::vector<MeshPoints> importMeshPoints(const std::string& file, const Vec3& scale,
                                         const std::string& context) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        throw InputError(fmt::format("{}: mesh file '{}' not found (paths are relative to the scene file)",
                                     context, file));
    // The file's bytes, read once for the checks of the formats assimp is known to mishandle.
    const std::optional<std::string> bytes = fileBytes(file);
    if (!bytes) throw InputError(fmt::format("{}: cannot read mesh file '{}'", context, file));
    if (isPlyFile(file, *bytes))
        if (const auto problem = plyProblem(*bytes))
            throw InputError(fmt::format("{}: cannot read mesh file '{}' as PLY: {}", context, file, *problem));
    if (isGlbFile(*bytes))
        if (const auto problem = glbProblem(*bytes))
            throw InputError(fmt::format("{}: cannot read mesh file '{}' as binary glTF: {}", context, file, *problem));
    Assimp::Importer importer;
    // Keep each mesh of the file as one part: no post-processing that merges or splits meshes.
    // (OBJ meshes come one per `o`/`g` group; a group with several materials would be split.)
    const aiScene* scene = importer.ReadFile(file, aiProcess_JoinIdenticalVertices);
    if (scene == nullptr || scene->mRootNode == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
        throw InputError(fmt::format("{}: cannot read mesh file '{}' (expected OBJ, STL, PLY or glTF): {}",
                                     context, file, importer.GetErrorString()));
    std::vector<MeshPoints> parts;
    collect(*scene, *scene->mRootNode, aiMatrix4x4(), scale, parts);
    std::erase_if(parts, [](const MeshPoints& p) { return p.vertices.empty(); });
    if (parts.empty())
        throw InputError(fmt::format("{}: mesh file '{}' has no vertices", context, file));
    return parts;
}

}  // namespace vroc
