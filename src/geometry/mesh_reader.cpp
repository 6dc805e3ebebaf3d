// Reading triangle meshes with assimp (STL binary and ASCII, OBJ, PLY, and whatever else assimp
// reads), merged into one mesh with the vertices at the same position joined. The file is
// checked first (mesh_file_check.hpp); assimp then reads it in a child process, with a memory
// and a time limit, so that a file it still crashes or hangs on is one line (GeometryError),
// never the end of the program.
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <assimp/Importer.hpp>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <map>

#include "geometry/mesh_file_check.hpp"
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

/// Every triangle of the file, read by assimp in this process.
TriangleMesh readWithAssimp(const std::string& path) {
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

/// Writes all of `n` bytes (the child's side of the pipe).
bool writeAll(int fd, const void* data, std::size_t n) {
    const char* p = static_cast<const char*>(data);
    while (n > 0) {
        const ssize_t w = ::write(fd, p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return false;
        p += w, n -= std::size_t(w);
    }
    return true;
}

/// The child: reads the mesh and sends 'M', the counts and the arrays, or 'E' and the message.
[[noreturn]] void childReads(const std::string& path, int fd) {
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
    const rlim_t memory = rlim_t(kMeshReaderMemory);
    const rlimit limit{memory, memory};
    ::setrlimit(RLIMIT_AS, &limit);
#endif
    bool ok = false;
    try {
        const TriangleMesh mesh = readWithAssimp(path);
        const std::uint64_t counts[2] = {mesh.vertices.size(), mesh.triangles.size()};
        ok =
            writeAll(fd, "M", 1) && writeAll(fd, counts, sizeof counts) &&
            writeAll(fd, mesh.vertices.data(), mesh.vertices.size() * sizeof(Point<3>)) &&
            writeAll(fd, mesh.triangles.data(), mesh.triangles.size() * sizeof(std::array<int, 3>));
    } catch (const std::exception& e) {
        const std::string m = e.what();
        ok = writeAll(fd, "E", 1) && writeAll(fd, m.data(), m.size());
    } catch (...) {
        ok = writeAll(fd, "E", 1);
    }
    ::_exit(ok ? 0 : 3);
}

}  // namespace

TriangleMesh readMesh(const std::string& path) {
    checkMeshFile(path);
    int fds[2];
    if (::pipe(fds) != 0) return readWithAssimp(path);  // no pipe: read here, checked
    const pid_t child = ::fork();
    if (child < 0) {
        ::close(fds[0]), ::close(fds[1]);
        return readWithAssimp(path);
    }
    if (child == 0) {
        ::close(fds[0]);
        childReads(path, fds[1]);
    }
    ::close(fds[1]);
    std::string got;
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::seconds(kMeshReaderSeconds);
    bool late = false;
    char buffer[65536];
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            late = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int ready = ::poll(&p, 1, int(std::min<long long>(left.count(), 1000)));
        if (ready < 0 && errno != EINTR) break;
        if (ready <= 0) continue;
        const ssize_t r = ::read(fds[0], buffer, sizeof buffer);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) break;
        got.append(buffer, std::size_t(r));
    }
    ::close(fds[0]);
    if (late) ::kill(child, SIGKILL);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (late)
        throw GeometryError(path + ": not a readable mesh (the reader took more than " +
                            std::to_string(kMeshReaderSeconds) +
                            " s on it): give an STL, OBJ or PLY file of triangles");
    if (WIFSIGNALED(status) || got.empty())
        throw GeometryError(
            path + ": not a readable mesh (the reader failed on it" +
            (WIFSIGNALED(status) ? std::string(": ") + ::strsignal(WTERMSIG(status)) : "") +
            (WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL
                 ? ", or it needed more than " + std::to_string(kMeshReaderMemory >> 30) + " GiB"
                 : "") +
            "): give an STL, OBJ or PLY file of triangles");
    if (got[0] == 'E') throw GeometryError(got.substr(1));
    std::uint64_t counts[2] = {0, 0};
    if (got.size() >= 1 + sizeof counts) std::memcpy(counts, got.data() + 1, sizeof counts);
    const std::size_t expected =
        1 + sizeof counts + counts[0] * sizeof(Point<3>) + counts[1] * sizeof(std::array<int, 3>);
    if (got[0] != 'M' || got.size() != expected)
        throw GeometryError(path +
                            ": not a readable mesh (the reader failed on it): give an "
                            "STL, OBJ or PLY file of triangles");
    TriangleMesh mesh;
    mesh.vertices.resize(counts[0]);
    mesh.triangles.resize(counts[1]);
    const char* at = got.data() + 1 + sizeof counts;
    std::memcpy(mesh.vertices.data(), at, counts[0] * sizeof(Point<3>));
    std::memcpy(mesh.triangles.data(), at + counts[0] * sizeof(Point<3>),
                counts[1] * sizeof(std::array<int, 3>));
    return mesh;
}

}  // namespace num::geometry
