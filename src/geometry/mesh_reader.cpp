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

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <unordered_map>
#include <vector>

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

/// Corners closer than this fraction of the mesh's bounding-box diagonal are one corner.
constexpr double kWeldTolerance = 1e-8;

/// Joins the corners closer than kWeldTolerance times the mesh's size, as a mesh exported from
/// CAD needs (a cylinder whose seam has sin(2 pi) = -2.4e-16 where its start has 0): cells of
/// that size, each corner joined to the first one within the tolerance in its cell or the 26
/// around it. Triangles that collapse (two corners joined) are left out; corners no triangle
/// uses are dropped.
void weldCorners(TriangleMesh& mesh) {
    if (mesh.vertices.empty()) return;
    Point<3> lo = mesh.vertices[0], hi = lo;
    for (const Point<3>& v : mesh.vertices)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
    double diagonal2 = 0;
    for (int k = 0; k < 3; ++k) diagonal2 += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    const double tol = kWeldTolerance * std::sqrt(diagonal2);
    if (!(tol > 0) || !std::isfinite(tol)) return;
    using Cell = std::array<long long, 3>;
    struct CellHash {
        std::size_t operator()(const Cell& c) const {
            return std::size_t(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
        }
    };
    std::unordered_map<Cell, std::vector<int>, CellHash> cells;
    std::vector<int> joined(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const Point<3>& v = mesh.vertices[i];
        Cell c;
        for (int k = 0; k < 3; ++k) c[k] = (long long)std::floor((v[k] - lo[k]) / tol);
        int found = -1;
        for (int dx = -1; dx <= 1 && found < 0; ++dx)
            for (int dy = -1; dy <= 1 && found < 0; ++dy)
                for (int dz = -1; dz <= 1 && found < 0; ++dz) {
                    const auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
                    if (it == cells.end()) continue;
                    for (int j : it->second) {
                        double d2 = 0;
                        for (int k = 0; k < 3; ++k)
                            d2 += (v[k] - mesh.vertices[j][k]) * (v[k] - mesh.vertices[j][k]);
                        if (d2 <= tol * tol) {
                            found = j;
                            break;
                        }
                    }
                }
        if (found < 0) cells[c].push_back(int(i)), found = int(i);
        joined[i] = found;
    }
    // The triangles on the joined corners, without the collapsed ones; the corners renumbered.
    std::vector<int> number(mesh.vertices.size(), -1);
    TriangleMesh out;
    for (const auto& t : mesh.triangles) {
        const std::array<int, 3> u{joined[t[0]], joined[t[1]], joined[t[2]]};
        if (u[0] == u[1] || u[1] == u[2] || u[0] == u[2]) continue;
        std::array<int, 3> r;
        for (int c = 0; c < 3; ++c) {
            if (number[u[c]] < 0)
                number[u[c]] = int(out.vertices.size()),
                out.vertices.push_back(mesh.vertices[u[c]]);
            r[c] = number[u[c]];
        }
        out.triangles.push_back(r);
    }
    mesh = std::move(out);
}

}  // namespace

TriangleMesh detail::readWithAssimp(const std::string& path) {
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
            for (int c = 0; c < 3; ++c) {
                // assimp can hand over a face naming corners past its vertices (a fuzzed PLY file)
                if (face.mIndices[c] >= part.mNumVertices)
                    throw GeometryError(path + ": not a readable mesh (triangle " +
                                        std::to_string(mesh.triangles.size()) +
                                        " names the vertex " + std::to_string(face.mIndices[c]) +
                                        " of " + std::to_string(part.mNumVertices) +
                                        "): give an STL, OBJ or PLY file of triangles");
                const aiVector3D& p = part.mVertices[face.mIndices[c]];
                if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                    throw GeometryError(
                        path + ": triangle " + std::to_string(mesh.triangles.size()) +
                        " has a corner that is not a finite point (" + std::to_string(p.x) + ", " +
                        std::to_string(p.y) + ", " + std::to_string(p.z) +
                        "): give every vertex as finite numbers");
                t[c] = vertexAt(mesh, index, p);
            }
            mesh.triangles.push_back(t);
        }
    }
    weldCorners(mesh);
    if (mesh.triangles.empty())
        throw GeometryError(path +
                            ": the file holds no triangles: give a surface mesh of triangles");
    return mesh;
}

