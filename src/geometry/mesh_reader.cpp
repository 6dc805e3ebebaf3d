// Reading triangle meshes with assimp (STL binary and ASCII, OBJ, PLY, and whatever else assimp
// reads), merged into one mesh with the vertices at the same position joined.
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <map>

#include "geometry/triangle_mesh.hpp"

namespace num::geometry {

namespace {

/// Index of the vertex at p, added when new. STL repeats each corner per triangle: joining
/// equal positions makes the triangles share edges.
int vertexAt(TriangleMesh& mesh, std::map<std::array<double, 3>, int>& index, const aiVector3D& p) {
    const std::array<double, 3> key{p.x, p.y, p.z};
    const auto [it, added] = index.try_emplace(key, int(mesh.vertices.size()));
    if (added) mesh.vertices.push_back(Point<3>{{key[0], key[1], key[2]}});
    return it->second;
}

}  // namespace

TriangleMesh readMesh(const std::string& path) {
    Assimp::Importer importer;
    // Node transformations baked into the vertices; polygons split into triangles.
    const aiScene* scene =
        importer.ReadFile(path, aiProcess_Triangulate | aiProcess_PreTransformVertices);
    if (!scene)
        throw GeometryError(path + ": not a readable mesh (" + importer.GetErrorString() +
                            "): give an STL, OBJ or PLY file of triangles");
    TriangleMesh mesh;
    std::map<std::array<double, 3>, int> index;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh& part = *scene->mMeshes[m];
        for (unsigned f = 0; f < part.mNumFaces; ++f) {
            const aiFace& face = part.mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines of the file
            std::array<int, 3> t;
            for (int c = 0; c < 3; ++c)
                t[c] = vertexAt(mesh, index, part.mVertices[face.mIndices[c]]);
            mesh.triangles.push_back(t);
        }
    }
    if (mesh.triangles.empty())
        throw GeometryError(path +
                            ": the file holds no triangles: give a surface mesh of triangles");
    return mesh;
}

}  // namespace num::geometry
