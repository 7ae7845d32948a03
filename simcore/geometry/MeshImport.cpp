#include "simcore/geometry/MeshImport.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace colonosim::geometry {

ImportedMesh importMesh(const std::filesystem::path& path)
{
    const std::string label = path.filename().string();
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".obj" && extension != ".stl" && extension != ".ply") {
        throw MeshImportError(label + ": unknown extension '" + extension + "' (allowed: .obj, .stl, .ply)");
    }
    std::error_code error;
    const auto size = std::filesystem::file_size(path, error);
    if (error) {
        throw MeshImportError(label + ": cannot read file (" + error.message() + ")");
    }
    if (size == 0) {
        throw MeshImportError(label + ": empty file (0 bytes; allowed: a mesh)");
    }

    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path.string(), aiProcess_Triangulate);
    if (scene == nullptr) {
        throw MeshImportError(label + ": not a readable mesh (" + std::string(importer.GetErrorString()) +
                              ")");
    }
    TriangleMesh mesh;
    int numVertices = 0;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m)
        numVertices += static_cast<int>(scene->mMeshes[m]->mNumVertices);
    mesh.vertices.resize(3, numVertices);
    int base = 0;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* in = scene->mMeshes[m];
        for (unsigned v = 0; v < in->mNumVertices; ++v) {
            mesh.vertices.col(base + static_cast<int>(v)) =
                Eigen::Vector3d(in->mVertices[v].x, in->mVertices[v].y, in->mVertices[v].z);
        }
        for (unsigned f = 0; f < in->mNumFaces; ++f) {
            const aiFace& face = in->mFaces[f];
            if (face.mNumIndices != 3) {
                continue;  // points and lines carry no surface
            }
            mesh.triangles.push_back({base + static_cast<int>(face.mIndices[0]),
                                      base + static_cast<int>(face.mIndices[1]),
                                      base + static_cast<int>(face.mIndices[2])});
        }
        base += static_cast<int>(in->mNumVertices);
    }
    ImportedMesh result;
    result.report = repairTubeMesh(mesh, label);
    result.mesh = std::move(mesh);
    return result;
}

}  // namespace colonosim::geometry
