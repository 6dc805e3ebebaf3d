// A mesh file checked before a reader (assimp) trusts it: a regular file (not a FIFO or a device,
// which would block), of at most kMaxMeshFileBytes; a PLY file (any file whose first three
// letters are "ply", in either case, as assimp takes one) walked whole (its first line "ply",
// its end_header within kMaxPlyHeader bytes, element counts within kMaxMeshElements, every
// element of its header there, a face of 3 to kMaxFaceCorners corners naming vertices that
// exist); a binary STL of 84 + 50 n bytes. What assimp can still do wrong runs in a child
// process (readMesh, mesh_reader.cpp), with limits on its memory, time and CPU time.
#pragma once

#include <cstdint>
#include <string>

namespace num::geometry {

inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t(512) << 20;
inline constexpr std::uintmax_t kMaxPlyHeader = 65536;
inline constexpr std::uint64_t kMaxMeshElements = 50'000'000;
inline constexpr int kMaxFaceCorners = 64;
/// The reader's child process: at most this much memory and time.
inline constexpr std::uintmax_t kMeshReaderMemory = std::uintmax_t(8) << 30;
inline constexpr int kMeshReaderSeconds = 60;

/// Throws GeometryError ("<path>: not a readable mesh (why): ...") when the file cannot be
/// given to a reader.
void checkMeshFile(const std::string& path);

}  // namespace num::geometry