namespace {

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

// AddressSanitizer and ThreadSanitizer reserve terabytes of address space for their shadow
// memory, which an address-space limit would refuse them. GCC says they are on with
// __SANITIZE_ADDRESS__ / __SANITIZE_THREAD__; clang before 15 only with __has_feature.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define NUMERICS_SANITIZER_SHADOW 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define NUMERICS_SANITIZER_SHADOW 1
#endif
#endif

/// The child: reads the mesh and sends 'M', the counts and the arrays, or 'E' and the message.
[[noreturn]] void childReads(const std::string& path, int fd) {
#ifndef NUMERICS_SANITIZER_SHADOW
    const rlim_t memory = rlim_t(kMeshReaderMemory);
    const rlimit limit{memory, memory};
    ::setrlimit(RLIMIT_AS, &limit);
#endif
    // A CPU-time limit of its own: a child whose parent was killed (no one to end it at the
    // deadline) must not spin on a file forever.
    const rlimit cpu{rlim_t(kMeshReaderSeconds + 1), rlim_t(kMeshReaderSeconds + 2)};
    ::setrlimit(RLIMIT_CPU, &cpu);
    bool ok = false;
    try {
        const TriangleMesh mesh = detail::readWithAssimp(path);
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

/// Reads the child's answer from fd until it closes it or kMeshReaderSeconds pass; true when
/// the time ran out.
bool readAnswer(int fd, std::string& got) {
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::seconds(kMeshReaderSeconds);
    char buffer[65536];
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) return true;
        pollfd p{fd, POLLIN, 0};
        const int ready = ::poll(&p, 1, int(std::min<long long>(left.count(), 1000)));
        if (ready < 0 && errno != EINTR) return false;
        if (ready <= 0) continue;
        const ssize_t r = ::read(fd, buffer, sizeof buffer);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) return false;
        got.append(buffer, std::size_t(r));
    }
}

/// Reaps the child (killed first when late) and refuses the mesh when it was late, died of a
/// signal or said nothing.
void reapChild(pid_t child, bool late, bool saidNothing, const std::string& path) {
    if (late) ::kill(child, SIGKILL);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (late)
        throw GeometryError(path + ": not a readable mesh (the reader took more than " +
                            std::to_string(kMeshReaderSeconds) +
                            " s on it): give an STL, OBJ or PLY file of triangles");
    if (WIFSIGNALED(status) || saidNothing)
        throw GeometryError(
            path + ": not a readable mesh (the reader failed on it" +
            (WIFSIGNALED(status) ? std::string(": ") + ::strsignal(WTERMSIG(status)) : "") +
            (WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL
                 ? ", or it needed more than " + std::to_string(kMeshReaderMemory >> 30) + " GiB"
                 : "") +
            "): give an STL, OBJ or PLY file of triangles");
}

/// The mesh in the child's answer: 'E' and a message, or 'M', the vertex and triangle counts
/// and their bytes.
TriangleMesh decodeAnswer(const std::string& got, const std::string& path) {
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

}  // namespace

TriangleMesh readMesh(const std::string& path) {
    checkMeshFile(path);
    int fds[2];
    if (::pipe(fds) != 0) return detail::readWithAssimp(path);  // no pipe: read here, checked
    const pid_t child = ::fork();
    if (child < 0) {
        ::close(fds[0]), ::close(fds[1]);
        return detail::readWithAssimp(path);
    }
    if (child == 0) {
        ::close(fds[0]);
        childReads(path, fds[1]);
    }
    ::close(fds[1]);
    std::string got;
    const bool late = readAnswer(fds[0], got);
    ::close(fds[0]);
    reapChild(child, late, got.empty(), path);
    return decodeAnswer(got, path);
}

}  // namespace num::geometry
