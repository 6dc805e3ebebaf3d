// The content hash of a file (internal to numerics_app): a checkpoint stores those of the files
// a run reads besides its scene (plugin libraries, meshes), so that a restart notices a changed
// file.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>

#include "app/formatted.hpp"

namespace num::app {

/// FNV-1a (64 bit) of the file's bytes, as 16 hexadecimal digits.
inline std::string fileHash(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::uint64_t h = 1469598103934665603ull;
    char buf[65536];
    while (in.read(buf, sizeof buf) || in.gcount() > 0) {
        for (std::streamsize k = 0; k < in.gcount(); ++k)
            h = (h ^ (unsigned char)buf[k]) * 1099511628211ull;
        if (!in) break;
    }
    return formatted("%016llx", (unsigned long long)h);
}

}  // namespace num::app
